// Small vector arithmetic on points of the plane, shared by the contact surfaces, the contact
// geometry and the C layer's checks of contact chains.
#pragma once
#include "bodies/mesh.hpp"
#include <cmath>

namespace mc {

inline double cross(Point u, Point v) { return u.x * v.y - u.y * v.x; }
inline double dot(Point u, Point v) { return u.x * v.x + u.y * v.y; }
inline Point minus(Point u, Point v) { return {u.x - v.x, u.y - v.y}; }
inline Point plus(Point u, Point v) { return {u.x + v.x, u.y + v.y}; }
inline Point scaled(Point u, double s) { return {s * u.x, s * u.y}; }
inline Point lerp(Point u, Point v, double s) { return {u.x + s * (v.x - u.x), u.y + s * (v.y - u.y)}; }
inline double norm(Point u) { return std::hypot(u.x, u.y); }
inline Point unit(Point u) { return scaled(u, 1 / norm(u)); }
// Outward normal of an edge a->b with the body on its left.
inline Point edge_normal(Point a, Point b) { return unit({b.y - a.y, a.x - b.x}); }
// Signed angle (radians) by which the direction of travel turns at b on the path a -> b -> c.
inline double turn_angle(Point a, Point b, Point c) {
  const Point d1 = minus(b, a), d2 = minus(c, b);
  return std::atan2(cross(d1, d2), dot(d1, d2));
}

}  // namespace mc
