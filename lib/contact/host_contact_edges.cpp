#include "contact/host_contact_edges.hpp"
#include "support/error.hpp"
#include "bodies/plane_vectors.hpp"
#include <cmath>
#include <cstdio>
#include <utility>

namespace mc {

ChordPlace place_on_chord(Point a, Point b, Point m) {
  const Point chord = minus(b, a), to_m = minus(m, a);
  const double length2 = dot(chord, chord);
  if (!(length2 > 0)) return {NAN, NAN};
  return {dot(to_m, chord) / length2, std::fabs(cross(chord, to_m)) / length2};
}

// Along the chord: the middle half, as for a mesh body's middles (whose cells' Jacobian check
// asks "well inside its edge's middle half"). It is exactly where the edge's quadratic map
// x(s) = N_a a + N_b b + N_m m advances along the chord for every s: its derivative's chord
// component, (s + 1/2) - 2 s t at middle position t, is linear in s and positive at s = -1 and
// s = 1 iff 1/4 < t < 3/4. Outside it the edge folds back on itself near one end.
// Off the chord: a circular arc of angle theta with its middle at the arc's midpoint lies
// tan(theta / 4) / 2 chord lengths off its chord: 0.21 at 90 degrees, 0.29 at 120 degrees, 0.5
// for a half circle. 0.3 admits every curved side a mesh of quadratic cells has (one cell
// rarely spans more than 90 degrees of a circle) and refuses a middle far off to one side.
// A side given (corner, middle, corner) and read as (end, end, middle) has its "middle" beyond
// its "ends" (at 2 cos^2(theta / 4) >= 1 of the chord for an arc up to 180 degrees): never
// between, whatever the bound off the chord.
bool lies_between_ends(ChordPlace p) { return p.along > 0.25 && p.along < 0.75 && p.off <= kMaxMiddleOffset; }

namespace {

ChordPlace place_of(const Mesh &nodes, const int *v) { return place_on_chord(nodes.node(v[0]), nodes.node(v[1]), nodes.node(v[2])); }

// The same edge read as (corner, middle, corner): its second node between the first and third.
ChordPlace place_as_corner_middle_corner(const Mesh &nodes, const int *v) {
  return place_on_chord(nodes.node(v[0]), nodes.node(v[2]), nodes.node(v[1]));
}

// Read as (corner, middle, corner) to be reordered: its middle near the chord's midpoint too
// (0.4 to 0.6 of it), as a legacy program's middles are. An edge (end, end, x) given with a
// wrong x can happen to have its second end between the first and x; near the midpoint it
// rarely does, so a wrong middle is refused rather than read as another edge.
bool clearly_corner_middle_corner(const Mesh &nodes, const int *v) {
  const ChordPlace p = place_as_corner_middle_corner(nodes, v);
  return lies_between_ends(p) && std::fabs(p.along - 0.5) <= 0.1;
}

// other: an edge that is not (corner, middle, corner), given as (end, end, middle) if
// other_fits: why edge e is not read so.
[[noreturn]] void fail_not_between(const Mesh &nodes, const std::vector<int> &ids, int e, int other, bool other_fits,
                                   int base, const std::function<std::string(int)> &describe) {
  const int *v = ids.data() + 3 * size_t(e);
  const ChordPlace p = place_of(nodes, v);
  char where[200];
  if (std::isnan(p.along))
    std::snprintf(where, sizeof where, "its ends, nodes %d and %d, are at one point", v[0] + base, v[1] + base);
  else
    std::snprintf(where, sizeof where,
                  "node %d is not between its ends %d and %d: it projects at %.3g of the chord from node %d (wanted: "
                  "inside the middle half, 0.25 to 0.75) and lies %.3g chord lengths off it (at most %.1f)",
                  v[2] + base, v[0] + base, v[1] + base, p.along, v[0] + base, p.off, kMaxMiddleOffset);
  char why[400] = "";
  if (clearly_corner_middle_corner(nodes, v) && other >= 0)
    std::snprintf(why, sizeof why,
                  ": this edge's nodes lie as (corner, middle, corner), so it would be (%d, %d, %d), but edge %d (%s) "
                  "%s: a surface whose edges are not all given one way is not guessed at",
                  v[0] + base, v[2] + base, v[1] + base, other + base, describe(other).c_str(),
                  other_fits ? "is given as (end, end, middle)" : "does not lie so");
  fail(MC_ERROR_CONTACT,
       "edge %d (%s): %s; mc_set_contact_curved takes each edge as (end, end, middle)%s", e + base, describe(e).c_str(),
       where, why);
}

// Roles: a node is the middle of one edge at most, and never both a middle and an end.
void check_node_roles(int n_nodes, const std::vector<int> &ids, int base, const std::function<std::string(int)> &describe) {
  const int n_edges = int(ids.size() / 3);
  std::vector<int> middle_of(n_nodes, -1), end_of(n_nodes, -1);
  for (int e = 0; e < n_edges; ++e) {
    const int *v = ids.data() + 3 * size_t(e);
    end_of[v[0]] = end_of[v[1]] = e;
    const int m = v[2];
    if (middle_of[m] >= 0)
      fail(MC_ERROR_CONTACT, "edge %d (%s) and edge %d (%s) both have node %d as their middle: a middle node belongs to "
           "one edge (mc_set_contact_curved takes each edge as (end, end, middle))", middle_of[m] + base,
           describe(middle_of[m]).c_str(), e + base, describe(e).c_str(), m + base);
    middle_of[m] = e;
  }
  for (int e = 0; e < n_edges; ++e) {
    const int m = ids[3 * size_t(e) + 2];
    if (end_of[m] >= 0)
      fail(MC_ERROR_CONTACT, "node %d is the middle of edge %d (%s) and an end of edge %d (%s): a node is an edge's "
           "middle or an end of edges, never both (mc_set_contact_curved takes each edge as (end, end, middle))",
           m + base, e + base, describe(e).c_str(), end_of[m] + base, describe(end_of[m]).c_str());
  }
}

}  // namespace

bool order_host_curved_edges(const Mesh &nodes, std::vector<int> &ids, int base,
                             const std::function<std::string(int)> &describe) {
  const int n_edges = int(ids.size() / 3);
  int first_misfit = -1, first_fit = -1;  // as (end, end, middle)
  int first_not_corner_middle_corner = -1;
  for (int e = 0; e < n_edges; ++e) {
    const int *v = ids.data() + 3 * size_t(e);
    if (lies_between_ends(place_of(nodes, v))) {
      if (first_fit < 0) first_fit = e;
    } else if (first_misfit < 0) {
      first_misfit = e;
    }
    if (first_not_corner_middle_corner < 0 && !clearly_corner_middle_corner(nodes, v))
      first_not_corner_middle_corner = e;
  }
  // Reordered only when the positions leave no doubt: every edge reads as (corner, middle,
  // corner) and none as (end, end, middle). A surface mixing the two is more likely wrong in
  // some other way than given in two orders, and is refused naming an edge of each.
  const bool reorder = first_fit < 0 && first_not_corner_middle_corner < 0;
  if (reorder)
    for (int e = 0; e < n_edges; ++e) std::swap(ids[3 * size_t(e) + 1], ids[3 * size_t(e) + 2]);
  else if (first_misfit >= 0)
    fail_not_between(nodes, ids, first_misfit, first_fit >= 0 ? first_fit : first_not_corner_middle_corner,
                     first_fit >= 0, base, describe);
  check_node_roles(nodes.n_nodes(), ids, base, describe);
  return reorder;
}

}  // namespace mc
