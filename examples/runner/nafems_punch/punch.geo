// punch.geo - NAFEMS R0094 (Konter, "Advanced Finite Element Contact Benchmarks", 2006),
// benchmark 2: a steel punch with rounded edges pressed on an aluminium foundation,
// axisymmetric (Code_Aster's validation case SSNA122). Units mm, MPa. The meridian: x = r, y = z.
//   body 1, "punch":      r <= 50, 200 <= z <= 300, the bottom edge rounded with radius 10
//                         (flat for r <= 40, then a quarter circle centred at (40, 210));
//   body 2, "foundation": r <= 100, 0 <= z <= 200.
// Meshed fine (size h) within 15 mm of the fillet's start (40, 200), growing to h_far.
//
//   gmsh -2 -format msh41 punch.geo -o punch.msh
//   gmsh -2 -setnumber h 0.25 -format msh41 punch.geo -o punch.msh   (a finer mesh)
//
// Physical groups (names used by punch.json):
//   punch, foundation          the two bodies
//   punch_contact              the punch's flat bottom and fillet (body 1's contact surface)
//   punch_top                  z = 300: the pressure of 100 MPa
//   foundation_contact         the foundation's top for r <= 70
//   foundation_bottom          z = 0: clamped
DefineConstant[
  h = {1.0, Name "Parameters/fine mesh size near the contact edge"},
  h_far = {8.0, Name "Parameters/mesh size far from it"}
];

// ---- body 1: the punch ----
Point(1) = {0, 200, 0};
Point(2) = {40, 200, 0};     // where the fillet starts
Point(3) = {40, 210, 0};     // the fillet's centre
Point(4) = {50, 210, 0};
Point(5) = {50, 300, 0};
Point(6) = {0, 300, 0};
Line(1) = {1, 2};            // the flat bottom
Circle(2) = {2, 3, 4};       // the fillet
Line(3) = {4, 5};
Line(4) = {5, 6};            // the top
Line(5) = {6, 1};            // the axis
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// ---- body 2: the foundation ----
Point(11) = {0, 0, 0};
Point(12) = {100, 0, 0};
Point(13) = {100, 200, 0};
Point(14) = {70, 200, 0};
Point(15) = {0, 200, 0};
Line(11) = {11, 12};         // the bottom
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};         // the top for r <= 70
Line(15) = {15, 11};         // the axis
Curve Loop(11) = {11, 12, 13, 14, 15};
Plane Surface(11) = {11};

Physical Surface("punch") = {1};
Physical Surface("foundation") = {11};
Physical Curve("punch_contact") = {1, 2};
Physical Curve("punch_top") = {4};
Physical Curve("foundation_contact") = {14};
Physical Curve("foundation_bottom") = {11};

// ---- mesh size: fine around the edge of the contact, coarse away from it ----
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = h_far;
Field[2].DistMin = 15;
Field[2].DistMax = 100;
Field[3] = Distance;         // the contact surfaces, at most 4 h everywhere along them
Field[3].CurvesList = {1, 14};
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = 4 * h;
Field[4].SizeMax = h_far;
Field[4].DistMin = 5;
Field[4].DistMax = 60;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
