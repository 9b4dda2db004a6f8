#include "bodies/elasticity.hpp"
#include "bodies/cell_shapes.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

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

// One point of a cell: shape functions, their gradients, where it is and its weight
// (quadrature weight x Jacobian x the measure's t or 2 pi r there).
struct CellPoint {
  double shape[kMaxCellNodes], dndx[kMaxCellNodes], dndy[kMaxCellNodes];
  Point x;
  double weight;
  double det;  // Jacobian determinant
};

// The isoparametric map of a cell at a reference point whose shape functions and their reference
// derivatives are given: x = sum N_a x_a, gradients by the inverse Jacobian.
CellPoint cell_point_from(const Point *p, int npc, const double *shape, const double *dxi, const double *deta) {
  CellPoint cp;
  double j11 = 0, j12 = 0, j21 = 0, j22 = 0;  // d(x,y)/d(xi,eta)
  cp.x = {0, 0};
  for (int a = 0; a < npc; ++a) {
    cp.shape[a] = shape[a];
    j11 += dxi[a] * p[a].x, j12 += dxi[a] * p[a].y;
    j21 += deta[a] * p[a].x, j22 += deta[a] * p[a].y;
    cp.x.x += shape[a] * p[a].x, cp.x.y += shape[a] * p[a].y;
  }
  cp.det = j11 * j22 - j12 * j21;
  for (int a = 0; a < npc; ++a) {
    cp.dndx[a] = (j22 * dxi[a] - j12 * deta[a]) / cp.det;
    cp.dndy[a] = (-j21 * dxi[a] + j11 * deta[a]) / cp.det;
  }
  cp.weight = 0;
  return cp;
}

// A quadrature rule with its shape functions and their reference derivatives at each point:
// the same for every cell of a kind, so evaluated once (each cell's points cost the map alone).
struct TabulatedRule {
  int n = 0;
  double weight[kMaxCellPoints];
  double shape[kMaxCellPoints][kMaxCellNodes], dxi[kMaxCellPoints][kMaxCellNodes], deta[kMaxCellPoints][kMaxCellNodes];
};

// The points a cell kind is evaluated at: its quadrature rules (plane or axisymmetric, stiffness
// or error estimate), its nodes, and the sampling points of a quadratic cell's stresses (T6: the
// 3 interior points (2/3, 1/6, 1/6); Q8, Q9: 2x2 Gauss).
enum class CellPoints { rule = 0, nodes = 4, samples = 5 };
constexpr int kPointSets = 6;

