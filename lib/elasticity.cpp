#include "elasticity.hpp"
#include <cmath>
#include <cstring>

namespace mc {

PlaneLaw isotropic_plane_law(double young, double poisson, bool plane_stress) {
  PlaneLaw law{};
  law.n_strain = 3;
  double c11, c12, c33;
  if (plane_stress) {
    double c = young / (1 - poisson * poisson);
    c11 = c, c12 = c * poisson, c33 = c * (1 - poisson) / 2;
    law.zz_factor = 0;
  } else {
    double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
    double mu = young / (2 * (1 + poisson));
    c11 = lambda + 2 * mu, c12 = lambda, c33 = mu;
    law.zz_factor = poisson;
  }
  law.d[0] = c11, law.d[1] = c12;
  law.d[4] = c12, law.d[5] = c11;
  law.d[10] = c33;
  return law;
}

PlaneLaw isotropic_axisymmetric_law(double young, double poisson) {
  PlaneLaw law{};
  law.n_strain = 4;
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  const double mu = young / (2 * (1 + poisson));
  for (int r : {0, 1, 3})
    for (int c : {0, 1, 3}) law.d[4 * r + c] = r == c ? lambda + 2 * mu : lambda;
  law.d[4 * 2 + 2] = mu;
  law.zz_factor = 0;
  return law;
}

PlaneLaw general_plane_law(const double d[9]) {
  PlaneLaw law{};
  law.n_strain = 3;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) law.d[4 * r + c] = d[3 * r + c];
  law.zz_factor = 0;
  return law;
}

