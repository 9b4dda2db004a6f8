// adaptive.hpp - the parts of mortarcontact-run's adaptive refinement (docs/scene_format.md,
// "adaptive") that do not solve: the mesh size field made of the error indicators, the files
// that hand it to Gmsh (a list-based post-processing view used as background mesh), running
// Gmsh, and the indicators added to the VTU files as cell data.
#ifndef MC_RUNNER_ADAPTIVE_HPP
#define MC_RUNNER_ADAPTIVE_HPP

#include "body_mesh.hpp"
#include "scene.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace mcrun {

// Gmsh could not be found or run, or it failed on the .geo (exit code 4 of the runner).
struct GmshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The size of a cell as Gmsh's mesh size counts it: the side of the equilateral triangle (or of
// the square) of the cell's area, from its corners (a curved side counts as its chord).
double cell_size(const BodyMesh &mesh, int cell);

// The new mesh size: one value per node of each body, from the cells' error indicators eta
// (relative, their squares summing to the square of the estimate) by equidistribution:
//   a cell of size h and indicator eta, whose error falls like h^(p+1) (energy norm, p the
//   element order, 2D: eta^2 ~ h^2p * area), gets the size r h with
//     r = (aim * target / (sqrt(N) * eta))^(1/(p+1)),
//     N = (sum over cells of (eta / (aim * target))^(2/(p+1)))^((p+1)/p),
//   the number of cells of the mesh that meets aim * target with every cell's error equal (the
//   smallest such mesh); r is kept within [1/max_refinement, max_coarsening]. A node takes the
//   smallest size of its cells; sizes are multiplied by `calibration` (how Gmsh's cells compare
//   with the sizes asked for, measured on the previous step) and kept within
//   [min_size, max_size].
struct SizeField {
  std::vector<double> node_size[2];  // per node of each body
  double optimal_cells = 0;          // N above
  double predicted_cells = 0;        // sum of 1/r^2 after the limits: the cells asked for
  int cells = 0;                     // cells of the current mesh
  int refined = 0, coarsened = 0;    // cells with r < 1, r > 1
  int limited = 0;                   // cells whose r hit max_refinement
};

SizeField make_size_field(const BodyMesh bodies[2], const std::vector<double> eta[2], const Adaptive &adaptive,
                          double calibration);

// The sizes of the mesh itself (each node the smallest size of its cells, nothing refined):
// meshed with them, Gmsh should give a mesh like it back, and the ratio of its cells to these
// measures how Gmsh takes the sizes asked for (about 1.2 for triangles; about 5 for
// quadrilaterals by subdivision, which halves every side): the first calibration.
SizeField current_size_field(const BodyMesh bodies[2]);

// Writes the size field as a list-based Gmsh view (.pos): one ST (triangle) or SQ
// (quadrilateral) element per cell, on its corners, with the corners' sizes, and a skirt of SQ
// elements outside the boundary sides (a curved boundary bulges out of the straight sides, and
// Gmsh gives a point outside every element of the view no size at all).
void write_size_view(const std::string &path, const BodyMesh bodies[2], const SizeField &field);

// Writes the .geo Gmsh meshes for a step after the first: the scene's .geo included, the size
// from points, curvature and boundary switched off, and the view merged and used as background
// mesh (Gmsh's t7 tutorial). Paths are written absolute; `what` goes into the first comment.
void write_step_geo(const std::string &path, const std::string &scene_geo, const std::string &size_view,
                    const std::string &what);

// The Gmsh executable: `requested` if not empty (a path, or a name looked up on PATH), else
// $MORTARCONTACT_GMSH if set, else "gmsh" on PATH. Throws GmshError with what to do.
std::string find_gmsh(const std::string &requested);

// Runs `gmsh -2 -format msh41 [-order 2] ARGUMENTS GEO -o MSH` with stdout and stderr in `log`.
// Throws GmshError (with Gmsh's error lines and the log's path) if it fails or writes nothing.
void run_gmsh(const std::string &gmsh, const std::string &geo, const std::string &msh, int order,
              const std::vector<std::string> &arguments, const std::string &log);

// Adds a Float64 cell-data array to a VTU file written by mc_write_vtu (ASCII), before the end
// of its <CellData>; `values` must have one value per cell of the file. Nothing is done if the
// file already has an array of that name.
void add_vtu_cell_data(const std::string &vtu, const std::string &name, const std::vector<double> &values);

}  // namespace mcrun

#endif
