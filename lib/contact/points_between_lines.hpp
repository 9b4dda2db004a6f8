// The points of a set that lie strictly between two lines, each line through a point along a
// direction: the body-2 surface nodes that may project inside a body-1 segment (contact_geometry.cpp:
// those between the look lines at the segment's two ends). Testing every body-2 node against
// every body-1 segment cost O(n1 n2): 2.7 s of the 16001-node strips' geometry
// (docs/notes/contact-geometry-cost.md). Here the points sit in a tree of boxes over runs of
// consecutive points (given in surface order, so that a run is a short piece of the surface and
// its box small), and a box none of whose points can be between the lines is skipped whole.
// The answer is the same set as the test of every point: the points are tested as before, and a
// box is skipped only when the sign test cannot hold anywhere in it, round-off included.
// The lines are whole lines, not rays: a point behind a segment (across a ring) is found too.
#pragma once
#include "bodies/mesh.hpp"
#include <vector>

namespace mc {

class PointsBetweenLines {
public:
  explicit PointsBetweenLines(std::vector<Point> points);

  // The points y with f_a(y) = cross(y - a, na) and f_b(y) = cross(y - b, nb) nonzero and of
  // opposite signs, into `found` (cleared first; in the tree's order, not sorted).
  void find(Point a, Point na, Point b, Point nb, std::vector<Point> &found) const;

private:
  struct Box {
    Point lo{0, 0}, hi{0, 0};
    int begin = 0, end = 0; // its points: points_[begin, end)
    int first_child = -1;   // children first_child and first_child + 1, or -1: a leaf
  };
  std::vector<Point> points_;
  std::vector<Box> boxes_;  // boxes_[0]: the root, if any point
  void fill(int index, int begin, int end);
};

}  // namespace mc
