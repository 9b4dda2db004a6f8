#include "mortar_operators.hpp"
#include "error.hpp"
#include <cmath>
#include <map>

namespace mc {

namespace {

Point lerp(Point u, Point v, double s) { return {u.x + s * (v.x - u.x), u.y + s * (v.y - u.y)}; }

// The body-1 test functions of the node pair (k, k+1) on a piece, at its ends: standard hats
// for the paper's mortar, biorthogonal ones for the dual method (2 phi_k - phi_k+1, ... with a
// constant weight; with 2 pi r, the basis biorthogonal in that measure on the segment xk-xk1).
void test_functions(int method, const MortarPiece &p, Point xk, Point xk1, const LineMeasure &measure, double psi_k[2],
                    double psi_k1[2]) {
  double phi_k[2] = {1 - p.xi0, 1 - p.xi1}, phi_k1[2] = {p.xi0, p.xi1};
  double c[4];
  if (method == MC_METHOD_DUAL_MORTAR) measure.dual_basis(xk, xk1, c);
  for (int e = 0; e < 2; ++e) {
    if (method == MC_METHOD_DUAL_MORTAR) {
      psi_k[e] = c[0] * phi_k[e] + c[1] * phi_k1[e];
      psi_k1[e] = c[2] * phi_k[e] + c[3] * phi_k1[e];
    } else {
      psi_k[e] = phi_k[e];
      psi_k1[e] = phi_k1[e];
    }
  }
}

// Interpolation weights of u2 at a surface point.
void add_interpolation(const ContactGeometry &g, SurfacePoint at, std::map<int, double> &row) {
  const SurfaceSegment &s = g.mortar_segments[at.segment];
  row[s.a] += 1 - at.eta;
  row[s.b] += at.eta;
}

void append_row(ConstraintRows &rows, int position, const std::map<int, double> &entries) {
  rows.position.push_back(position);
  for (auto &[node, w] : entries)
    if (w != 0) rows.body2_node.push_back(node), rows.weight.push_back(w);
  rows.start.push_back(int(rows.body2_node.size()));
}

// Rows of one run for the mortar methods: the paper's pi_h^1 (3.2).
void mortar_rows(const ContactGeometry &g, const ContactRun &run, const Mesh &body1, int method,
                 const LineMeasure &measure, ConstraintRows &rows) {
  const int m = int(run.positions.size()) - 1;  // nodes x_0..x_m
  // Columns: the body-2 nodes this run touches.
  std::map<int, int> column;
  for (const MortarPiece &p : run.pieces) {
    column.emplace(g.mortar_segments[p.segment].a, 0);
    column.emplace(g.mortar_segments[p.segment].b, 0);
  }
  for (int end : {0, m}) {
    const SurfaceSegment &s = g.mortar_segments[g.projection[run.positions[end]].segment];
    column.emplace(s.a, 0), column.emplace(s.b, 0);
  }
  std::vector<int> column_node;
  for (auto &[node, index] : column) index = int(column_node.size()), column_node.push_back(node);
  const int nc = int(column_node.size());

  // End rows: (pi phi)(c_i) = phi(c_i), i.e. interpolation at the projection of c_1, c_2.
  std::vector<double> end_row[2];
  for (int e = 0; e < 2; ++e) {
    end_row[e].assign(nc, 0.0);
    std::map<int, double> w;
    add_interpolation(g, g.projection[run.positions[e == 0 ? 0 : m]], w);
    for (auto &[node, value] : w) end_row[e][column[node]] += value;
  }
  // Multiplier index of node k's test function: the end modification merges psi_0 into psi_1
  // and psi_m into psi_{m-1} (M_h^1 is constant on the two end segments).
  auto multiplier = [m](int k) { return k == 0 ? 1 : k == m ? m - 1 : k; };
  // D (band: columns i-1, i, i+1 of row i) and M (dense over the run's columns), rows 1..m-1.
  std::vector<double> lower(m + 1, 0.0), diag(m + 1, 0.0), upper(m + 1, 0.0);
  std::vector<double> mm(size_t(m + 1) * nc, 0.0);
  for (const MortarPiece &p : run.pieces) {
    // The piece's ends on body 1's segment x_k -> x_k+1: the weight 2 pi r is linear there.
    const Point xk = body1.node(g.nodes[run.positions[p.k]]), xk1 = body1.node(g.nodes[run.positions[p.k + 1]]);
    const Point end0 = lerp(xk, xk1, p.xi0), end1 = lerp(xk, xk1, p.xi1);
    double psi[2][2], phi[2][2] = {{1 - p.xi0, 1 - p.xi1}, {p.xi0, p.xi1}};
    test_functions(method, p, xk, xk1, measure, psi[0], psi[1]);
    const SurfaceSegment &s = g.mortar_segments[p.segment];
    double phi2[2][2] = {{1 - p.eta0, 1 - p.eta1}, {p.eta0, p.eta1}};
    int node2[2] = {s.a, s.b};
    for (int t = 0; t < 2; ++t) {
      int i = multiplier(p.k + t);
      for (int j = 0; j < 2; ++j) {
        double dij = measure.product_integral(end0, end1, psi[t][0], psi[t][1], phi[j][0], phi[j][1]);
        int col = p.k + j;
        (col == i ? diag : col < i ? lower : upper)[i] += dij;
        mm[size_t(i) * nc + column[node2[j]]] += measure.product_integral(end0, end1, psi[t][0], psi[t][1], phi2[j][0], phi2[j][1]);
      }
    }
  }
  // Interior rows: D_II P_I = M_I - D_IE P_E, solved by the Thomas algorithm (D_II is
  // tridiagonal and diagonally dominant on a covered run).
  std::vector<double> rhs(size_t(m + 1) * nc, 0.0);
  for (int i = 1; i < m; ++i)
    for (int c = 0; c < nc; ++c) rhs[size_t(i) * nc + c] = mm[size_t(i) * nc + c];
  for (int c = 0; c < nc; ++c) {
    rhs[size_t(1) * nc + c] -= lower[1] * end_row[0][c];
    rhs[size_t(m - 1) * nc + c] -= upper[m - 1] * end_row[1][c];
  }
  double scale = 0;
  for (int i = 1; i < m; ++i) scale = std::max(scale, std::fabs(diag[i]));
  std::vector<double> c_prime(m + 1, 0.0);
  for (int i = 1; i < m; ++i) {
    double pivot = diag[i] - (i > 1 ? lower[i] * c_prime[i - 1] : 0);
    if (!(std::fabs(pivot) > 1e-12 * scale))
      fail(MC_ERROR_CONTACT,
           "the mortar matrix D is singular at body-1 contact node %d: body 2's surface covers too little "
           "of the body-1 edges around it",
           g.nodes[run.positions[i]]);
    c_prime[i] = upper[i] / pivot;
    for (int c = 0; c < nc; ++c) {
      double &r = rhs[size_t(i) * nc + c];
      if (i > 1) r -= lower[i] * rhs[size_t(i - 1) * nc + c];
      r /= pivot;
    }
  }
  for (int i = m - 2; i >= 1; --i)
    for (int c = 0; c < nc; ++c) rhs[size_t(i) * nc + c] -= c_prime[i] * rhs[size_t(i + 1) * nc + c];

  for (int k = 0; k <= m; ++k) {
    const double *values = k == 0 ? end_row[0].data() : k == m ? end_row[1].data() : &rhs[size_t(k) * nc];
    std::map<int, double> entries;
    for (int c = 0; c < nc; ++c)
      if (values[c] != 0) entries[column_node[c]] = values[c];
    append_row(rows, run.positions[k], entries);
  }
}

}  // namespace

ConstraintRows build_constraint_rows(const ContactGeometry &g, const Mesh &body1, const Mesh &, int method,
                                     const LineMeasure &measure) {
  ConstraintRows rows;
  rows.start.push_back(0);
  for (const ContactRun &run : g.runs) {
    // Node-to-segment, and runs too short to carry a multiplier (one or two nodes: only the
    // end conditions of (3.2) remain), use the pointwise constraint.
    if (method == MC_METHOD_NODE_TO_SEGMENT || run.positions.size() <= 2) {
      for (int pos : run.positions) {
        std::map<int, double> w;
        add_interpolation(g, g.projection[pos], w);
        append_row(rows, pos, w);
      }
    } else {
      mortar_rows(g, run, body1, method, measure, rows);
    }
  }
  return rows;
}

}  // namespace mc
