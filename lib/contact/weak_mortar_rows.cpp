// The constraint rows of a body 1 with quadratic cells (T6, Q8, Q9): weak rows, one per
// multiplier, with the paper's linear multipliers or quadratic ones (docs/theory.md section 2b).
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include "contact/mortar_spaces.hpp"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include <map>

namespace mc {

namespace {

// The quadratic multipliers' functions on an element at its coordinate s: the Lagrange ones of its
// two ends and its middle (interpolatory: the multiplier's value at a node is its coefficient).
// Tried instead: the Bernstein ones, (1 - s)^2, s^2, 2 s (1 - s), whose nonnegative coefficients
// make the pressure nonnegative everywhere; same space, no better on Hertz (notes).
void quadratic_multiplier_functions(double s, double f[3]) {
  f[0] = (1 - s) * (1 - 2 * s), f[1] = s * (2 * s - 1), f[2] = 4 * s * (1 - s);
}

}  // namespace

// Rows of one run when body 1's trace is quadratic (T6, Q8, Q9). Three multiplier spaces, one
// form of row: the paper's linear M_h^1 (the default, described here), the quadratic space
// (MC_MULTIPLIER_QUADRATIC: a multiplier at every corner and at every interior element's middle,
// end elements constant) and its dual basis (MC_METHOD_DUAL_MORTAR). With the paper's space the
// multipliers stay the paper's M_h^1, continuous piecewise linear on the trace points (Gamma_c's vertex nodes) with
// the end modification, but the constraint is the weak one, for each multiplier psi_i
//     integral over Gamma_c of psi_i ((u1 - u2) . n_i - g0) <= 0,
// since a quadratic W_h^1 has more nodes than M_h^1 has functions and pi_h of (3.2) is not
// defined on it. A nonnegative P1 multiplier is a nonnegative combination of the psi_i, so these
// rows are the exact cone of the mixed P2/P1 method (Hild & Laborde 2002; GetFEM's P2/P1), and
// its KKT forces int lambda phi_k reach every node of body 1's trace, the mid-edge nodes
// included: a uniform pressure loads an edge 1/6, 2/3, 1/6, which is what the patch test needs.
// Each row is divided by int psi_i (its body-1 weights then sum to 1, the row's gap is a length
// and lambda_i a force, as in the paper's rows). The gap is measured along the look direction n(x)
// of each quadrature point, the displacements' too: (u1(x) - u2(y(x))) . n(x). One normal per row
// (the multiplier node's) would project the middle nodes' displacements on a direction off theirs
// by half an edge's turn, an O(h^2) error in the interference of a shrink fit (measured: 0.64 %
// in Lame's pressure with 32 Q8 cells around, 0.16 % with 64); n_i, the multiplier node's normal,
// is the direction its force is reported along.
// A run of one or two elements has one multiplier, constant along it.
//
// The ends of Gamma_c inside a body-1 edge (the first element a fraction theta of its edge):
// the multipliers that the run starting at the next corner would not have (the first corner's,
// constant on the partial element, and with quadratic multipliers the next element's middle)
// and the one that would take their place (the second corner's) form a group G whose functions
// are blended towards their sum F: psi_r -> theta psi_r + (1 - theta) F / |G|. At theta = 1 this
// is the space as it is; as theta -> 0 every member tends to F / |G|, the first multiplier of the
// shorter run, so their constraints become one and the cone tends to the shorter run's (the
// solution is continuous as body 2's end crosses a body-1 node; the snapping of
// contact_geometry, 1e-6 of an edge, then moves it by about that much). The sum over G is kept,
// so constants stay in the space (the patch tests). Sharing the corner's function between the
// two multipliers instead (what the paper's rows do, MultiplierSpace) leaves a constraint
// pinned at the corner, the partial element's, as theta -> 0: measured 3.7 % in the
// displacements (Q8 on Q8) between body 2 ending 1e-5 of an edge before a corner and at it.
void weak_mortar_rows(const ContactGeometry &g, const ContactRun &run, bool quadratic, bool dual, ConstraintRows &rows) {
  if (dual) quadratic = true;  // the dual basis is the quadratic space's
  const int n = int(run.trace.size());
  const bool closed = run.closed, single = !closed && n <= 3;
  const MultiplierSpace space(run, false);
  const int first = closed ? 0 : single ? 0 : 1, last = closed ? n - 1 : single ? 0 : n - 2;
  const int corners = last - first + 1;
  // The quadratic multipliers' middles: one per element that is neither an end element nor the
  // whole of a single run (those stay constant, as in M_h^1), rows corners + own_middle[e].
  std::vector<int> own_middle(run.elements.size(), -1);
  int middles = 0;
  if (quadratic && !single)
    for (int e = 0; e < int(run.elements.size()); ++e)
      if (closed || (e > 0 && e < n - 2)) own_middle[e] = middles++;
  const int count = corners + middles;
  // Entries (node or position, scalar weight, vector weight); merged per row below.
  struct Entry {
    int id;
    double w;
    Point v;
    bool operator<(const Entry &o) const { return id < o.id; }
  };
  auto merged = [](std::vector<Entry> &row) {
    std::sort(row.begin(), row.end());
    size_t kept = 0;
    for (size_t i = 0; i < row.size(); ++i) {
      if (kept > 0 && row[kept - 1].id == row[i].id) row[kept - 1].w += row[i].w, row[kept - 1].v = plus(row[kept - 1].v, row[i].v);
      else row[kept++] = row[i];
    }
    row.resize(kept);
  };
  // The multiplier rows that element e's local function t (0, 1: its ends, 2: its middle)
  // feeds, with its share of `value`.
  auto feed = [&](int e, int t, double value, auto &&add_row) {
    auto add = [&](int i, double v) { add_row(single ? 0 : i - first, v); };
    if (single) return add(0, value);
    if (t < 2) return space.feed(e, e + t, value, add);
    if (own_middle[e] >= 0) return add_row(corners + own_middle[e], value);
    space.feed(e, e == 0 ? 0 : e + 1, value, add);  // an end element's middle: its constant
  };
  std::vector<std::vector<Entry>> body1(count), body2(count);
  std::vector<double> gap(count, 0.0), total(count, 0.0);
  for (int e = 0; e < int(run.elements.size()); ++e) {
    // The element's multiplier functions as combinations of its quadratic ones N_b: the identity,
    // or for dual mortar Wohlmuth's biorthogonal basis psi_a = sum_b A_ab N_b, A = D M^-1 with
    // M_ab = int N_a N_b and D = diag(int N_a) in the element's measure (its quadrature weights,
    // 2 pi r included), so that int psi_a N_b = delta_ab int N_a: each row then tests body 1's
    // trace at its own node only. (Quadratic in 2D: the integrals of N are h/6, h/6, 2h/3, all
    // positive, so D is regular; ../shared/design/quadratic.md.) Sum_a psi_a = 1, so an end
    // element, whose functions all feed one multiplier, stays constant.
    double dual_a[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (dual) {
      double m[3][3] = {}, d[3] = {};
      for (const QuadraturePoint &q : run.elements[e]) {
        double f[3];
        quadratic_multiplier_functions(q.s, f);
        for (int a = 0; a < 3; ++a) {
          d[a] += q.weight * f[a];
          for (int b = 0; b < 3; ++b) m[a][b] += q.weight * f[a] * f[b];
        }
      }
      // M^-1 = adj(M) / det (symmetric positive definite: det > 0 on an element of positive
      // measure; one of none is refused below, its rows having no measure)
      double adj[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const int a1 = (b + 1) % 3, a2 = (b + 2) % 3, b1 = (a + 1) % 3, b2 = (a + 2) % 3;
          adj[a][b] = m[a1][b1] * m[a2][b2] - m[a1][b2] * m[a2][b1];
        }
      const double det = m[0][0] * adj[0][0] + m[0][1] * adj[1][0] + m[0][2] * adj[2][0];
      if (det > 0)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) dual_a[a][b] = d[a] * adj[a][b] / det;
    }
    for (const QuadraturePoint &q : run.elements[e]) {
      const std::array<int, 3> &pos = g.segment_positions[q.segment1];
      const int count1 = pos[2] >= 0 ? 3 : 2;
      double phi1[3], ds[3], phi2[3];
      line_shapes(count1, q.xi1, phi1, ds);
      int node2[3];
      const int count2 = mortar_trace(g, q.mortar, node2, phi2);
      // The multiplier space's local functions: the hats of the two trace points, or the
      // quadratic ones of the element's two ends and its middle.
      double local[3] = {1 - q.s, q.s, 0};
      if (quadratic) {
        double f[3];
        quadratic_multiplier_functions(q.s, f);
        for (int a = 0; a < 3; ++a) local[a] = dual_a[a][0] * f[0] + dual_a[a][1] * f[1] + dual_a[a][2] * f[2];
      }
      auto add_row = [&](int r, double w) {
        for (int a = 0; a < count1; ++a) body1[r].push_back({pos[a], w * phi1[a], scaled(q.normal, w * phi1[a])});
        for (int a = 0; a < count2; ++a) body2[r].push_back({node2[a], w * phi2[a], scaled(q.normal, w * phi2[a])});
        gap[r] += w * q.gap, total[r] += w;
      };
      for (int t = 0; t < (quadratic ? 3 : 2); ++t) feed(e, t, q.weight * local[t], add_row);
    }
  }
  // The end groups (see above), in the order they are applied.
  struct Blend {
    std::vector<int> group;
    double theta;
  };
  std::vector<Blend> blends;
  if (!closed && !single && n >= 4) {
    if (!run.trace.front().is_position()) {
      Blend b{{0, 1}, 1 - run.trace.front().xi};
      if (own_middle[1] >= 0) b.group.push_back(corners + own_middle[1]);
      blends.push_back(b);
    }
    if (!run.trace.back().is_position()) {
      Blend b{{corners - 1, corners - 2}, run.trace.back().xi};
      if (own_middle[n - 3] >= 0) b.group.push_back(corners + own_middle[n - 3]);
      blends.push_back(b);
    }
  }
  for (const Blend &b : blends) {
    const double share = (1 - b.theta) / double(b.group.size());
    std::vector<Entry> sum1, sum2;
    double sum_gap = 0, sum_total = 0;
    for (int r : b.group) {
      sum1.insert(sum1.end(), body1[r].begin(), body1[r].end()), sum2.insert(sum2.end(), body2[r].begin(), body2[r].end());
      sum_gap += gap[r], sum_total += total[r];
    }
    for (int r : b.group) {
      for (auto *row : {&body1[r], &body2[r]})
        for (Entry &e : *row) e.w *= b.theta, e.v = scaled(e.v, b.theta);
      for (const Entry &e : sum1) body1[r].push_back({e.id, share * e.w, scaled(e.v, share)});
      for (const Entry &e : sum2) body2[r].push_back({e.id, share * e.w, scaled(e.v, share)});
      gap[r] = b.theta * gap[r] + share * sum_gap, total[r] = b.theta * total[r] + share * sum_total;
    }
  }
  // mu at the run's positions (ConstraintRows::pressure_of_position): at the ends of each element
  // the multipliers' values (the share of a trace point's function each one takes there),
  // averaged over the one or two elements at a trace point; at a mid-edge node inside an element,
  // the element's functions there. Gathered as the functions' values per row, blended as the
  // rows were, then divided by the rows' integrals.
  // (Sparse: a position sees the few rows of its one or two elements; a dense row vector per
  // position would be O(n^2) along a long interface.)
  using Values = std::vector<std::pair<int, double>>;  // (row of this run, value), rows repeated
  std::map<int, Values> value_at;                       // position -> the rows' functions there
  std::map<int, int> elements_at;
  auto add_values = [&](int position, int e, const double f[3], double weight) {
    Values &v = value_at[position];
    for (int t = 0; t < (quadratic ? 3 : 2); ++t)
      if (f[t] != 0) feed(e, t, weight * f[t], [&](int r, double x) { v.emplace_back(r, x); });
  };
  for (int e = 0; e < int(run.elements.size()); ++e) {
    const int k0 = e, k1 = closed ? (e + 1) % n : e + 1;
    const double at_start[3] = {1, 0, 0}, at_end[3] = {0, 1, 0};
    if (run.trace[k0].is_position()) add_values(run.trace[k0].a, e, at_start, 1.0), elements_at[run.trace[k0].a]++;
    if (run.trace[k1].is_position()) add_values(run.trace[k1].a, e, at_end, 1.0), elements_at[run.trace[k1].a]++;
    // The middle of the element's body-1 edge, if the element holds it: s is affine in the
    // edge's parameter xi along an element (one edge, or a part of it).
    const ElementPoints qs = run.elements[e];
    if (qs.size() < 2) continue;
    const QuadraturePoint &qa = qs.front(), &qb = qs.back();
    const int mid = g.segment_positions[qa.segment1][2];
    if (mid < 0 || qb.xi1 == qa.xi1 || qb.segment1 != qa.segment1) continue;
    const double s_mid = qa.s + (0.5 - qa.xi1) * (qb.s - qa.s) / (qb.xi1 - qa.xi1);
    if (s_mid <= 1e-9 || s_mid >= 1 - 1e-9) continue;  // outside, or a trace point of its own
    double f[3] = {1 - s_mid, s_mid, 0};
    if (quadratic) quadratic_multiplier_functions(s_mid, f);
    add_values(mid, e, f, 1.0);
  }
  const int row0 = rows.size();
  if (rows.pressure_of_position.empty()) rows.pressure_of_position.resize(g.nodes.size());
  for (auto &[position, v] : value_at) {
    const auto at = elements_at.find(position);
    const double average = at == elements_at.end() ? 1.0 : 1.0 / at->second;  // a trace point: over its elements
    std::map<int, double> value;  // per row, summed
    for (auto &[r, x] : v) value[r] += x;
    for (const Blend &b : blends) {
      double sum = 0;
      bool seen = false;  // a group none of whose rows reach this position leaves it alone
      for (int r : b.group) {
        const auto it = value.find(r);
        if (it != value.end()) sum += it->second, seen = true;
      }
      if (!seen) continue;
      for (int r : b.group) value[r] = b.theta * value[r] + (1 - b.theta) / double(b.group.size()) * sum;
    }
    for (auto &[r, x] : value)
      if (x != 0 && total[r] > 0) rows.pressure_of_position[position].emplace_back(row0 + r, average * x / total[r]);
  }
  // A middle row's element, and its position (the body-1 edge's mid-edge node).
  std::vector<int> middle_position(middles, -1);
  for (int e = 0; e < int(run.elements.size()); ++e)
    if (own_middle[e] >= 0 && !run.elements[e].empty())
      middle_position[own_middle[e]] = g.segment_positions[run.elements[e].front().segment1][2];
  for (int r = 0; r < count; ++r) {
    // The row's trace point: its multiplier's node (the middle one of a single multiplier on
    // two elements; none on one element); a middle row's mid-edge node.
    const bool middle = r >= corners;
    const int k = middle ? -1 : single ? (n == 3 ? 1 : -1) : first + r;
    const int mid = middle ? middle_position[r - corners] : -1;
    if (!(total[r] > 0) || (middle && mid < 0))
      fail(MC_ERROR_CONTACT,
           "the contact constraint at body-1 contact node %d has no measure: body 2's surface covers too little of "
           "the body-1 edges around it",
           g.nodes[mid >= 0 ? mid : run.trace[k >= 0 ? k : 0].a]);
    merged(body1[r]), merged(body2[r]);
    const double scale = 1 / total[r];
    for (const Entry &e : body1[r])
      rows.position1.push_back(e.id), rows.weight1.push_back(e.w * scale), rows.vector1.push_back(scaled(e.v, scale));
    rows.start1.push_back(int(rows.position1.size()));
    for (const Entry &e : body2[r])
      if (e.w != 0 || e.v.x != 0 || e.v.y != 0)
        rows.body2_node.push_back(e.id), rows.weight2.push_back(e.w * scale), rows.vector2.push_back(scaled(e.v, scale));
    rows.start2.push_back(int(rows.body2_node.size()));
    rows.normal.push_back(middle ? g.normals[mid]
                          : k >= 0 ? run.trace[k].normal : unit(plus(run.trace.front().normal, run.trace.back().normal)));
    rows.gap0.push_back(gap[r] / total[r]);
    rows.measure.push_back(total[r]);
    rows.own_position.push_back(middle ? mid : k >= 0 && run.trace[k].is_position() ? run.trace[k].a : -1);
    rows.aux.push_back(-1);
  }
}

}  // namespace mc
