#include "elasticity.hpp"
#include <cmath>
#include <cstring>

namespace mc {

PlaneLaw isotropic_plane_law(double young, double poisson, bool plane_stress) {
  PlaneLaw law{};
  if (plane_stress) {
    double c = young / (1 - poisson * poisson);
    double d[9] = {c, c * poisson, 0, c * poisson, c, 0, 0, 0, c * (1 - poisson) / 2};
    std::memcpy(law.d, d, sizeof d);
    law.zz_factor = 0;
  } else {
    double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
    double mu = young / (2 * (1 + poisson));
    double d[9] = {lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu};
    std::memcpy(law.d, d, sizeof d);
    law.zz_factor = poisson;
  }
  return law;
}

PlaneLaw general_plane_law(const double d[9]) {
  PlaneLaw law{};
  std::memcpy(law.d, d, sizeof law.d);
  law.zz_factor = 0;
  return law;
}

namespace {

// Strain-displacement matrix rows for one point from the shape-function gradients:
// B (3 x 2n, row-major) with eps = B u.
void strain_displacement(int n, const double *dndx, const double *dndy, double *b) {
  for (int a = 0; a < n; ++a) {
    b[0 * 2 * n + 2 * a] = dndx[a], b[0 * 2 * n + 2 * a + 1] = 0;
    b[1 * 2 * n + 2 * a] = 0, b[1 * 2 * n + 2 * a + 1] = dndy[a];
    b[2 * 2 * n + 2 * a] = dndy[a], b[2 * 2 * n + 2 * a + 1] = dndx[a];
  }
}

// ke += weight * B^T D B
void add_btdb(int n, const double *b, const double *d, double weight, double *ke) {
  const int m = 2 * n;
  double db[3 * 8];
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < m; ++j) db[r * m + j] = d[r * 3 + 0] * b[j] + d[r * 3 + 1] * b[m + j] + d[r * 3 + 2] * b[2 * m + j];
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      ke[i * m + j] += weight * (b[i] * db[j] + b[m + i] * db[m + j] + b[2 * m + i] * db[2 * m + j]);
}

// P1 gradients: constant on the triangle; returns the area.
double triangle_gradients(const Point p[3], double dndx[3], double dndy[3]) {
  double area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  for (int a = 0; a < 3; ++a) {
    const Point &q = p[(a + 1) % 3], &r = p[(a + 2) % 3];
    dndx[a] = (q.y - r.y) / area2;
    dndy[a] = (r.x - q.x) / area2;
  }
  return area2 / 2;
}

const double kGauss = 0.57735026918962576451;  // 1/sqrt(3)
const double kRefX[4] = {-1, 1, 1, -1}, kRefY[4] = {-1, -1, 1, 1};

// Q1 shape functions, gradients and Jacobian determinant at reference point (xi, eta).
double quadrilateral_gradients(const Point p[4], double xi, double eta, double shape[4], double dndx[4],
                               double dndy[4]) {
  double dxi[4], deta[4];
  for (int a = 0; a < 4; ++a) {
    shape[a] = 0.25 * (1 + xi * kRefX[a]) * (1 + eta * kRefY[a]);
    dxi[a] = 0.25 * kRefX[a] * (1 + eta * kRefY[a]);
    deta[a] = 0.25 * kRefY[a] * (1 + xi * kRefX[a]);
  }
  double j11 = 0, j12 = 0, j21 = 0, j22 = 0;  // d(x,y)/d(xi,eta)
  for (int a = 0; a < 4; ++a) {
    j11 += dxi[a] * p[a].x, j12 += dxi[a] * p[a].y;
    j21 += deta[a] * p[a].x, j22 += deta[a] * p[a].y;
  }
  double det = j11 * j22 - j12 * j21;
  for (int a = 0; a < 4; ++a) {
    dndx[a] = (j22 * dxi[a] - j12 * deta[a]) / det;
    dndy[a] = (-j21 * dxi[a] + j11 * deta[a]) / det;
  }
  return det;
}

// The four Gauss-point B matrices of a Q1 cell (B-bar if asked) and their weights (det J).
void quadrilateral_b_matrices(const Point p[4], bool bbar, double b[4][24], double weight[4]) {
  double dndx[4][4], dndy[4][4], shape[4];
  double mean_x[4] = {0, 0, 0, 0}, mean_y[4] = {0, 0, 0, 0}, area = 0;
  for (int g = 0; g < 4; ++g) {
    weight[g] = quadrilateral_gradients(p, kGauss * kRefX[g], kGauss * kRefY[g], shape, dndx[g], dndy[g]);
    strain_displacement(4, dndx[g], dndy[g], b[g]);
    area += weight[g];
    for (int a = 0; a < 4; ++a) mean_x[a] += weight[g] * dndx[g][a], mean_y[a] += weight[g] * dndy[g][a];
  }
  if (!bbar) return;
  // eps_bar = eps + 1/2 (mean dilatation - dilatation) on xx and yy.
  for (int g = 0; g < 4; ++g)
    for (int a = 0; a < 4; ++a) {
      double cx = 0.5 * (mean_x[a] / area - dndx[g][a]), cy = 0.5 * (mean_y[a] / area - dndy[g][a]);
      b[g][0 * 8 + 2 * a] += cx, b[g][0 * 8 + 2 * a + 1] += cy;
      b[g][1 * 8 + 2 * a] += cx, b[g][1 * 8 + 2 * a + 1] += cy;
    }
}

void stress_from_strain(const PlaneLaw &law, const double eps[3], double sigma[4]) {
  for (int r = 0; r < 3; ++r) sigma[r] = law.d[r * 3] * eps[0] + law.d[r * 3 + 1] * eps[1] + law.d[r * 3 + 2] * eps[2];
  sigma[3] = law.zz_factor * (sigma[0] + sigma[1]);
}

}  // namespace

