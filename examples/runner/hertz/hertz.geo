// hertz.geo - the shared Hertz scene of the design notes (method.md, "Shared benchmark scenes"),
// the same geometry, materials and load as examples/scenes/hertz_scene.c:
//   body 1: the lower half-disc of radius R = 1 centred at (0, 1), touching the origin;
//   body 2: the block [-4, 4] x [-4, 0].
// Meshed fine (size h) within 0.25 of the contact point, growing linearly to h_far at
// distance 3. Both bodies are meshed independently: their meshes do not match on the contact.
//
//   gmsh -2 -format msh41 hertz.geo -o hertz.msh             (or -format msh22)
//   gmsh -2 -setnumber h 0.005 -format msh41 hertz.geo -o hertz.msh   (a finer mesh)
//
// Physical groups (names used by hertz.json):
//   disc, block            the two bodies (surfaces)
//   disc_contact           the disc's arc for |x| <= 0.5: body 1's candidate contact surface
//   block_contact          the block's top for |x| <= 1: body 2's candidate contact surface
//   disc_top               the disc's flat top y = 1: carries the load
//   disc_axis              the axis x = 0 inside the disc: u_x = 0 there (the disc is held
//                          vertically by contact alone)
//   block_bottom           y = -4: clamped
DefineConstant[
  h = {0.01, Name "Parameters/fine mesh size near the contact"},
  h_far = {0.5, Name "Parameters/mesh size far from the contact"}
];
R = 1;
x_c = 0.5;                          // end of the disc's contact surface
y_c = R - Sqrt(R * R - x_c * x_c);  // ... on the arc

// ---- body 1: the half-disc, split along its axis so that the axis is a mesh line ----
Point(1) = {0, 0, 0};       // the contact point
Point(2) = {0, R, 0};       // the centre
Point(3) = {R, R, 0};
Point(4) = {-R, R, 0};
Point(5) = {x_c, y_c, 0};
Point(6) = {-x_c, y_c, 0};
Circle(1) = {1, 2, 5};      // arcs, counter-clockwise around each quarter
Circle(2) = {5, 2, 3};
Line(3) = {3, 2};           // flat top, right half
Line(4) = {2, 1};           // the axis
Circle(5) = {4, 2, 6};
Circle(6) = {6, 2, 1};
Line(7) = {2, 4};           // flat top, left half
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -4, 7};
Plane Surface(2) = {2};

// ---- body 2: the block ----
Point(11) = {-4, -4, 0};
Point(12) = {4, -4, 0};
Point(13) = {4, 0, 0};
Point(14) = {1, 0, 0};
Point(15) = {-1, 0, 0};
Point(16) = {-4, 0, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};        // the top for |x| <= 1
Line(15) = {15, 16};
Line(16) = {16, 11};
Curve Loop(11) = {11, 12, 13, 14, 15, 16};
Plane Surface(11) = {11};

Physical Surface("disc") = {1, 2};
Physical Surface("block") = {11};
Physical Curve("disc_contact") = {1, 6};
Physical Curve("disc_top") = {3, 7};
Physical Curve("disc_axis") = {4};
Physical Curve("block_contact") = {14};
Physical Curve("block_bottom") = {11};

// ---- mesh size: fine around the contact point, coarse away from it ----
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.25;
Field[2].DistMax = 3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
