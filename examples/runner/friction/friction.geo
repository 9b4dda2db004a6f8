// friction.geo - two blocks, one on the other, for the runner's friction example and its patch
// test (docs/scene_format.md, "friction"; test runner_friction):
//   upper  [0, 1] x [1, 2]   body 1 (non-mortar), held along x by friction alone
//   lower  [0, 1] x [0, 1]   body 2 (mortar), its base held
// The blocks touch along y = 1 and are meshed independently at different sizes: their meshes
// do not match on the contact surface. friction.json loads them into the uniform stress
// sigma_yy = -p, sigma_xy = tau, sigma_xx = 0 (tractions on every free side), exact on any mesh.
//
//   gmsh -2 -format msh41 friction.geo -o friction.msh
//
// Physical groups (names used by friction.json):
//   upper, lower                                the two bodies (surfaces)
//   upper_top, upper_left, upper_right          the upper block's loaded sides
//   upper_bottom, lower_top                     the contact surfaces
//   lower_left, lower_right                     the lower block's loaded sides
//   lower_base                                  y = 0: held
DefineConstant[
  h_upper = {0.23, Name "Parameters/mesh size of the upper block"},
  h_lower = {0.29, Name "Parameters/mesh size of the lower block"}
];
// The blocks touch: without this Gmsh's built-in kernel would merge their coincident corners
// into one point shared by two bodies.
Geometry.AutoCoherence = 0;

// Block k (1 upper, 2 lower) with bottom-left corner (0, 2 - k): points 10k+1..4, lines
// 10k+1..4 (bottom, right, top, left), surface k.
sizes[] = {h_upper, h_lower};
For k In {1:2}
  y0 = 2 - k;
  hk = sizes[k - 1];
  Point(10 * k + 1) = {0, y0, 0, hk};
  Point(10 * k + 2) = {1, y0, 0, hk};
  Point(10 * k + 3) = {1, y0 + 1, 0, hk};
  Point(10 * k + 4) = {0, y0 + 1, 0, hk};
  Line(10 * k + 1) = {10 * k + 1, 10 * k + 2};
  Line(10 * k + 2) = {10 * k + 2, 10 * k + 3};
  Line(10 * k + 3) = {10 * k + 3, 10 * k + 4};
  Line(10 * k + 4) = {10 * k + 4, 10 * k + 1};
  Curve Loop(k) = {10 * k + 1, 10 * k + 2, 10 * k + 3, 10 * k + 4};
  Plane Surface(k) = {k};
EndFor

Physical Surface("upper") = {1};
Physical Surface("lower") = {2};
Physical Curve("upper_bottom") = {11};
Physical Curve("upper_right") = {12};
Physical Curve("upper_top") = {13};
Physical Curve("upper_left") = {14};
Physical Curve("lower_base") = {21};
Physical Curve("lower_right") = {22};
Physical Curve("lower_top") = {23};
Physical Curve("lower_left") = {24};
