// Rigid motions of a body left free by its supports. With contact, a body may be held by
// contact alone (the paper's Corollary 4.1): its stiffness K is then singular with kernel R
// (the free rigid modes). The library treats that exactly, as FETI does: a generalized
// inverse K^+ from fixing as many well-chosen unknowns as there are free modes, plus the
// equilibrium condition R^T (f - B^T lambda) = 0 on the contact forces.
#pragma once
#include "bodies/assembly.hpp"
#include "bodies/mesh.hpp"
#include <string>
#include <vector>

namespace mc {

struct RigidModes {
  int count = 0;                   // free rigid modes (0..3)
  std::vector<double> modes;       // 2*n_nodes x count, column-major, orthonormal columns
  std::vector<int> pinned_dofs;    // count unknowns fixed to define K^+
  std::string description;         // e.g. "translation in y", for messages
};

// prescribed[dof] != 0 where mc_fix holds the component.
RigidModes free_rigid_modes(const Mesh &mesh, const std::vector<char> &prescribed);
// The same for a body of revolution (axisymmetric model): its only rigid motion is the
// translation along the axis (y); a radial "translation" or a rotation of the meridian strains
// the hoop fibres, so the stiffness already resists them.
RigidModes free_axial_translation(const Mesh &mesh, const std::vector<char> &prescribed);
// A host body's (mc_set_host_body): unknown i is component[i] (0: x, 1: y) of the motion of
// point[i]; the rigid motions that k does not resist (k R = 0 to round-off) are free.
RigidModes kernel_rigid_modes(const std::vector<Point> &point, const std::vector<int> &component,
                              const SymmetricCsc &k, bool axisymmetric);

}  // namespace mc
