// cylinders.geo - two cylinders in contact, R = 1 on R = 3 (plane strain), the scene of
// bench/cylinders_layout.c meshed by Gmsh for the scene runner (cylinders_adaptive.json):
//   body 1: the part |x| <= 0.6, y <= 0.6 of the disc of radius 1 centred at (0, 1) (its arc
//           touches the origin);
//   body 2: the part |x| <= 1.5, y >= -1.5 of the disc of radius 3 centred at (0, -3).
// Meshed fine (size h) within 0.1 of the contact point, growing linearly to h_far at distance
// 1. Both bodies are meshed independently: their meshes do not match on the contact.
//
//   gmsh -2 -format msh41 cylinders.geo -o cylinders.msh
//   gmsh -2 -setnumber h 0.005 -setnumber h_far 0.05 -format msh41 cylinders.geo -o cylinders.msh
//
// Physical groups (names used by cylinders_adaptive.json):
//   small, large           the two bodies (surfaces)
//   small_contact          body 1's arc for |x| <= 0.4: its candidate contact surface
//   large_contact          body 2's arc for |x| <= 0.8: its candidate contact surface
//   small_top              body 1's flat top y = 0.6: carries the load
//   small_axis             the axis x = 0 inside body 1: u_x = 0 there (body 1 is held
//                          vertically by contact alone)
//   large_bottom           y = -1.5: clamped
DefineConstant[
  h = {0.02, Name "Parameters/fine mesh size near the contact"},
  h_far = {0.2, Name "Parameters/mesh size far from the contact"}
];
R1 = 1;     // body 1: centre (0, R1)
R2 = 3;     // body 2: centre (0, -R2)
w1 = 0.6;   // body 1: |x| <= w1, y <= top1
top1 = 0.6;
w2 = 1.5;   // body 2: |x| <= w2, y >= -bottom2
bottom2 = 1.5;
x1c = 0.4;  // end of body 1's contact surface
x2c = 0.8;  // end of body 2's contact surface
y1e = R1 - Sqrt(R1 * R1 - w1 * w1);
y1c = R1 - Sqrt(R1 * R1 - x1c * x1c);
y2e = -R2 + Sqrt(R2 * R2 - w2 * w2);
y2c = -R2 + Sqrt(R2 * R2 - x2c * x2c);

// ---- body 1, split along its axis so that the axis is a mesh line ----
Point(1) = {0, 0, 0};        // the contact point
Point(2) = {0, R1, 0};       // the centre (off the body)
Point(3) = {x1c, y1c, 0};
Point(4) = {w1, y1e, 0};
Point(5) = {w1, top1, 0};
Point(6) = {0, top1, 0};
Point(7) = {-w1, top1, 0};
Point(8) = {-w1, y1e, 0};
Point(9) = {-x1c, y1c, 0};
Circle(1) = {1, 2, 3};
Circle(2) = {3, 2, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};            // flat top, right half
Line(5) = {6, 1};            // the axis
Line(6) = {6, 7};            // flat top, left half
Line(7) = {7, 8};
Circle(8) = {8, 2, 9};
Circle(9) = {9, 2, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {-5, 6, 7, 8, 9};
Plane Surface(2) = {2};

// ---- body 2 ----
Point(11) = {0, -R2, 0};     // the centre (off the body)
Point(12) = {-w2, -bottom2, 0};
Point(13) = {w2, -bottom2, 0};
Point(14) = {w2, y2e, 0};
Point(15) = {x2c, y2c, 0};
Point(16) = {0, 0, 0};
Point(17) = {-x2c, y2c, 0};
Point(18) = {-w2, y2e, 0};
Line(11) = {12, 13};
Line(12) = {13, 14};
Circle(13) = {14, 11, 15};
Circle(14) = {15, 11, 16};
Circle(15) = {16, 11, 17};
Circle(16) = {17, 11, 18};
Line(17) = {18, 12};
Curve Loop(11) = {11, 12, 13, 14, 15, 16, 17};
Plane Surface(11) = {11};

Physical Surface("small") = {1, 2};
Physical Surface("large") = {11};
Physical Curve("small_contact") = {1, 9};
Physical Curve("small_top") = {4, 6};
Physical Curve("small_axis") = {5};
Physical Curve("large_contact") = {14, 15};
Physical Curve("large_bottom") = {11};

// ---- mesh size: fine around the contact point, coarse away from it ----
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.1;
Field[2].DistMax = 1;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
