// Global stiffness of one body, assembled straight into compressed sparse columns (upper
// triangle, the form CHOLMOD reads for a symmetric matrix) without a dense intermediate.
#pragma once
#include "bodies/elasticity.hpp"
#include "bodies/mesh.hpp"
#include <vector>

namespace mc {

// Symmetric matrix stored as its upper triangle (diagonal included) in compressed columns,
// rows sorted within each column.
struct SymmetricCsc {
  int n = 0;
  std::vector<int> colptr, rows;
  std::vector<double> values;

  // y = A x (full symmetric product).
  void multiply(const double *x, double *y) const;
  // The principal submatrix on the unknowns with index[i] >= 0; index must be increasing on
  // them (so the upper triangle stays upper) and number them 0..n_kept-1.
  SymmetricCsc principal_submatrix(const std::vector<int> &index, int n_kept) const;
};

// One plane law for all cells (laws.size() == 1) or one per cell. DOF 2*node + component.
SymmetricCsc assemble_stiffness(const Mesh &mesh, const std::vector<PlaneLaw> &laws, const LineMeasure &measure,
                                bool bbar);

}  // namespace mc
