// A host body (mc_set_host_body): a body with no cells, whose stiffness and load a legacy
// program hands over in its own equation numbering (coordinate entries or element matrices,
// MUMPS's and Smith and Griffiths' conventions: ../shared/design/host-bodies.md). Its unknowns
// are the host's equations; a node's freedom without an equation is restrained.
#pragma once
#include "bodies/assembly.hpp"
#include <vector>

namespace mc {

struct HostBody {
  int n_equations = 0;
  std::vector<int> equations;         // 2 per node (x, y): 0-based equation, -1 for none
  std::vector<int> node_of_equation;  // per equation: the node whose freedom it is, -1 if none
  std::vector<int> component_of_equation;
  // The stiffness as summed-later entries of its upper triangle (row <= col), 0-based. half:
  // 0 for a whole value (a triangle's entry, an element's, a diagonal), 1 or 2 for an
  // off-diagonal MC_MATRIX_FULL entry given in the upper or the lower triangle: the two halves
  // are summed apart and checked equal when the matrix is assembled (a check that per call would
  // cost a sort of the entries, several times the factorization's time: docs/notes).
  std::vector<int> entry_row, entry_col;
  std::vector<double> entry_value;
  std::vector<unsigned char> entry_half;
  double full_largest = 0;  // the largest |value| given with MC_MATRIX_FULL
  std::vector<double> load;  // n_equations

  // The unknown of node's component, or -1.
  int equation(int node, int component) const { return equations[2 * size_t(node) + component]; }
};

// Checks and takes the host's numbering (ids with the index base; below it: none). Throws
// mc::Error naming the argument and index.
HostBody make_host_body(int n_nodes, const int *equations, int n_equations, int base);
// Coordinate entries (rows, cols, values) in host numbers; storage MC_MATRIX_FULL or
// MC_MATRIX_TRIANGLE. One pass, no sort: a call's cost is a copy of its arrays. Adds nothing if
// it throws.
void add_coordinate_entries(HostBody &host, int n, const int *rows, const int *cols, const double *values, int storage,
                            int base);
// MUMPS's elemental input: element e's equations eltvar[eltptr[e] - base .. eltptr[e+1] - base),
// its full matrix column by column in a_elt. Adds nothing if it throws.
void add_element_matrices(HostBody &host, int n_elements, const int *eltptr, const int *eltvar, const double *a_elt,
                          int base);
// The summed stiffness, upper triangle in compressed columns. Throws MC_ERROR_ARGUMENT naming
// the equations of an MC_MATRIX_FULL pair whose two triangles differ, MC_ERROR_SINGULAR naming
// the first equation whose diagonal is not positive (base added for the messages).
SymmetricCsc assemble_host_stiffness(const HostBody &host, int body, int base);

}  // namespace mc
