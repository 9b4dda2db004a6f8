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
#include "elasticity.hpp"
#include "mesh.hpp"
#include <vector>

namespace mc {

// sigma* at every node, 4 per node (the components of cell_stress). u: 2 per node.
std::vector<double> patch_recovered_stresses(const Mesh &mesh, const std::vector<PlaneLaw> &laws,
                                             const LineMeasure &measure, bool bbar, const std::vector<double> &u);

}  // namespace mc
