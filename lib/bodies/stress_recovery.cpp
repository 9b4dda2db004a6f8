#include "bodies/stress_recovery.hpp"
#include "bodies/cell_shapes.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

// The monomials of the patch polynomial at (dx, dy) (coordinates relative to the patch's node,
// divided by its size): 1, x, y (linear), then x^2, x y, y^2 (quadratic).
int monomials(bool quadratic, double dx, double dy, double m[6]) {
  m[0] = 1, m[1] = dx, m[2] = dy;
  if (!quadratic) return 3;
  m[3] = dx * dx, m[4] = dx * dy, m[5] = dy * dy;
  return 6;
}

// A node's patch fit: the polynomial coefficients of each stress component (4 x terms), around
// its node, in coordinates scaled by `size`.
struct PatchFit {
  Point centre{0, 0};
  double size = 1;
  int terms = 0;  // 0: no fit (then `mean` stands for the field near the node)
  double coefficient[4][6] = {};
  double mean[4] = {0, 0, 0, 0};

  void evaluate(Point x, double sigma[4]) const {
    if (terms == 0) {
      for (int k = 0; k < 4; ++k) sigma[k] = mean[k];
      return;
    }
    double m[6];
    monomials(terms == 6, (x.x - centre.x) / size, (x.y - centre.y) / size, m);
    for (int k = 0; k < 4; ++k) {
      sigma[k] = 0;
      for (int t = 0; t < terms; ++t) sigma[k] += coefficient[k][t] * m[t];
    }
  }
};

// Least squares over the sampling points (x, sigma): the normal equations, solved by Cholesky
// in place (3 or 6 unknowns, once per node: no library call). A pivot below 1e-10 of the largest
// diagonal entry means the points do not determine the polynomial (a patch whose points lie on
// a line, a corner with one cell): the node keeps the patch's mean. The number of terms is a
// template argument so that the small loops unroll and the matrices stay in registers (the
// same operations in the same order as with a run-time count: the same numbers; measured: this
// fit was half of the estimate's time on P1 meshes).
template <int terms>
PatchFit fit_patch_terms(Point centre, const std::vector<Point> &x, const std::vector<double> &sigma) {
  constexpr bool quadratic = terms == 6;
  PatchFit fit;
  fit.centre = centre;
  const size_t n = x.size();
  double size = 0;
  for (const Point &p : x) size = std::max(size, std::fabs(p.x - centre.x) + std::fabs(p.y - centre.y));
  fit.size = size > 0 ? size : 1;
  // The patch's mean, what a node without a fit keeps (computed only then: it is 4 n divisions).
  auto without_fit = [&]() {
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) fit.mean[k] += sigma[4 * i + k] / double(n);
    return fit;
  };
  if (n < size_t(terms) + (quadratic ? 3 : 1)) return without_fit();
  double a[terms][terms] = {}, b[4][terms] = {}, m[6];
  const double inverse_size = 1 / fit.size;
  for (size_t i = 0; i < n; ++i) {
    monomials(quadratic, (x[i].x - centre.x) * inverse_size, (x[i].y - centre.y) * inverse_size, m);
    for (int r = 0; r < terms; ++r) {
      for (int c = 0; c <= r; ++c) a[r][c] += m[r] * m[c];
      for (int k = 0; k < 4; ++k) b[k][r] += m[r] * sigma[4 * i + k];
    }
  }
  double largest = 0;
  for (int r = 0; r < terms; ++r) largest = std::max(largest, a[r][r]);
  for (int c = 0; c < terms; ++c) {  // a = L L^T, L in the lower triangle
    double d = a[c][c];
    for (int k = 0; k < c; ++k) d -= a[c][k] * a[c][k];
    if (!(d > 1e-10 * largest)) return without_fit();
    a[c][c] = std::sqrt(d);
    for (int r = c + 1; r < terms; ++r) {
      double v = a[r][c];
      for (int k = 0; k < c; ++k) v -= a[r][k] * a[c][k];
      a[r][c] = v / a[c][c];
    }
  }
  for (int k = 0; k < 4; ++k) {
    double *y = b[k];
    for (int r = 0; r < terms; ++r) {
      for (int c = 0; c < r; ++c) y[r] -= a[r][c] * y[c];
      y[r] /= a[r][r];
    }
    for (int r = terms - 1; r >= 0; --r) {
      for (int c = r + 1; c < terms; ++c) y[r] -= a[c][r] * y[c];
      y[r] /= a[r][r];
    }
    for (int t = 0; t < terms; ++t) fit.coefficient[k][t] = y[t];
  }
  fit.terms = terms;
  return fit;
}

PatchFit fit_patch(Point centre, bool quadratic, const std::vector<Point> &x, const std::vector<double> &sigma) {
  return quadratic ? fit_patch_terms<6>(centre, x, sigma) : fit_patch_terms<3>(centre, x, sigma);
}

}  // namespace

