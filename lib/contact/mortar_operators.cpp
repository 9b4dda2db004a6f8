#include "contact/mortar_operators.hpp"
#include "contact/mortar_spaces.hpp"
#include "bodies/cell_shapes.hpp"
#include "bodies/plane_vectors.hpp"
#include "support/error.hpp"
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace mc {

// The body-2 trace at a surface point: its nodes (2, or 3 on a quadratic edge: ends, middle) and
// their shape functions there. Returns the count.
int mortar_trace(const ContactGeometry &g, SurfacePoint at, int node[3], double shape[3]) {
  const CurveSegment &s = g.mortar.segments()[at.segment];
  double ds[3];
  const int count = s.quadratic() ? 3 : 2;
  line_shapes(count, at.eta, shape, ds);
  node[0] = s.a, node[1] = s.b, node[2] = s.mid;
  return count;
}

namespace {

// The body-1 test functions of an element's two trace points at element coordinate s:
// standard hats for the paper's mortar; for the dual method (Wohlmuth) the biorthogonal ones in
// the measure, psi_0 = c0 phi_0 + c1 phi_1, psi_1 = c2 phi_0 + c3 phi_1 (2, -1, -1, 2 with a
// constant weight; LineMeasure::dual_basis with 2 pi r).
void test_functions(int method, double s, const double c[4], double psi[2]) {
  const double phi0 = 1 - s, phi1 = s;
  if (method == MC_METHOD_DUAL_MORTAR) psi[0] = c[0] * phi0 + c[1] * phi1, psi[1] = c[2] * phi0 + c[3] * phi1;
  else psi[0] = phi0, psi[1] = phi1;
}

// Interpolation weights of u2 at a body-2 surface point.
void add_interpolation(const ContactGeometry &g, SurfacePoint at, std::map<int, double> &row) {
  int node[3];
  double shape[3];
  const int count = mortar_trace(g, at, node, shape);
  for (int a = 0; a < count; ++a) row[node[a]] += shape[a];
}


// A row's body-2 weights as kept: weights below 1e-17 of the row's largest are left out: D^-1
// decays geometrically away from the diagonal, so most of a long run's row is round-off, and B
// stays sparse. Appended to (out_nodes, out_w).
template <class Nodes, class Weights>
void keep_weights(const int *nodes, const double *w, int n, Nodes &out_nodes, Weights &out_w) {
  double largest = 0;
  for (int k = 0; k < n; ++k) largest = std::max(largest, std::fabs(w[k]));
  for (int k = 0; k < n; ++k)
    if (w[k] != 0 && std::fabs(w[k]) >= 1e-17 * largest) out_nodes.push_back(nodes[k]), out_w.push_back(w[k]);
}

// A row: body 1 at trace point t; body 2 with weights w over nodes (both n long, nodes
// ascending; n = 0 for a pending row, ConstraintRows::pending).
void append_row(ConstraintRows &rows, const TracePoint &t, const int *nodes, const double *w, int n) {
  rows.position1.push_back(t.a);
  rows.weight1.push_back(t.is_position() ? 1.0 : 1 - t.xi);
  if (!t.is_position()) rows.position1.push_back(t.b), rows.weight1.push_back(t.xi);
  rows.start1.push_back(int(rows.position1.size()));
  keep_weights(nodes, w, n, rows.body2_node, rows.weight2);
  rows.start2.push_back(int(rows.body2_node.size()));
  rows.normal.push_back(t.normal);
  rows.gap0.push_back(t.gap0);
  rows.own_position.push_back(t.is_position() ? t.a : -1);
  rows.aux.push_back(-1);
}

// The pointwise row at a trace point (node-to-segment, and the ends of Gamma_c in (3.2)).
void append_pointwise_row(const ContactGeometry &g, ConstraintRows &rows, const TracePoint &t) {
  std::map<int, double> row;
  add_interpolation(g, t.projection, row);
  std::vector<int> nodes;
  std::vector<double> w;
  for (auto &[node, value] : row) nodes.push_back(node), w.push_back(value);
  append_row(rows, t, nodes.data(), w.data(), int(nodes.size()));
}

// Solves the tridiagonal system rows first..last of (lower, diag, upper) for nc right-hand
// sides stored row-major in rhs (Thomas algorithm; D is diagonally dominant on a covered run).
// Returns the row of a vanishing pivot, or -1.
// c_prime: scratch, resized here (a caller solving many small systems keeps one).
int solve_tridiagonal(const std::vector<double> &lower, const std::vector<double> &diag, const std::vector<double> &upper,
                      int first, int last, int nc, std::vector<double> &rhs, std::vector<double> &c_prime) {
  double scale = 0;
  for (int i = first; i <= last; ++i) scale = std::max(scale, std::fabs(diag[i]));
  c_prime.assign(diag.size(), 0.0);
  for (int i = first; i <= last; ++i) {
    const double pivot = diag[i] - (i > first ? lower[i] * c_prime[i - 1] : 0);
    if (!(std::fabs(pivot) > 1e-12 * scale)) return i;
    c_prime[i] = upper[i] / pivot;
    for (int c = 0; c < nc; ++c) {
      double &r = rhs[size_t(i) * nc + c];
      if (i > first) r -= lower[i] * rhs[size_t(i - 1) * nc + c];
      r /= pivot;
    }
  }
  for (int i = last - 1; i >= first; --i)
    for (int c = 0; c < nc; ++c) rhs[size_t(i) * nc + c] -= c_prime[i] * rhs[size_t(i + 1) * nc + c];
  return -1;
}

// The same for a cyclic tridiagonal matrix (corners lower[0] at (0, n-1) and upper[n-1] at
// (n-1, 0)) by the Sherman-Morrison formula: a closed loop's D.
int solve_cyclic_tridiagonal(std::vector<double> lower, std::vector<double> diag, std::vector<double> upper, int nc,
                             std::vector<double> &rhs) {
  const int n = int(diag.size());
  const double top_right = lower[0], bottom_left = upper[n - 1], gamma = -diag[0];
  diag[0] -= gamma;
  diag[n - 1] -= bottom_left * top_right / gamma;
  lower[0] = 0, upper[n - 1] = 0;
  std::vector<double> z(n, 0.0);
  z[0] = gamma, z[n - 1] = bottom_left;
  std::vector<double> c_prime;
  int bad = solve_tridiagonal(lower, diag, upper, 0, n - 1, nc, rhs, c_prime);
  if (bad >= 0) return bad;
  solve_tridiagonal(lower, diag, upper, 0, n - 1, 1, z, c_prime);
  const double denominator = 1 + z[0] + top_right * z[n - 1] / gamma;
  for (int c = 0; c < nc; ++c) {
    const double factor = (rhs[c] + top_right * rhs[size_t(n - 1) * nc + c] / gamma) / denominator;
    for (int i = 0; i < n; ++i) rhs[size_t(i) * nc + c] -= factor * z[i];
  }
  return -1;
}

// Room in v for `more` entries after its own, at least doubling its capacity (a run after run
// reserving just what it needs would copy the arrays once per run; grown entry by entry, a long
// run's were copied into fresh memory again and again).
template <class T> void make_room(std::vector<T> &v, size_t more) {
  if (v.size() + more > v.capacity()) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

// A sparse row: (column, value), columns ascending and distinct once merged.
using SparseRow = std::vector<std::pair<int, double>>;

// Sums of terms per column, as a row's terms are merged: the columns ascending, each column's
// terms added in ascending order of value (the order of sorting the (column, value) pairs and
// summing equal columns left to right, which the rows were first built with: the same sums, bit
// for bit). A row of pi_h collects some 300 terms over some 100 body-2 nodes: sorting them all
// took a third of the 16001-node strips' operators; here each term goes to its column's slot,
// and only a column's few terms, and the columns, are sorted (the columns mostly come in order).
class ColumnSums {
public:
  explicit ColumnSums(int columns) : slot_(columns, -1) {}
  void add(int column, double value) {
    int &slot = slot_[column];
    if (slot < 0) slot = int(column_.size()), column_.push_back(column);
    term_.emplace_back(slot, value);
  }
  // The row so far into `row` (replaced), and a fresh start.
  void take(SparseRow &row) {
    const int n = int(column_.size());
    start_.assign(n + 1, 0);
    for (const auto &t : term_) ++start_[t.first + 1];
    for (int c = 0; c < n; ++c) start_[c + 1] += start_[c];
    next_.assign(start_.begin(), start_.end() - 1);
    value_.resize(term_.size());
    for (const auto &t : term_) value_[next_[t.first]++] = t.second;
    order_.resize(n);
    for (int c = 0; c < n; ++c) order_[c] = c;
    auto by_column = [&](int a, int b) { return column_[a] < column_[b]; };
    if (!std::is_sorted(order_.begin(), order_.end(), by_column)) std::sort(order_.begin(), order_.end(), by_column);
    row.clear();
    for (int c : order_) {
      double *first = value_.data() + start_[c], *last = value_.data() + start_[c + 1];
      std::sort(first, last);
      double sum = *first;
      for (const double *v = first + 1; v < last; ++v) sum += *v;
      row.emplace_back(column_[c], sum);
      slot_[column_[c]] = -1;
    }
    column_.clear(), term_.clear();
  }

private:
  std::vector<int> slot_;                      // per column: its slot in the row being summed, or -1
  std::vector<int> column_;                    // per slot: its column
  std::vector<std::pair<int, double>> term_;   // (slot, value) as added
  std::vector<int> start_, next_, order_;
  std::vector<double> value_;                  // the terms slot after slot
};

// Row k of D^-1 (D tridiagonal: lower, diag, upper; cyclic on a closed run), restricted to the
// points whose entries are not round-off: D is diagonally dominant (a mass matrix on the trace,
// or the dual basis' diagonal one), so the row decays geometrically away from k (about 0.27 per
// point) and a window of points around k gives it to full precision. The window grows until
// its ends are below 1e-20 of the largest entry, or it covers the run. Interior points
// first..last (open run) or all n (closed). Cost: O(window) per row, where solving D with one
// right-hand side per column of M cost O(n) per column, O(n^2) for a long run. Into `row`.
// `work`: the window's scratch, kept from row to row (a long run has thousands of rows).
struct InverseRowWork {
  std::vector<int> point;
  std::vector<double> lo, di, up, z, c_prime;
};

void inverse_row(const std::vector<double> &lower, const std::vector<double> &diag, const std::vector<double> &upper,
                 int first, int last, bool closed, int k, InverseRowWork &work, SparseRow &row) {
  const int n = last - first + 1;
  row.clear();
  std::vector<int> &point = work.point;
  std::vector<double> &lo = work.lo, &di = work.di, &up = work.up, &z = work.z;
  for (int half = 24;; half *= 2) {
    const bool whole = 2 * half + 1 >= n;
    // Row k of D^-1 is the solution of D^T z = e_k. Window: positions k - half .. k + half
    // (mod n on a loop), or the whole run.
    point.clear();
    if (whole) {
      for (int i = first; i <= last; ++i) point.push_back(i);
    } else if (closed) {
      for (int j = -half; j <= half; ++j) point.push_back(((k + j) % n + n) % n);
    } else {
      for (int i = std::max(first, k - half); i <= std::min(last, k + half); ++i) point.push_back(i);
    }
    const int m = int(point.size());
    // D^T restricted to the window: (D^T)_{i,i-1} = upper[i-1], (D^T)_{i,i+1} = lower[i+1].
    lo.assign(m, 0.0), di.assign(m, 0.0), up.assign(m, 0.0), z.assign(m, 0.0);
    for (int j = 0; j < m; ++j) {
      const int i = point[j];
      di[j] = diag[i];
      const int before = closed ? (i + n - 1) % n : i - 1, after = closed ? (i + 1) % n : i + 1;
      if (j > 0 || (whole && closed)) lo[j] = upper[before];
      if (j < m - 1 || (whole && closed)) up[j] = lower[after];
      if (i == k) z[j] = 1;
    }
    int bad;
    if (whole && closed) bad = solve_cyclic_tridiagonal(lo, di, up, 1, z);
    else bad = solve_tridiagonal(lo, di, up, 0, m - 1, 1, z, work.c_prime);
    if (bad >= 0) return;  // (empty) the caller has checked D's pivots over the whole run
    double largest = 0;
    for (double v : z) largest = std::max(largest, std::fabs(v));
    const bool converged = whole || ((closed || point.front() == first || std::fabs(z.front()) <= 1e-20 * largest) &&
                                     (closed || point.back() == last || std::fabs(z.back()) <= 1e-20 * largest) &&
                                     (!closed || std::max(std::fabs(z.front()), std::fabs(z.back())) <= 1e-20 * largest));
    if (!converged) continue;
    for (int j = 0; j < m; ++j)
      if (z[j] != 0) row.emplace_back(point[j], z[j]);
    return;
  }
}

// Rows of one run for the mortar methods: the paper's pi_h^1 (3.2).
// sums: a ColumnSums over body 2's nodes, inverse: scratch, both kept from run to run.
void mortar_rows(const ContactGeometry &g, const ContactRun &run, int method, const LineMeasure &measure,
                 ConstraintRows &rows, ColumnSums &sums, InverseRowWork &inverse) {
  const int n = int(run.trace.size());
  const bool closed = run.closed;
  // End rows: (pi phi)(c_i) = phi(c_i), i.e. interpolation at the projection of c_1, c_2.
  SparseRow end_row[2];
  if (!closed)
    for (int e = 0; e < 2; ++e) {
      std::map<int, double> w;
      add_interpolation(g, run.trace[e == 0 ? 0 : n - 1].projection, w);
      for (auto &[node, value] : w) end_row[e].emplace_back(node, value);
    }
  // The multipliers (rows of D and M) that trace point k's test function on element e feeds.
  const MultiplierSpace space(run, true);  // shared ends for both bases (mortar_spaces.hpp)
  // D (band: trace points i-1, i, i+1 of row i, cyclic on a loop) and M (sparse: row i over the
  // body-2 nodes that its multiplier's support faces).
  std::vector<double> lower(n, 0.0), diag(n, 0.0), upper(n, 0.0);
  // M's terms as they come, (row, node, value), grouped by row below (an array per row cost an
  // allocation or more per trace point).
  std::vector<int> term_row, term_node;
  std::vector<double> term_value;
  // (at most 2 test functions x 2 multipliers each x 3 body-2 nodes a point: reserved, not touched)
  const size_t most_terms = 12 * run.elements.points.size() + 6;
  term_row.reserve(most_terms), term_node.reserve(most_terms), term_value.reserve(most_terms);
  for (int e = 0; e < int(run.elements.size()); ++e) {
    double c[4] = {2, -1, -1, 2};
    if (method == MC_METHOD_DUAL_MORTAR) measure.dual_basis(run.trace[e].x, run.trace[(e + 1) % n].x, c);
    for (const QuadraturePoint &q : run.elements[e]) {
      double psi[2];
      test_functions(method, q.s, c, psi);
      const double phi[2] = {1 - q.s, q.s};
      double phi2[3];
      int node2[3];
      const int count2 = mortar_trace(g, q.mortar, node2, phi2);
      for (int t = 0; t < 2; ++t)
        space.feed(e, e + t, q.weight * psi[t], [&](int i, double w) {
          for (int j = 0; j < 2; ++j) {
            const int trace = closed ? (e + j) % n : e + j;
            const int offset = closed ? ((trace - i) % n + n + 1) % n - 1 : trace - i;  // -1, 0 or +1
            (offset == 0 ? diag : offset > 0 ? upper : lower)[i] += w * phi[j];
          }
          for (int j = 0; j < count2; ++j) term_row.push_back(i), term_node.push_back(node2[j]), term_value.push_back(w * phi2[j]);
        });
    }
  }
  // R = M - D_E P_E on the interior points (open), M (closed): D_II P_I = R (3.2).
  // Merged per row (each row's terms in the order they came) into the run's R (CSR), which also
  // computes its explicit rows later (ConstraintRows::PendingRun).
  if (!closed) {
    for (auto &[node, value] : end_row[0]) term_row.push_back(1), term_node.push_back(node), term_value.push_back(-lower[1] * value);
    for (auto &[node, value] : end_row[1])
      term_row.push_back(n - 2), term_node.push_back(node), term_value.push_back(-upper[n - 2] * value);
  }
  ConstraintRows::PendingRun pending;
  {
    std::vector<int> term_start(n + 1, 0), order(term_row.size());
    for (int i : term_row) ++term_start[i + 1];
    for (int i = 0; i < n; ++i) term_start[i + 1] += term_start[i];
    std::vector<int> next(term_start.begin(), term_start.end() - 1);
    for (size_t t = 0; t < term_row.size(); ++t) order[next[term_row[t]]++] = int(t);
    SparseRow merged;
    pending.r_node.reserve(term_row.size()), pending.r_value.reserve(term_row.size());
    for (int i = 0; i < n; ++i) {
      for (int p = term_start[i]; p < term_start[i + 1]; ++p) sums.add(term_node[order[p]], term_value[order[p]]);
      sums.take(merged);
      for (const auto &[node, value] : merged) pending.r_node.push_back(node), pending.r_value.push_back(value);
      pending.r_start.push_back(int(pending.r_node.size()));
    }
  }
  // D's pivots over the whole run (no right-hand side): a vanishing one is an error.
  const int first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  std::vector<double> none;
  const int singular = closed ? solve_cyclic_tridiagonal(lower, diag, upper, 0, none)
                              : solve_tridiagonal(lower, diag, upper, first, last, 0, none, inverse.c_prime);
  if (singular >= 0)
    fail(MC_ERROR_CONTACT,
         "the mortar matrix D is singular at body-1 contact node %d: body 2's surface covers too little "
         "of the body-1 edges around it",
         g.nodes[run.trace[singular].a]);

  // The sparse form: interior point k is auxiliary point aux0 + k (open runs: k - 1, the ends
  // have none). Its equation: D's band on the interior points, R on the body-2 nodes.
  const int aux0 = rows.aux_count - first;
  make_room(rows.aux_d_point, 3 * size_t(n)), make_room(rows.aux_d, 3 * size_t(n));
  make_room(rows.aux_d_start, n), make_room(rows.aux_r_start, n);
  make_room(rows.aux_r_node, pending.r_node.size()), make_room(rows.aux_r, pending.r_node.size());
  make_room(rows.position1, 2 * size_t(n)), make_room(rows.weight1, 2 * size_t(n));
  make_room(rows.start1, n), make_room(rows.start2, n), make_room(rows.normal, n), make_room(rows.gap0, n);
  make_room(rows.own_position, n), make_room(rows.aux, n);
  for (int k = first; k <= last; ++k) {
    const int neighbour[3] = {closed ? (k + n - 1) % n : k - 1, k, closed ? (k + 1) % n : k + 1};
    const double d[3] = {lower[k], diag[k], upper[k]};
    for (int j = 0; j < 3; ++j) {
      if (!closed && (neighbour[j] < first || neighbour[j] > last)) continue;  // an end: moved into R
      if (d[j] != 0) rows.aux_d_point.push_back(aux0 + neighbour[j]), rows.aux_d.push_back(d[j]);
    }
    rows.aux_d_start.push_back(int(rows.aux_d_point.size()));
    for (int p = pending.r_start[k]; p < pending.r_start[k + 1]; ++p)
      if (pending.r_value[p] != 0) rows.aux_r_node.push_back(pending.r_node[p]), rows.aux_r.push_back(pending.r_value[p]);
    rows.aux_r_start.push_back(int(rows.aux_r_node.size()));
  }
  // The explicit rows pi_h = D^-1 R (row k: sum_j (D^-1)_kj R_j), for B: computed from here
  // when B is built (MortarWeights), not stored twice. The ends' rows (interpolation) are kept.
  pending.first_row = rows.size(), pending.n = n, pending.first = first, pending.last = last, pending.closed = closed;
  {
    SparseRow z_row, middle;
    inverse_row(lower, diag, upper, first, last, closed, n / 2, inverse, z_row);
    for (auto &[j, z] : z_row)
      for (int p = pending.r_start[j]; p < pending.r_start[j + 1]; ++p) sums.add(pending.r_node[p], z * pending.r_value[p]);
    sums.take(middle);
    pending.middle_length = middle.size();
  }
  pending.lower = std::move(lower), pending.diag = std::move(diag), pending.upper = std::move(upper);
  for (int k = 0; k < n; ++k) {
    const bool end = !closed && (k == 0 || k == n - 1);
    std::vector<int> nodes;
    std::vector<double> w;
    if (end)  // (its nodes ascending and distinct: merged already)
      for (auto &[node, value] : end_row[k == 0 ? 0 : 1]) nodes.push_back(node), w.push_back(value);
    append_row(rows, run.trace[k], nodes.data(), w.data(), int(nodes.size()));
    if (!end) rows.aux.back() = aux0 + k;
  }
  rows.pending.push_back(std::move(pending));
  rows.aux_count += last - first + 1;
}

// ConstraintRows::measure of a run's rows (one per trace point, in order): the integrals of the
// trace points' hats over the run's elements (their quadrature weights hold the line measure).
void append_trace_hat_measures(const ContactRun &run, ConstraintRows &rows) {
  const int n = int(run.trace.size());
  std::vector<double> hat(n, 0.0);
  for (int e = 0; e < int(run.elements.size()); ++e)
    for (const QuadraturePoint &q : run.elements[e]) hat[e] += q.weight * (1 - q.s), hat[(e + 1) % n] += q.weight * q.s;
  rows.measure.insert(rows.measure.end(), hat.begin(), hat.end());
}

}  // namespace

ConstraintRows build_constraint_rows(const ContactGeometry &g, int method, int multiplier, const LineMeasure &measure) {
  ConstraintRows rows;
  if (method == MC_METHOD_NODE_TO_SEGMENT) {
    // Each body-1 node that sees body 2, against the point it projects to.
    for (size_t pos = 0; pos < g.nodes.size(); ++pos)
      if (g.projection[pos].segment >= 0) {
        TracePoint t;
        t.a = int(pos), t.normal = g.normals[pos], t.gap0 = g.gap0[pos], t.projection = g.projection[pos];
        append_pointwise_row(g, rows, t);
        rows.measure.push_back(g.tributary[pos]);
      }
    return rows;
  }
  int body2_nodes = 0;  // (ids up to the largest on body 2's surface)
  for (const CurveSegment &c : g.mortar.segments()) body2_nodes = std::max({body2_nodes, c.a + 1, c.b + 1, c.mid + 1});
  rows.body2_columns = body2_nodes;
  ColumnSums sums(body2_nodes);
  InverseRowWork inverse;
  for (const ContactRun &run : g.runs) {
    if (g.quadratic_nonmortar) {
      weak_mortar_rows(g, run, multiplier == MC_MULTIPLIER_QUADRATIC, method == MC_METHOD_DUAL_MORTAR, rows);
      continue;
    }
    // Runs of one element carry no multiplier: only the end conditions of (3.2) remain.
    if (!run.closed && run.trace.size() <= 2) {
      for (const TracePoint &t : run.trace) append_pointwise_row(g, rows, t);
    } else {
      mortar_rows(g, run, method, measure, rows, sums, inverse);
    }
    append_trace_hat_measures(run, rows);
  }
  return rows;
}

bool ConstraintRows::weights_pending(int r) const {
  auto after = std::upper_bound(pending.begin(), pending.end(), r,
                                [](int row, const PendingRun &run) { return row < run.first_row; });
  if (after == pending.begin()) return false;
  const PendingRun &run = *(after - 1);
  const int k = r - run.first_row;
  return k >= run.first && k <= run.last;
}

size_t ConstraintRows::pending_weights_estimate() const {
  size_t total = 0;
  for (const PendingRun &run : pending) total += size_t(run.n) * run.middle_length;
  return total;
}

struct MortarWeights::Work {
  explicit Work(int columns) : sums(columns) {}
  ColumnSums sums;
  InverseRowWork inverse;
  SparseRow z_row, values;
  std::vector<int> nodes;
  std::vector<double> w;
};

MortarWeights::MortarWeights(const ConstraintRows &rows) : rows_(rows), work_(std::make_unique<Work>(rows.body2_columns)) {}

MortarWeights::~MortarWeights() = default;

void MortarWeights::row(int r, std::vector<int> &nodes, std::vector<double> &weights, std::vector<Point> &vectors) {
  nodes.clear(), weights.clear(), vectors.clear();
  if (!rows_.weights_pending(r)) {
    nodes.assign(rows_.body2_node.begin() + rows_.start2[r], rows_.body2_node.begin() + rows_.start2[r + 1]);
    weights.assign(rows_.weight2.begin() + rows_.start2[r], rows_.weight2.begin() + rows_.start2[r + 1]);
    if (!rows_.vector2.empty())
      vectors.assign(rows_.vector2.begin() + rows_.start2[r], rows_.vector2.begin() + rows_.start2[r + 1]);
    return;
  }
  auto after = std::upper_bound(rows_.pending.begin(), rows_.pending.end(), r,
                                [](int row, const ConstraintRows::PendingRun &run) { return row < run.first_row; });
  const ConstraintRows::PendingRun &run = *(after - 1);
  Work &w = *work_;
  inverse_row(run.lower, run.diag, run.upper, run.first, run.last, run.closed, r - run.first_row, w.inverse, w.z_row);
  for (auto &[j, z] : w.z_row)
    for (int p = run.r_start[j]; p < run.r_start[j + 1]; ++p) w.sums.add(run.r_node[p], z * run.r_value[p]);
  w.sums.take(w.values);
  w.nodes.clear(), w.w.clear();
  for (auto &[node, value] : w.values) w.nodes.push_back(node), w.w.push_back(value);
  keep_weights(w.nodes.data(), w.w.data(), int(w.nodes.size()), nodes, weights);
}

}  // namespace mc