namespace {

// One quadrature point of a cell: shape functions, their gradients, where it is and its
// weight (quadrature weight x Jacobian x the measure's t or 2 pi r there).
struct CellPoint {
  double shape[4], dndx[4], dndy[4];
  Point x;
  double weight;
};

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

// Quadrature points of a triangle. Plane: the centroid, exact for the constant B^T D B and
// for the linear N_a of a body force. Axisymmetric: the three interior points at barycentric
// (2/3, 1/6, 1/6) and permutations, exact for N_a r (body forces) and never on the axis,
// where the hoop row N_a / r of B is undefined.
int triangle_points(const Point p[3], const LineMeasure &measure, CellPoint q[3]) {
  double dndx[3], dndy[3];
  const double area = triangle_gradients(p, dndx, dndy);
  const int n = measure.axisymmetric ? 3 : 1;
  for (int g = 0; g < n; ++g) {
    CellPoint &cp = q[g];
    for (int a = 0; a < 3; ++a) {
      cp.shape[a] = n == 1 ? 1.0 / 3 : (a == g ? 2.0 / 3 : 1.0 / 6);
      cp.dndx[a] = dndx[a], cp.dndy[a] = dndy[a];
    }
    cp.x = {0, 0};
    for (int a = 0; a < 3; ++a) cp.x.x += cp.shape[a] * p[a].x, cp.x.y += cp.shape[a] * p[a].y;
    cp.weight = area / n * measure.weight(cp.x);
  }
  return n;
}

const double kGauss = 0.57735026918962576451;  // 1/sqrt(3)
const double kRefX[4] = {-1, 1, 1, -1}, kRefY[4] = {-1, -1, 1, 1};

// The 2x2 Gauss points of a Q1 cell.
int quadrilateral_points(const Point p[4], const LineMeasure &measure, CellPoint q[4]) {
  for (int g = 0; g < 4; ++g) {
    CellPoint &cp = q[g];
    const double xi = kGauss * kRefX[g], eta = kGauss * kRefY[g];
    double dxi[4], deta[4];
    for (int a = 0; a < 4; ++a) {
      cp.shape[a] = 0.25 * (1 + xi * kRefX[a]) * (1 + eta * kRefY[a]);
      dxi[a] = 0.25 * kRefX[a] * (1 + eta * kRefY[a]);
      deta[a] = 0.25 * kRefY[a] * (1 + xi * kRefX[a]);
    }
    double j11 = 0, j12 = 0, j21 = 0, j22 = 0;  // d(x,y)/d(xi,eta)
    cp.x = {0, 0};
    for (int a = 0; a < 4; ++a) {
      j11 += dxi[a] * p[a].x, j12 += dxi[a] * p[a].y;
      j21 += deta[a] * p[a].x, j22 += deta[a] * p[a].y;
      cp.x.x += cp.shape[a] * p[a].x, cp.x.y += cp.shape[a] * p[a].y;
    }
    const double det = j11 * j22 - j12 * j21;
    for (int a = 0; a < 4; ++a) {
      cp.dndx[a] = (j22 * dxi[a] - j12 * deta[a]) / det;
      cp.dndy[a] = (-j21 * dxi[a] + j11 * deta[a]) / det;
    }
    cp.weight = det * measure.weight(cp.x);
  }
  return 4;
}

// Strain-displacement matrix at one point: eps = B u, B row-major n_strain x 2n. The hoop
// row of an axisymmetric model is u_r / r = sum N_a u_r,a / r.
void strain_displacement(int n, int n_strain, const CellPoint &cp, double *b) {
  const int m = 2 * n;
  for (int a = 0; a < n; ++a) {
    b[0 * m + 2 * a] = cp.dndx[a], b[0 * m + 2 * a + 1] = 0;
    b[1 * m + 2 * a] = 0, b[1 * m + 2 * a + 1] = cp.dndy[a];
    b[2 * m + 2 * a] = cp.dndy[a], b[2 * m + 2 * a + 1] = cp.dndx[a];
    if (n_strain == 4) b[3 * m + 2 * a] = cp.shape[a] / cp.x.x, b[3 * m + 2 * a + 1] = 0;
  }
}

// The B matrices of a cell's quadrature points; with bbar, Hughes' B-bar: each point's
// dilatation (eps_xx + eps_yy, plus eps_theta_theta when axisymmetric) is replaced by its
// mean over the cell in the measure, shared equally among the normal strains.
int cell_b_matrices(const Point *p, int npc, const LineMeasure &measure, int n_strain, bool bbar, double b[4][32],
                    double weight[4]) {
  CellPoint q[4];
  const int n = npc == 3 ? triangle_points(p, measure, q) : quadrilateral_points(p, measure, q);
  const int m = 2 * npc;
  for (int g = 0; g < n; ++g) weight[g] = q[g].weight, strain_displacement(npc, n_strain, q[g], b[g]);
  if (!bbar) return n;
  const int normal_rows[3] = {0, 1, 3}, n_normal = n_strain == 4 ? 3 : 2;
  double dilatation[4][8], mean[8] = {0}, volume = 0;
  for (int g = 0; g < n; ++g) {
    volume += weight[g];
    for (int j = 0; j < m; ++j) {
      dilatation[g][j] = 0;
      for (int k = 0; k < n_normal; ++k) dilatation[g][j] += b[g][normal_rows[k] * m + j];
      mean[j] += weight[g] * dilatation[g][j];
    }
  }
  for (int g = 0; g < n; ++g)
    for (int j = 0; j < m; ++j) {
      const double correction = (mean[j] / volume - dilatation[g][j]) / n_normal;
      for (int k = 0; k < n_normal; ++k) b[g][normal_rows[k] * m + j] += correction;
    }
  return n;
}

// The upper triangle of ke += weight * B^T D B (ke is symmetric: cell_stiffness mirrors it).
void add_btdb(int n, int n_strain, const double *b, const double *d, double weight, double *ke) {
  const int m = 2 * n;
  double db[4 * 8];
  for (int r = 0; r < n_strain; ++r)
    for (int j = 0; j < m; ++j) {
      double s = 0;
      for (int k = 0; k < n_strain; ++k) s += d[4 * r + k] * b[k * m + j];
      db[r * m + j] = weight * s;
    }
  for (int i = 0; i < m; ++i)
    for (int j = i; j < m; ++j) {
      double s = 0;
      for (int r = 0; r < n_strain; ++r) s += b[r * m + i] * db[r * m + j];
      ke[i * m + j] += s;
    }
}

void cell_stiffness(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar, double *ke) {
  double b[4][32], weight[4];
  const int n = cell_b_matrices(p, npc, measure, law.n_strain, bbar, b, weight), m = 2 * npc;
  std::memset(ke, 0, size_t(4 * npc * npc) * sizeof(double));
  for (int g = 0; g < n; ++g) add_btdb(npc, law.n_strain, b[g], law.d, weight[g], ke);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j) ke[i * m + j] = ke[j * m + i];
}