RecoveredStress patch_recovered_stresses(const Mesh &mesh, const std::vector<PlaneLaw> &laws,
                                         const LineMeasure &measure, bool bbar, const std::vector<double> &u) {
  const int n_nodes = mesh.n_nodes(), n_cells = mesh.n_cells(), npc = mesh.nodes_per_cell();
  const int corners = mesh.corners_per_cell();
  const bool quadratic = mesh.quadratic();
  // Each cell's sampled stresses, and the cells around each corner node (CSR).
  RecoveredStress result;
  std::vector<int> &sample_start = result.sample_start;
  sample_start.assign(size_t(n_cells) + 1, 0);
  std::vector<Point> sample_x;
  std::vector<double> &sample_sigma = result.sigma;
  const bool with_weights = !quadratic;
  // (reserved for the most a cell samples: no regrowth of these large arrays)
  const size_t per_cell = npc == 3 ? (measure.axisymmetric ? 3 : 1) : npc == 6 ? 3 : 4;
  sample_x.reserve(size_t(n_cells) * per_cell), sample_sigma.reserve(size_t(n_cells) * per_cell * 4);
  if (with_weights) result.weight.reserve(size_t(n_cells) * per_cell);
  double weight[kMaxCellPoints];
  Point p[kMaxCellNodes], x[kMaxCellPoints];
  double ue[2 * kMaxCellNodes], sigma[4 * kMaxCellPoints];
  for (int c = 0; c < n_cells; ++c) {
    const int *v = mesh.cell(c);
    for (int a = 0; a < npc; ++a) p[a] = mesh.node(v[a]), ue[2 * a] = u[2 * size_t(v[a])], ue[2 * a + 1] = u[2 * size_t(v[a]) + 1];
    const PlaneLaw &law = laws.size() == 1 ? laws[0] : laws[c];
    const int n = cell_sampled_stresses(p, npc, law, measure, bbar, ue, x, sigma, with_weights ? weight : nullptr);
    sample_x.insert(sample_x.end(), x, x + n);
    if (with_weights) result.weight.insert(result.weight.end(), weight, weight + n);
    sample_sigma.insert(sample_sigma.end(), sigma, sigma + 4 * n);
    sample_start[c + 1] = int(sample_x.size());
  }
  std::vector<int> cell_start(size_t(n_nodes) + 1, 0), node_cells;
  for (int c = 0; c < n_cells; ++c)
    for (int a = 0; a < corners; ++a) cell_start[mesh.cell(c)[a] + 1]++;
  for (int i = 0; i < n_nodes; ++i) cell_start[i + 1] += cell_start[i];
  node_cells.resize(size_t(cell_start[n_nodes]));
  {
    std::vector<int> next(cell_start.begin(), cell_start.end() - 1);
    for (int c = 0; c < n_cells; ++c)
      for (int a = 0; a < corners; ++a) node_cells[size_t(next[mesh.cell(c)[a]]++)] = c;
  }
  // The fit of each corner node: its cells' samples; too few (a boundary node with one or two
  // cells), then also the cells around those cells' corners.
  const size_t wanted = quadratic ? 12 : 6;
  // A linear mesh's fits are evaluated at once; a quadratic mesh's are kept for its middles.
  std::vector<PatchFit> fits(quadratic ? size_t(n_nodes) : 0);
  std::vector<double> &out = result.nodal;
  out.assign(4 * size_t(n_nodes), 0.0);
  std::vector<int> patch, mark(n_cells, -1);
  std::vector<Point> px;
  std::vector<double> psigma;
  for (int i = 0; i < n_nodes; ++i) {
    if (cell_start[i] == cell_start[i + 1]) continue;  // not a corner (a middle, a centre)
    patch.clear(), px.clear(), psigma.clear();
    auto take = [&](int c) {
      if (mark[c] == i) return;
      mark[c] = i, patch.push_back(c);
      for (int s = sample_start[c]; s < sample_start[c + 1]; ++s)
        px.push_back(sample_x[s]), psigma.insert(psigma.end(), &sample_sigma[4 * size_t(s)], &sample_sigma[4 * size_t(s)] + 4);
    };
    for (int k = cell_start[i]; k < cell_start[i + 1]; ++k) take(node_cells[k]);
    if (px.size() < wanted) {
      const std::vector<int> first_ring(patch);
      for (int c : first_ring)
        for (int a = 0; a < corners; ++a) {
          const int j = mesh.cell(c)[a];
          for (int k = cell_start[j]; k < cell_start[j + 1]; ++k) take(node_cells[k]);
        }
    }
    const PatchFit fit = fit_patch(mesh.node(i), quadratic, px, psigma);
    fit.evaluate(mesh.node(i), &out[4 * size_t(i)]);
    if (quadratic) fits[i] = fit;
  }
  if (!quadratic) return result;
  // Middles and centres: the mean of their corners' polynomials there.
  std::vector<char> done(n_nodes, 0);
  for (int c = 0; c < n_cells; ++c) {
    const int *v = mesh.cell(c);
    for (int a = corners; a < npc; ++a) {
      const int node = v[a];
      if (done[node]) continue;
      done[node] = 1;
      const int k = a - corners;
      const int ends[4] = {v[k % corners], v[(k + 1) % corners], v[2], v[3]};
      const int count = a == 8 ? 4 : 2;  // a Q9 centre: all four corners
      const int *which = a == 8 ? v : ends;
      double sum[4] = {0, 0, 0, 0}, s[4];
      for (int e = 0; e < count; ++e) {
        fits[which[e]].evaluate(mesh.node(node), s);
        for (int q = 0; q < 4; ++q) sum[q] += s[q] / count;
      }
      for (int q = 0; q < 4; ++q) out[4 * size_t(node) + q] = sum[q];
    }
  }
  return result;
}

}  // namespace mc