void triangle_stiffness(const Point p[3], const PlaneLaw &law, double thickness, double ke[36]) {
  double dndx[3], dndy[3], b[18];
  double area = triangle_gradients(p, dndx, dndy);
  strain_displacement(3, dndx, dndy, b);
  std::memset(ke, 0, 36 * sizeof(double));
  add_btdb(3, b, law.d, thickness * area, ke);
}

void quadrilateral_stiffness(const Point p[4], const PlaneLaw &law, double thickness, bool bbar, double ke[64]) {
  double b[4][24], weight[4];
  quadrilateral_b_matrices(p, bbar, b, weight);
  std::memset(ke, 0, 64 * sizeof(double));
  for (int g = 0; g < 4; ++g) add_btdb(4, b[g], law.d, thickness * weight[g], ke);
}

void triangle_stress(const Point p[3], const PlaneLaw &law, const double ue[6], double sigma[4]) {
  double dndx[3], dndy[3], b[18], eps[3] = {0, 0, 0};
  triangle_gradients(p, dndx, dndy);
  strain_displacement(3, dndx, dndy, b);
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < 6; ++j) eps[r] += b[r * 6 + j] * ue[j];
  stress_from_strain(law, eps, sigma);
}

void quadrilateral_stress(const Point p[4], const PlaneLaw &law, bool bbar, const double ue[8], double sigma[4]) {
  double b[4][24], weight[4], area = 0;
  quadrilateral_b_matrices(p, bbar, b, weight);
  for (int k = 0; k < 4; ++k) sigma[k] = 0;
  for (int g = 0; g < 4; ++g) {
    double eps[3] = {0, 0, 0}, s[4];
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < 8; ++j) eps[r] += b[g][r * 8 + j] * ue[j];
    stress_from_strain(law, eps, s);
    for (int k = 0; k < 4; ++k) sigma[k] += weight[g] * s[k];
    area += weight[g];
  }
  for (int k = 0; k < 4; ++k) sigma[k] /= area;
}

void triangle_body_force(const Point p[3], double bx, double by, double thickness, double fe[6]) {
  double dndx[3], dndy[3];
  double share = thickness * triangle_gradients(p, dndx, dndy) / 3;
  for (int a = 0; a < 3; ++a) fe[2 * a] = share * bx, fe[2 * a + 1] = share * by;
}

void quadrilateral_body_force(const Point p[4], double bx, double by, double thickness, double fe[8]) {
  double shape[4], dndx[4], dndy[4];
  for (int k = 0; k < 8; ++k) fe[k] = 0;
  for (int g = 0; g < 4; ++g) {
    double w = thickness * quadrilateral_gradients(p, kGauss * kRefX[g], kGauss * kRefY[g], shape, dndx, dndy);
    for (int a = 0; a < 4; ++a) fe[2 * a] += w * shape[a] * bx, fe[2 * a + 1] += w * shape[a] * by;
  }
}

void edge_traction_force(Point p, Point q, double tx, double ty, double thickness, double fe[4]) {
  double half = 0.5 * thickness * std::hypot(q.x - p.x, q.y - p.y);
  fe[0] = fe[2] = half * tx;
  fe[1] = fe[3] = half * ty;
}

}  // namespace mc
