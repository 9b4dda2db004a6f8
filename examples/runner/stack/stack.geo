// stack.geo - three blocks stacked on each other (docs/scene_format.md, "pairs"): the runner's
// example of a scene of more than two bodies, and its patch test (test runner_stack):
//   top     [0, 1] x [2, 3]   body 1, pressed with a uniform pressure p on its top
//   middle  [0, 1] x [1, 2]   body 2, held vertically by contact alone
//   bottom  [0, 1] x [0, 1]   body 3, on rollers (u_y = 0 at y = 0)
// Each block's bottom-left corner is held in x. The blocks touch along y = 2 and y = 1 and are
// meshed independently, at different sizes: their meshes do not match on the contact
// surfaces. Frictionless contact passes a uniform stress sigma_yy = -p through both
// interfaces, whatever the meshes: the contact pressure is p at every position of both pairs.
//
//   gmsh -2 -format msh41 stack.geo -o stack.msh
//
// Physical groups (names used by stack.json):
//   top, middle, bottom                         the three bodies (surfaces)
//   top_load                                    the top block's top: the pressure
//   top_bottom, middle_top                      pair 1: top (non-mortar) on middle (mortar)
//   middle_bottom, bottom_top                   pair 2: middle (non-mortar) on bottom (mortar)
//   top_corner, middle_corner, bottom_corner    each block's bottom-left corner: u_x = 0
//   bottom_base                                 y = 0: u_y = 0
DefineConstant[
  h_top = {0.23, Name "Parameters/mesh size of the top block"},
  h_middle = {0.17, Name "Parameters/mesh size of the middle block"},
  h_bottom = {0.29, Name "Parameters/mesh size of the bottom block"}
];
// The blocks touch: without this Gmsh's built-in kernel would merge their coincident corners
// into one point shared by two bodies.
Geometry.AutoCoherence = 0;

// Block k (1 top, 2 middle, 3 bottom) with bottom-left corner (0, 3 - k): points 10k+1..4,
// lines 10k+1..4 (bottom, right, top, left), surface k.
sizes[] = {h_top, h_middle, h_bottom};
For k In {1:3}
  y0 = 3 - k;
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

Physical Surface("top") = {1};
Physical Surface("middle") = {2};
Physical Surface("bottom") = {3};
Physical Curve("top_load") = {13};
Physical Curve("top_bottom") = {11};
Physical Curve("middle_top") = {23};
Physical Curve("middle_bottom") = {21};
Physical Curve("bottom_top") = {33};
Physical Curve("bottom_base") = {31};
Physical Point("top_corner") = {11};
Physical Point("middle_corner") = {21};
Physical Point("bottom_corner") = {31};
