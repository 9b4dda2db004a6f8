// hertz_quadratic.geo - the Hertz scene of ../hertz/hertz.geo (the same geometry, physical
// groups and mesh-size field) for second-order cells. Mesh it with -order 2:
//
//   gmsh -2 -order 2 hertz_quadratic.geo -o hertz_quadratic.msh        6-node triangles (T6)
//   gmsh -2 -order 2 -string "Mesh.RecombineAll=1; Mesh.SubdivisionAlgorithm=1;" \
//        hertz_quadratic.geo -o hertz_quadratic.msh                     9-node quadrilaterals (Q9)
//   ... and "Mesh.SecondOrderIncomplete=1;" as well                     8-node quadrilaterals (Q8)
//
// Gmsh puts the mid-edge nodes of the disc's arc on the circle itself, so each 3-node line of
// the contact surface is a parabola through three points of the true circle. The boundaries
// come out as 3-node lines in the same physical groups as with -order 1, and hertz_quadratic.json
// names the same groups as ../hertz/hertz.json: the runner hands the library each edge by its
// two corner nodes and finds the rest itself.
//
// A coarser default than the linear scene's (h = 0.02 near the contact instead of 0.01):
// second-order cells are more accurate per node; -setnumber h 0.01 still overrides it.
DefineConstant[
  h = {0.02, Name "Parameters/fine mesh size near the contact"}
];
Include "../hertz/hertz.geo";