// Those points' shapes, tabulated on first use: a constant table, built once however many
// threads ask (a function-local static).
const TabulatedRule &tabulated(int npc, CellPoints set, bool axisymmetric = false, bool for_error = false) {
  static const std::vector<TabulatedRule> table = [] {
    std::vector<TabulatedRule> t(10 * kPointSets);
    for (int kind : {3, 4, 6, 8, 9})
      for (int k = 0; k < kPointSets; ++k) {
        TabulatedRule &r = t[kPointSets * size_t(kind) + k];
        double xi[kMaxCellNodes], eta[kMaxCellNodes];
        if (k < 4) {
          const bool axi = k & 1, error = k & 2;
          r.n = error ? error_quadrature_rule(kind, axi, xi, eta, r.weight) : quadrature_rule(kind, axi, xi, eta, r.weight);
        } else if (k == int(CellPoints::nodes)) {
          r.n = kind;
          for (int a = 0; a < kind; ++a) reference_node(kind, a, xi[a], eta[a]);
        } else if (kind == 6) {
          r.n = 3;
          const double l[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
          for (int g = 0; g < 3; ++g) xi[g] = l[g][0], eta[g] = l[g][1];
        } else if (kind > 6) {
          r.n = 4;
          const double gauss = 0.57735026918962576451, sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
          for (int g = 0; g < 4; ++g) xi[g] = gauss * sx[g], eta[g] = gauss * sy[g];
        }
        for (int g = 0; g < r.n; ++g) reference_shapes(kind, xi[g], eta[g], r.shape[g], r.dxi[g], r.deta[g]);
      }
    return t;
  }();
  const int k = set == CellPoints::rule ? (axisymmetric ? 1 : 0) + (for_error ? 2 : 0) : int(set);
  return table[kPointSets * size_t(npc) + k];
}

// The quadrature points of a cell (cell_shapes.hpp: the rule of each kind; for_error: the error
// estimate's rule).
int cell_points(const Point *p, int npc, const LineMeasure &measure, CellPoint q[kMaxCellPoints],
                bool for_error = false) {
  const TabulatedRule &rule = tabulated(npc, CellPoints::rule, measure.axisymmetric, for_error);
  for (int g = 0; g < rule.n; ++g) {
    q[g] = cell_point_from(p, npc, rule.shape[g], rule.dxi[g], rule.deta[g]);
    q[g].weight = rule.weight[g] * q[g].det * measure.weight(q[g].x);
  }
  return rule.n;
}

constexpr int kMaxCellDofs = 2 * kMaxCellNodes;
using BMatrix = double[4 * kMaxCellDofs];  // n_strain x 2n, row-major with row stride 2n

// Strain-displacement matrix at one point: eps = B u, B row-major n_strain x 2n. The hoop
// row of an axisymmetric model is u_r / r = sum N_a u_r,a / r; at a point on the axis (a node
// of the cell, for nodal stresses) its limit du_r / dr.
void strain_displacement(int n, int n_strain, const CellPoint &cp, double axis, double *b) {
  const int m = 2 * n;
  for (int a = 0; a < n; ++a) {
    b[0 * m + 2 * a] = cp.dndx[a], b[0 * m + 2 * a + 1] = 0;
    b[1 * m + 2 * a] = 0, b[1 * m + 2 * a + 1] = cp.dndy[a];
    b[2 * m + 2 * a] = cp.dndy[a], b[2 * m + 2 * a + 1] = cp.dndx[a];
    if (n_strain == 4) b[3 * m + 2 * a] = std::fabs(cp.x.x) <= axis ? cp.dndx[a] : cp.shape[a] / cp.x.x, b[3 * m + 2 * a + 1] = 0;
  }
}

// The dilatation row (eps_xx + eps_yy, plus eps_theta_theta when axisymmetric) of B.
void dilatation_row(const double *b, int m, int n_strain, double *row) {
  const int normal_rows[3] = {0, 1, 3}, n_normal = n_strain == 4 ? 3 : 2;
  for (int j = 0; j < m; ++j) {
    row[j] = 0;
    for (int k = 0; k < n_normal; ++k) row[j] += b[normal_rows[k] * m + j];
  }
}

// Hughes' B-bar at one point: its dilatation replaced by `mean` (the cell's), shared equally
// among the normal strains.
void replace_dilatation(double *b, int m, int n_strain, const double *mean) {
  const int normal_rows[3] = {0, 1, 3}, n_normal = n_strain == 4 ? 3 : 2;
  double own[kMaxCellDofs];
  dilatation_row(b, m, n_strain, own);
  for (int j = 0; j < m; ++j) {
    const double correction = (mean[j] - own[j]) / n_normal;
    for (int k = 0; k < n_normal; ++k) b[normal_rows[k] * m + j] += correction;
  }
}

// The B matrices of a cell's quadrature points; with bbar, Hughes' B-bar, and `mean` (if not
// null) receives the cell's mean dilatation row.
int cell_b_matrices(const Point *p, int npc, const LineMeasure &measure, int n_strain, bool bbar, BMatrix *b,
                    double *weight, double *mean_out = nullptr, CellPoint *points_out = nullptr) {
  CellPoint own[kMaxCellPoints];
  CellPoint *q = points_out ? points_out : own;
  const int n = cell_points(p, npc, measure, q);
  const int m = 2 * npc;
  for (int g = 0; g < n; ++g) weight[g] = q[g].weight, strain_displacement(npc, n_strain, q[g], 0.0, b[g]);
  if (!bbar) return n;
  double mean[kMaxCellDofs] = {0}, volume = 0, row[kMaxCellDofs];
  for (int g = 0; g < n; ++g) {
    volume += weight[g];
    dilatation_row(b[g], m, n_strain, row);
    for (int j = 0; j < m; ++j) mean[j] += weight[g] * row[j];
  }
  for (int j = 0; j < m; ++j) mean[j] /= volume;
  for (int g = 0; g < n; ++g) replace_dilatation(b[g], m, n_strain, mean);
  if (mean_out)
    for (int j = 0; j < m; ++j) mean_out[j] = mean[j];
  return n;
}

// The upper triangle of ke += weight * B^T D B (ke is symmetric: cell_stiffness mirrors it).
void add_btdb(int n, int n_strain, const double *b, const double *d, double weight, double *ke) {
  const int m = 2 * n;
  double db[4 * kMaxCellDofs];
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

// add_btdb for a plane law without B-bar, node pair by node pair: B_a = [dN_a/dx 0; 0 dN_a/dy;
// dN_a/dy dN_a/dx], so the 2x2 block of nodes a, b is B_a^T (D B_b), without B's zeros (the
// stiffness's inner loop: a third of the multiplications of the general product). Its sums are
// add_btdb's without the zero terms, so the two give the same bits.
void add_plane_btdb(int n, const double *dndx, const double *dndy, const double *d, double weight, double *ke) {
  const int m = 2 * n;
  for (int b = 0; b < n; ++b) {
    const double bx = dndx[b], by = dndy[b];
    double dbx[3], dby[3];  // weight D B_b's two columns (rounded as add_btdb rounds them)
    for (int r = 0; r < 3; ++r)
      dbx[r] = weight * (d[4 * r] * bx + d[4 * r + 2] * by), dby[r] = weight * (d[4 * r + 1] * by + d[4 * r + 2] * bx);
    for (int a = 0; a <= b; ++a) {
      const double ax = dndx[a], ay = dndy[a];
      double *row_x = ke + (2 * a) * m + 2 * b, *row_y = row_x + m;
      row_x[0] += ax * dbx[0] + ay * dbx[2];
      row_x[1] += ax * dby[0] + ay * dby[2];
      if (a < b) row_y[0] += ay * dbx[1] + ax * dbx[2];
      row_y[1] += ay * dby[1] + ax * dby[2];
    }
  }
}

void stress_from_strain(const PlaneLaw &law, const double eps[4], double sigma[4]) {
  for (int r = 0; r < law.n_strain; ++r) {
    sigma[r] = 0;
    for (int k = 0; k < law.n_strain; ++k) sigma[r] += law.d[4 * r + k] * eps[k];
  }
  if (law.n_strain == 3) sigma[3] = law.zz_factor * (sigma[0] + sigma[1]);
}

void stress_at(const double *b, int m, const PlaneLaw &law, const double *ue, double s[4]) {
  double eps[4] = {0, 0, 0, 0};
  s[0] = s[1] = s[2] = s[3] = 0;
  for (int r = 0; r < law.n_strain; ++r)
    for (int j = 0; j < m; ++j) eps[r] += b[r * m + j] * ue[j];
  stress_from_strain(law, eps, s);
}

// The strain at a point straight from the shape gradients: B u (strain_displacement's rows,
// without building B) when there is no B-bar.
void strain_at(const CellPoint &cp, int n, int n_strain, double axis, const double *ue, double eps[4]) {
  eps[0] = eps[1] = eps[2] = eps[3] = 0;
  for (int a = 0; a < n; ++a) {
    const double ux = ue[2 * a], uy = ue[2 * a + 1];
    eps[0] += cp.dndx[a] * ux;
    eps[1] += cp.dndy[a] * uy;
    eps[2] += cp.dndy[a] * ux;
    eps[2] += cp.dndx[a] * uy;
    if (n_strain == 4) eps[3] += (std::fabs(cp.x.x) <= axis ? cp.dndx[a] : cp.shape[a] / cp.x.x) * ux;
  }
}

void point_stress(const CellPoint &cp, int n, const PlaneLaw &law, double axis, const double *ue, double s[4]) {
  double eps[4];
  strain_at(cp, n, law.n_strain, axis, ue, eps);
  stress_from_strain(law, eps, s);
}

// The stress at each quadrature point of a cell (for_error: the error estimate's rule; with
// B-bar, a Q1's, whose two rules are one): through the B matrices with B-bar, else straight from
// the shape gradients. Fills q (the points, their weights included) and s; returns the count.
int cell_point_stresses(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                        const double *ue, bool for_error, CellPoint q[kMaxCellPoints], double s[kMaxCellPoints][4]) {
  if (!bbar) {
    const int n = cell_points(p, npc, measure, q, for_error);
    for (int g = 0; g < n; ++g) point_stress(q[g], npc, law, 0.0, ue, s[g]);
    return n;
  }
  BMatrix b[kMaxCellPoints];
  double weight[kMaxCellPoints];
  const int n = cell_b_matrices(p, npc, measure, law.n_strain, true, b, weight, nullptr, q);
  for (int g = 0; g < n; ++g) stress_at(b[g], 2 * npc, law, ue, s[g]);
  return n;
}

}  // namespace

void cell_stiffness(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar, double *ke) {
  const int m = 2 * npc;
  std::memset(ke, 0, size_t(m * m) * sizeof(double));
  if (law.n_strain == 3 && !bbar) {
    CellPoint q[kMaxCellPoints];
    const int n = cell_points(p, npc, measure, q);
    for (int g = 0; g < n; ++g) add_plane_btdb(npc, q[g].dndx, q[g].dndy, law.d, q[g].weight, ke);
  } else {
    BMatrix b[kMaxCellPoints];
    double weight[kMaxCellPoints];
    const int n = cell_b_matrices(p, npc, measure, law.n_strain, bbar, b, weight);
    for (int g = 0; g < n; ++g) add_btdb(npc, law.n_strain, b[g], law.d, weight[g], ke);
  }
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j) ke[i * m + j] = ke[j * m + i];
}

