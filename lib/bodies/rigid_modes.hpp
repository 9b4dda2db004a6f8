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

// A host body's candidate rigid motion (one direction of the candidates' span, the least
// resisted first) and how firmly its stiffness holds it; see kernel_rigid_modes.
struct RigidCandidate {
  enum Kind { free, ambiguous, held };
  Kind kind = held;
  double resistance = 0;  // max over rows i of |(K w)_i| / sum_j |K_ij w_j|
  double norm_ratio = 0;  // |K w| / (max|K_ij| |w|), for the log
  double motion[3] = {0, 0, 0};  // w in the candidates' terms: translation x, y, rotation
  std::string description;       // e.g. "translation in x"
};

struct RigidModes {
  int count = 0;                   // free rigid modes (0..3)
  std::vector<double> modes;       // 2*n_nodes x count, column-major, orthonormal columns
  std::vector<int> pinned_dofs;    // count unknowns fixed to define K^+
  std::string description;         // e.g. "translation in y", for messages
  // Host bodies only (kernel_rigid_modes): every candidate direction, free ones first, and the
  // held ones' fields (unknowns x held_count, orthonormal) for the check after the factorization.
  std::vector<RigidCandidate> candidates;
  std::vector<double> held;
  int held_count = 0;
};

// A free mode's unbalanced share of a row's forces (row_resistance in rigid_modes.cpp) is
// round-off of the precision the matrices were computed in; a held one's is the share of the
// support. Measured: double-precision element matrices at most 2.4e-16 (test_host_body's 249
// candidate directions), single-precision gradients (a legacy program's REAL coordinates) 1.4e-8
// .. 2.5e-8 (test_host_precision, Q4 in a V-groove), where |K w| / (kmax |w|) is 1e-16 and 4e-9
// .. 2e-8; float's worst case is about the ~40 entries of a Q8 row times its 6e-8, 2.4e-6. Held
// directions: 0.037 at least (test_host_body), 0.08 for the groove body clamped at its top. The
// share next to a restrained freedom does not depend on the number of unknowns, whereas |K w| /
// kmax falls as 1/sqrt(unknowns) (1e-3 at 10^6) and cannot be told from round-off by one
// threshold. Free up to 1e-5: 4x above float's worst case, 400x above the measured. Held from
// 1e-3: 37x below the least measured hold; a hold leaving 1/1000 of its rows' forces (a spring
// some thousand times softer than the elements around it) is not what a legacy program means by
// "restrained". Between the two the matrix does not say whether the body is held; the solve is
// refused rather than answered with an arbitrary rigid motion.
constexpr double kFreeResistance = 1e-5;
constexpr double kHeldResistance = 1e-3;

// prescribed[dof] != 0 where mc_fix holds the component.
RigidModes free_rigid_modes(const Mesh &mesh, const std::vector<char> &prescribed);
// The same for a body of revolution (axisymmetric model): its only rigid motion is the
// translation along the axis (y); a radial "translation" or a rotation of the meridian strains
// the hoop fibres, so the stiffness already resists them.
RigidModes free_axial_translation(const Mesh &mesh, const std::vector<char> &prescribed);
// A host body's (mc_set_host_body): unknown i is component[i] (0: x, 1: y) of the motion of
// point[i]; the rigid motions that k does not resist (k R = 0 to round-off, kFreeResistance)
// are free. candidates says how firmly each direction is held; one in the ambiguous band is
// for the caller to refuse (it knows the body's number and log).
// "translation in x", "rotation", ... for motion = (tx, ty, rotation) coefficients.
std::string describe_rigid_motion(const double motion[3]);
RigidModes kernel_rigid_modes(const std::vector<Point> &point, const std::vector<int> &component,
                              const SymmetricCsc &k, bool axisymmetric);

}  // namespace mc
