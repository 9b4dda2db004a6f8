#include "bodies/line_measure.hpp"
#include <cmath>

namespace mc {

namespace {
const double kTwoPi = 6.283185307179586476925286766559;
}

double LineMeasure::weight(Point p) const { return axisymmetric ? kTwoPi * p.x : thickness; }

// With s in [0, 1] along the piece and f, g, w linear in s, the integral of f g w ds is
// |ab| / 12 [f0 g0 (3 w0 + w1) + (f0 g1 + f1 g0)(w0 + w1) + f1 g1 (w0 + 3 w1)]
// (the integrals of (1-s)^3, (1-s)^2 s, ... are 1/4, 1/12, 1/12, 1/4); w = 1 gives the
// familiar |ab| / 6 (2 f0 g0 + f0 g1 + f1 g0 + 2 f1 g1).
double LineMeasure::product_integral(Point a, Point b, double f0, double f1, double g0, double g1) const {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const double w0 = weight(a), w1 = weight(b);
  return length / 12 * (f0 * g0 * (3 * w0 + w1) + (f0 * g1 + f1 * g0) * (w0 + w1) + f1 * g1 * (w0 + 3 * w1));
}

// int phi_a w ds = |ab| (2 w_a + w_b) / 6: the product integral with g = 1.
void LineMeasure::hat_integrals(Point a, Point b, double &at_a, double &at_b) const {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const double w0 = weight(a), w1 = weight(b);
  at_a = length * (2 * w0 + w1) / 6;
  at_b = length * (w0 + 2 * w1) / 6;
}

// psi = A phi with A = D M^-1, M_ij = int phi_i phi_j w (the weighted edge mass matrix) and
// D = diag(int phi_j w) = diag(row sums of M): then int psi_i phi_j w = (A M)_ij = D_ij.
void LineMeasure::dual_basis(Point a, Point b, double c[4]) const {
  const double m00 = product_integral(a, b, 1, 0, 1, 0), m01 = product_integral(a, b, 1, 0, 0, 1),
               m11 = product_integral(a, b, 0, 1, 0, 1);
  const double det = m00 * m11 - m01 * m01;
  if (!(det > 1e-14 * (m00 + m11) * (m00 + m11))) {  // no measure: an edge on the axis
    c[0] = 2, c[1] = -1, c[2] = -1, c[3] = 2;
    return;
  }
  const double d0 = m00 + m01, d1 = m01 + m11;
  c[0] = d0 * m11 / det, c[1] = -d0 * m01 / det;
  c[2] = -d1 * m01 / det, c[3] = d1 * m00 / det;
}

}  // namespace mc