void cell_stress(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar, const double *ue,
                 double sigma[4]) {
  CellPoint q[kMaxCellPoints];
  double s[kMaxCellPoints][4], total = 0;
  const int n = cell_point_stresses(p, npc, law, measure, bbar, ue, false, q, s);
  for (int k = 0; k < 4; ++k) sigma[k] = 0;
  for (int g = 0; g < n; ++g) {
    for (int k = 0; k < 4; ++k) sigma[k] += q[g].weight * s[g][k];
    total += q[g].weight;
  }
  for (int k = 0; k < 4; ++k) sigma[k] /= total;
}

void cell_nodal_stresses(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                         const double *ue, double *sigma) {
  const int m = 2 * npc;
  if (npc == 3) {  // constant strain (plane); the axisymmetric hoop strain varies, evaluated below
    if (!measure.axisymmetric) {
      double s[4];
      cell_stress(p, npc, law, measure, false, ue, s);
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k) sigma[4 * a + k] = s[k];
      return;
    }
  }
  double mean[kMaxCellDofs] = {0};
  if (bbar) {
    BMatrix b[kMaxCellPoints];
    double weight[kMaxCellPoints];
    cell_b_matrices(p, npc, measure, law.n_strain, true, b, weight, mean);
  }
  // A node within round-off of the axis (model.hpp's axis tolerance: 1e-12 of the extent).
  double extent = 0;
  for (int a = 0; a < npc; ++a) extent = std::max({extent, std::fabs(p[a].x - p[0].x), std::fabs(p[a].y - p[0].y)});
  const TabulatedRule &nodes = tabulated(npc, CellPoints::nodes);
  for (int a = 0; a < npc; ++a) {
    const CellPoint cp = cell_point_from(p, npc, nodes.shape[a], nodes.dxi[a], nodes.deta[a]);
    if (!bbar) {
      point_stress(cp, npc, law, 1e-9 * extent, ue, &sigma[4 * a]);
      continue;
    }
    BMatrix b;
    strain_displacement(npc, law.n_strain, cp, 1e-9 * extent, b);
    replace_dilatation(b, m, law.n_strain, mean);
    stress_at(b, m, law, ue, &sigma[4 * a]);
  }
}

