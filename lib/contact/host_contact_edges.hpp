// A host body's curved contact edges (mc_set_contact_curved on a host body): no cells to check
// them against, so their nodes' positions and roles are checked instead (docs/api.md, "3-node
// edges on host bodies"), and a surface given corner, middle, corner throughout (the order of
// Smith and Griffiths' 8-node quadrilateral's sides) is put in the library's order.
#pragma once
#include "bodies/mesh.hpp"
#include <functional>
#include <string>
#include <vector>

namespace mc {

// Where node m lies against the chord a -> b, in chord lengths: along it (0 at a, 1 at b; NaN if
// a and b coincide) and off it.
struct ChordPlace {
  double along, off;
};
ChordPlace place_on_chord(Point a, Point b, Point m);

// A middle node between its ends: projecting inside the chord's middle half, and off the chord
// by at most kMaxMiddleOffset chord lengths.
constexpr double kMaxMiddleOffset = 0.3;
bool lies_between_ends(ChordPlace p);

// ids: 3 per edge, 0-based, as given (end, end, middle) - or, if every edge's nodes lie as
// (corner, middle, corner) and none as (end, end, middle), reordered in place to (end, end,
// middle). Then checks that no node is the middle of two edges or both a middle and an end.
// describe(e): edge e as the caller gave it, for the messages (ids in base). Returns true if it
// reordered. Throws MC_ERROR_CONTACT naming the first edge at fault otherwise.
bool order_host_curved_edges(const Mesh &nodes, std::vector<int> &ids, int base,
                             const std::function<std::string(int)> &describe);

}  // namespace mc