void stress_from_strain(const PlaneLaw &law, const double eps[4], double sigma[4]) {
  for (int r = 0; r < law.n_strain; ++r) {
    sigma[r] = 0;
    for (int k = 0; k < law.n_strain; ++k) sigma[r] += law.d[4 * r + k] * eps[k];
  }
  if (law.n_strain == 3) sigma[3] = law.zz_factor * (sigma[0] + sigma[1]);
}

void cell_stress(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                 const double *ue, double sigma[4]) {
  double b[4][32], weight[4], total = 0;
  const int n = cell_b_matrices(p, npc, measure, law.n_strain, bbar, b, weight), m = 2 * npc;
  for (int k = 0; k < 4; ++k) sigma[k] = 0;
  for (int g = 0; g < n; ++g) {
    double eps[4] = {0, 0, 0, 0}, s[4] = {0, 0, 0, 0};
    for (int r = 0; r < law.n_strain; ++r)
      for (int j = 0; j < m; ++j) eps[r] += b[g][r * m + j] * ue[j];
    stress_from_strain(law, eps, s);
    for (int k = 0; k < 4; ++k) sigma[k] += weight[g] * s[k];
    total += weight[g];
  }
  for (int k = 0; k < 4; ++k) sigma[k] /= total;
}

void cell_body_force(const Point *p, int npc, double bx, double by, const LineMeasure &measure, double *fe) {
  CellPoint q[4];
  const int n = npc == 3 ? triangle_points(p, measure, q) : quadrilateral_points(p, measure, q);
  for (int k = 0; k < 2 * npc; ++k) fe[k] = 0;
  for (int g = 0; g < n; ++g)
    for (int a = 0; a < npc; ++a) fe[2 * a] += q[g].weight * q[g].shape[a] * bx, fe[2 * a + 1] += q[g].weight * q[g].shape[a] * by;
}

}  // namespace

void triangle_stiffness(const Point p[3], const PlaneLaw &law, const LineMeasure &measure, double ke[36]) {
  cell_stiffness(p, 3, law, measure, false, ke);
}

void quadrilateral_stiffness(const Point p[4], const PlaneLaw &law, const LineMeasure &measure, bool bbar, double ke[64]) {
  cell_stiffness(p, 4, law, measure, bbar, ke);
}

void triangle_stress(const Point p[3], const PlaneLaw &law, const LineMeasure &measure, const double ue[6], double sigma[4]) {
  cell_stress(p, 3, law, measure, false, ue, sigma);
}

void quadrilateral_stress(const Point p[4], const PlaneLaw &law, const LineMeasure &measure, bool bbar, const double ue[8],
                          double sigma[4]) {
  cell_stress(p, 4, law, measure, bbar, ue, sigma);
}

void triangle_body_force(const Point p[3], double bx, double by, const LineMeasure &measure, double fe[6]) {
  cell_body_force(p, 3, bx, by, measure, fe);
}

void quadrilateral_body_force(const Point p[4], double bx, double by, const LineMeasure &measure, double fe[8]) {
  cell_body_force(p, 4, bx, by, measure, fe);
}

void edge_traction_force(Point p, Point q, double tx, double ty, const LineMeasure &measure, double fe[4]) {
  double at_p, at_q;
  measure.hat_integrals(p, q, at_p, at_q);
  fe[0] = at_p * tx, fe[1] = at_p * ty;
  fe[2] = at_q * tx, fe[3] = at_q * ty;
}

}  // namespace mc