// D^-1 by Gauss-Jordan with partial pivoting; D is symmetric positive definite.
void law_compliance(const PlaneLaw &law, double c[16]) {
  const int n = law.n_strain;
  double a[4][8];
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < 2 * n; ++k) a[r][k] = k < n ? law.d[4 * r + k] : (k - n == r ? 1 : 0);
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    for (int k = 0; k < 2 * n; ++k) std::swap(a[col][k], a[pivot][k]);
    const double diagonal = a[col][col];
    for (int k = 0; k < 2 * n; ++k) a[col][k] /= diagonal;
    for (int r = 0; r < n; ++r) {
      if (r == col) continue;
      const double factor = a[r][col];
      for (int k = 0; k < 2 * n; ++k) a[r][k] -= factor * a[col][k];
    }
  }
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < n; ++k) c[4 * r + k] = a[r][n + k];
}


int cell_sampled_stresses(const Point *p, int npc, const PlaneLaw &law, const LineMeasure &measure, bool bbar,
                          const double *ue, Point *x, double *sigma, double *weight_out) {
  if (npc == 3 || npc == 4) {
    CellPoint q[kMaxCellPoints];
    double s[kMaxCellPoints][4];
    const int n = cell_point_stresses(p, npc, law, measure, bbar, ue, false, q, s);
    for (int g = 0; g < n; ++g) {
      x[g] = q[g].x;
      for (int k = 0; k < 4; ++k) sigma[4 * g + k] = s[g][k];
      if (weight_out) weight_out[g] = q[g].weight;
    }
    return n;
  }
  const TabulatedRule &samples = tabulated(npc, CellPoints::samples);
  const int n = samples.n;
  for (int g = 0; g < n; ++g) {
    const CellPoint cp = cell_point_from(p, npc, samples.shape[g], samples.dxi[g], samples.deta[g]);
    x[g] = cp.x;
    point_stress(cp, npc, law, 0.0, ue, &sigma[4 * g]);
  }
  return n;
}

