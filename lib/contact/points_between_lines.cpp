#include "contact/points_between_lines.hpp"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace mc {

namespace {

// Points per leaf box: enough that a box is not much smaller than the segments it is tested
// against, few enough that a leaf's points are tested at little cost.
constexpr int kLeafPoints = 8;

// Where f(y) = cross(y - p, n) can be over a box, as the leaf's test computes it: f is linear,
// so its extremes over the box are at corners; the range is widened by far more than the
// round-off of evaluating f anywhere in the box (a few units in the last place of the terms'
// magnitudes). `unknown`: not finite anywhere (overflow), so nothing can be skipped.
struct Range {
  double lo, hi;
  bool unknown;
};

Range range_over(Point lo, Point hi, Point p, Point n) {
  double least = 0, most = 0, size = 0;
  bool finite = true;  // (finite differences and magnitudes: every f finite, no NaN anywhere in the box)
  const Point corner[4] = {lo, {hi.x, lo.y}, {lo.x, hi.y}, hi};
  for (int c = 0; c < 4; ++c) {
    const Point d = minus(corner[c], p);
    const double f = cross(d, n), magnitude = std::fabs(d.x * n.y) + std::fabs(d.y * n.x);
    finite = finite && std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(magnitude);
    least = c == 0 ? f : std::min(least, f), most = c == 0 ? f : std::max(most, f);
    size = std::max(size, magnitude);
  }
  const double margin = 1e-12 * size;
  return {least - margin, most + margin, !finite};
}

}  // namespace

PointsBetweenLines::PointsBetweenLines(std::vector<Point> points) : points_(std::move(points)) {
  if (points_.empty()) return;
  boxes_.reserve(4 * (points_.size() / kLeafPoints) + 1);
  boxes_.emplace_back();
  fill(0, 0, int(points_.size()));
}

// Fills box `index` with points [begin, end), after its children (the two halves) if it has any.
void PointsBetweenLines::fill(int index, int begin, int end) {
  Box box{points_[begin], points_[begin], begin, end, -1};
  if (end - begin <= kLeafPoints) {
    for (int i = begin; i < end; ++i) {
      const Point y = points_[i];
      box.lo = {std::min(box.lo.x, y.x), std::min(box.lo.y, y.y)};
      box.hi = {std::max(box.hi.x, y.x), std::max(box.hi.y, y.y)};
    }
  } else {
    box.first_child = int(boxes_.size());  // the two children side by side: one index names both
    boxes_.emplace_back(), boxes_.emplace_back();
    const int middle = begin + (end - begin) / 2;
    fill(box.first_child, begin, middle);
    fill(box.first_child + 1, middle, end);
    const Box &left = boxes_[box.first_child], &right = boxes_[box.first_child + 1];
    box.lo = {std::min(left.lo.x, right.lo.x), std::min(left.lo.y, right.lo.y)};
    box.hi = {std::max(left.hi.x, right.hi.x), std::max(left.hi.y, right.hi.y)};
  }
  boxes_[index] = box;
}

void PointsBetweenLines::find(Point a, Point na, Point b, Point nb, std::vector<Point> &found) const {
  found.clear();
  if (boxes_.empty()) return;
  int stack[64], depth = 0;  // the tree halves its runs: depth below 32 for any int count
  stack[depth++] = 0;
  while (depth > 0) {
    const Box &box = boxes_[stack[--depth]];
    const Range fa = range_over(box.lo, box.hi, a, na), fb = range_over(box.lo, box.hi, b, nb);
    const bool may_hold = fa.unknown || fb.unknown || (fa.hi > 0 && fb.lo < 0) || (fa.lo < 0 && fb.hi > 0);
    if (!may_hold) continue;
    if (box.first_child >= 0) {
      stack[depth++] = box.first_child + 1, stack[depth++] = box.first_child;
      continue;
    }
    for (int i = box.begin; i < box.end; ++i) {
      const Point y = points_[i];
      const double f_a = cross(minus(y, a), na), f_b = cross(minus(y, b), nb);
      if (f_a == 0 || f_b == 0 || (f_a > 0) == (f_b > 0)) continue;
      found.push_back(y);
    }
  }
}

}  // namespace mc
