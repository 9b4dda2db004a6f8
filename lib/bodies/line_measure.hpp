// The measure that every integral of the 2D model carries. A plane model (plane strain or plane
// stress) stands for a slab of thickness t: an integral over the mesh or over an edge of it is
// t times the 2D one. An axisymmetric model stands for a body of revolution whose meridian
// half-plane is the mesh (x = r >= 0, y = z on the axis): a point of the meridian sweeps a circle
// of length 2 pi r, so every integral carries the weight 2 pi r (volume dV = 2 pi r dA, surface
// dS = 2 pi r ds). Forces computed with it are totals over the slab or over the full turn.
//
// The mortar integrals (D, M, the lumped weights int phi_j) of the contact interface use the
// same weight; the exact integrals of products of linear functions below are what they need:
// on a straight piece r is linear, so phi phi' r is a cubic and is integrated in closed form.
#pragma once
#include "bodies/mesh.hpp"

namespace mc {

struct LineMeasure {
  bool axisymmetric = false;
  double thickness = 1;  // plane models only; an axisymmetric model ignores it

  // The weight w at a point: t, or 2 pi r.
  double weight(Point p) const;
  // Exact integral over the straight piece a -> b of f g w, for f and g linear on it with end
  // values (f0, g0) at a and (f1, g1) at b.
  double product_integral(Point a, Point b, double f0, double f1, double g0, double g1) const;
  // Exact integrals over the straight edge a -> b of phi_a w and phi_b w (phi_a: the hat that
  // is 1 at a, 0 at b): the edge's shares of its end nodes' tributary measure. Their sum is
  // the weighted length of the edge (t |ab|, or the area 2 pi r_mid |ab| of the cone it sweeps).
  void hat_integrals(Point a, Point b, double &at_a, double &at_b) const;
  // Wohlmuth's biorthogonal (dual) basis on the edge a -> b for this measure:
  // psi_a = c[0] phi_a + c[1] phi_b, psi_b = c[2] phi_a + c[3] phi_b, such that
  // int psi_i phi_j w = delta_ij int phi_j w. With a constant weight c = (2, -1, -1, 2); with
  // 2 pi r it depends on the edge's radii. An edge with no measure (on the axis) keeps (2,-1,-1,2).
  void dual_basis(Point a, Point b, double c[4]) const;
};

}  // namespace mc