double cell_recovery_error(const Point *p, int npc, const PlaneLaw &law, const double c[16], const LineMeasure &measure,
                           bool bbar, const double *ue, const double *nodal_sigma) {
  CellPoint q[kMaxCellPoints];
  double own[kMaxCellPoints][4];
  const int n = cell_point_stresses(p, npc, law, measure, bbar, ue, true, q, own);
  // The components the energy sees: plane (xx, yy, xy), axisymmetric (rr, zz, rz, theta theta),
  // in nodal_sigma's slots 0..3 as in the law's strain order.
  const int k = law.n_strain;
  double error = 0;
  for (int g = 0; g < n; ++g) {
    double recovered[4] = {0, 0, 0, 0}, d[4];
    for (int a = 0; a < npc; ++a)
      for (int r = 0; r < k; ++r) recovered[r] += q[g].shape[a] * nodal_sigma[4 * a + r];
    for (int r = 0; r < k; ++r) d[r] = recovered[r] - own[g][r];
    double energy = 0;
    for (int r = 0; r < k; ++r)
      for (int s2 = 0; s2 < k; ++s2) energy += d[r] * c[4 * r + s2] * d[s2];
    error += q[g].weight * energy;
  }
  return error;
}

void cell_body_force(const Point *p, int npc, double bx, double by, const LineMeasure &measure, double *fe) {
  CellPoint q[kMaxCellPoints];
  const int n = cell_points(p, npc, measure, q);
  for (int k = 0; k < 2 * npc; ++k) fe[k] = 0;
  for (int g = 0; g < n; ++g)
    for (int a = 0; a < npc; ++a) fe[2 * a] += q[g].weight * q[g].shape[a] * bx, fe[2 * a + 1] += q[g].weight * q[g].shape[a] * by;
}

void edge_traction_force(Point p, Point q, double tx, double ty, const LineMeasure &measure, double fe[4]) {
  double at_p, at_q;
  measure.hat_integrals(p, q, at_p, at_q);
  fe[0] = at_p * tx, fe[1] = at_p * ty;
  fe[2] = at_q * tx, fe[3] = at_q * ty;
}

// f_a = integral over s in [0,1] of N_a t w |x'(s)| ds, with t = -p n(s) and n(s) |x'(s)| =
// (y', -x') for a pressure. Five Gauss points: exact (degree 9) for a straight edge in every
// model, and for a curved one up to the non-polynomial |x'| of a traction.
void quadratic_edge_force(Point p, Point q, Point m, double tx, double ty, bool is_pressure, const LineMeasure &measure,
                          double fe[6]) {
  double s[5], w[5];
  gauss_on_unit_interval(5, s, w);
  const Point node[3] = {p, q, m};
  for (int k = 0; k < 6; ++k) fe[k] = 0;
  for (int g = 0; g < 5; ++g) {
    double n[3], dn[3];
    line_shapes(3, s[g], n, dn);
    Point x{0, 0}, d{0, 0};
    for (int a = 0; a < 3; ++a) x.x += n[a] * node[a].x, x.y += n[a] * node[a].y, d.x += dn[a] * node[a].x, d.y += dn[a] * node[a].y;
    const double weight = w[g] * measure.weight(x);
    double fx, fy;  // traction times |x'|
    if (is_pressure) fx = -tx * d.y, fy = tx * d.x;
    else {
      const double speed = std::hypot(d.x, d.y);
      fx = tx * speed, fy = ty * speed;
    }
    for (int a = 0; a < 3; ++a) fe[2 * a] += weight * n[a] * fx, fe[2 * a + 1] += weight * n[a] * fy;
  }
}

}  // namespace mc
