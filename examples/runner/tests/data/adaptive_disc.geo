// adaptive_disc.geo - a small Hertz-like scene for the runner's adaptive refinement tests: the
// lower half of a disc of radius 1 centred at (0, 1), pressed on the block [-1.5, 1.5] x [-1, 0].
// Meshed coarse and uniform (size h, default 0.25): the runner refines it (adaptive_disc.json,
// adaptive_step_limit.json; examples/runner/tests/check_runner_adaptive.py).
DefineConstant[ h = {0.25, Name "Parameters/mesh size"} ];
Point(1) = {0, 0, 0, h};
Point(2) = {0, 1, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {-1, 1, 0, h};
Circle(1) = {1, 2, 3};
Line(2) = {3, 2};
Line(3) = {2, 4};
Circle(4) = {4, 2, 1};
Line(5) = {2, 1};
Curve Loop(1) = {1, 2, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {4, -5, 3};
Plane Surface(2) = {2};
Point(11) = {-1.5, -1, 0, h};
Point(12) = {1.5, -1, 0, h};
Point(13) = {1.5, 0, 0, h};
Point(14) = {-1.5, 0, 0, h};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Physical Surface("disc") = {1, 2};
Physical Surface("block") = {11};
Physical Curve("disc_contact") = {1, 4};
Physical Curve("disc_top") = {2, 3};
Physical Curve("disc_axis") = {5};
Physical Curve("block_contact") = {13};
Physical Curve("block_bottom") = {11};
