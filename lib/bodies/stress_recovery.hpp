// Superconvergent patch recovery (Zienkiewicz and Zhu, IJNME 33, 1992): a continuous stress
// field sigma* from a solution's cell stresses, the smoother field the error estimate
// (error_estimate.cpp) compares them with. At each corner node a polynomial (linear for P1 and
// Q1, quadratic for T6, Q8, Q9) is fitted by least squares to the stresses at the sampling
// points of the cells around it (their points of highest accuracy: the centroid of a P1
// triangle, the Gauss points of a Q1, the 2x2 Gauss points of a Q8 or Q9, the 3 interior points
// of a T6), and evaluated there; a patch with too few points (at the boundary, where one-sided
// patches are small) takes in the cells of its neighbours too. A mid-edge node gets the mean of
// its two corners' polynomials there, a Q9 centre of its four.
#pragma once
#include "bodies/elasticity.hpp"
#include "bodies/mesh.hpp"
#include <vector>

namespace mc {

// sigma* at every node (4 per node: the components of cell_stress), and the cells' samples it
// was fitted to. For P1 and Q1 the sampling points are the cells' quadrature points, and their
// weights come along (weight non-empty), so that the error estimate integrates with the samples
// instead of evaluating each cell's stresses again.
struct RecoveredStress {
  std::vector<double> nodal;
  std::vector<int> sample_start;  // cell c's samples: [sample_start[c], sample_start[c + 1])
  std::vector<double> sigma;      // 4 per sample
  std::vector<double> weight;     // per sample (P1 and Q1 only)
};

// u: 2 per node.
RecoveredStress patch_recovered_stresses(const Mesh &mesh, const std::vector<PlaneLaw> &laws,
                                         const LineMeasure &measure, bool bbar, const std::vector<double> &u);

}  // namespace mc
