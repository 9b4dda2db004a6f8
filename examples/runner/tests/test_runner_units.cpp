// test_runner_units.cpp - unit tests of mortarcontact-run's parts (Check):
// - the Gmsh reader on the hand-written tiny_v22.msh / tiny_v41.msh (the same mesh in both
//   formats, with sparse node tags, a clockwise triangle and quadrilateral, a reversed line and
//   lines in two groups) and on malformed texts: each error names the file and the line;
// - body extraction: compact numbering, counter-clockwise cells, boundary edges oriented with
//   the body on their left, groups split between the two bodies;
// - scene validation: unknown, duplicated and missing keys, wrong types and ranges, each
//   message naming the key;
// - the runner end to end on the tiny meshes: the contact patch test (a uniform pressure
//   reaches the non-matching contact surface exactly) in both formats, identical results; an
//   interference fit (prescribed displacement + gap offset) with its exact pressure; the patch
//   test with solver.interface_solver forced to each path, which the runner reports;
// - second-order meshes (tiny_quadratic_v22.msh / _v41.msh, 6-node triangles and 9-node
//   quadrilaterals, 3-node lines): both formats alike, clockwise cells reversed with their
//   mid-edge nodes, edges handed over as corner pairs, supports with the mid-edge nodes, a
//   clamped solve without contact exact, linear and quadratic mixed refused with a clear message,
//   and the runner's patch test on them (exact pressure at the mid-edge node too, VTK types 22, 28)
//   and interference fit (exact only with the mid-edge nodes in the support and the gap offset);
// - adaptive refinement's parts: the scene's "adaptive" object (defaults, every key checked), the
//   size field's equidistribution rule and its limits, the Gmsh view with its skirt, the .geo of a
//   step, and an array added to a VTU file (the loop itself: check_runner_adaptive.py).
//
// usage: test_runner_units DATA_DIR RUNNER   (DATA_DIR: a copy of examples/runner/tests/data)
#include "adaptive.hpp"
#include "body_mesh.hpp"
#include "gmsh_reader.hpp"
#include "scene.hpp"

#include "mortarcontact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <check.h>  // last: it defines a macro fail() that clashes with std::ios::fail

using namespace mcrun;

namespace {

std::string data_dir;
std::string runner;

GmshMesh tiny(const char *version) { return read_gmsh(data_dir + "/tiny_v" + version + ".msh"); }

// The message of the exception `f` throws, "" if it throws none.
template <class E>
std::string error_of(const std::function<void()> &f) {
  try {
    f();
  } catch (const E &e) {
    return e.what();
  }
  return "";
}

#define ASSERT_HAS(text, piece) \
  ck_assert_msg(std::string(text).find(piece) != std::string::npos, "'%s' does not contain '%s'", \
                std::string(text).c_str(), std::string(piece).c_str())

double twice_area(const BodyMesh &m, int c) {
  double sum = 0;
  const int n = m.nodes_per_cell;
  for (int k = 0; k < n; ++k) {
    int a = m.cells[size_t(c * n + k)], b = m.cells[size_t(c * n + (k + 1) % n)];
    sum += m.xy[2 * size_t(a)] * m.xy[2 * size_t(b) + 1] - m.xy[2 * size_t(b)] * m.xy[2 * size_t(a) + 1];
  }
  return sum;
}

// ---- the reader ----------------------------------------------------------------------------

START_TEST(both_formats_read_the_same_mesh) {
  const GmshMesh v2 = tiny("22"), v4 = tiny("41");
  ck_assert_str_eq(v2.version.c_str(), "2.2");
  ck_assert_str_eq(v4.version.c_str(), "4.1");
  ck_assert_int_eq(v2.node_tags.size(), 14);
  ck_assert_msg(v2.node_tags == v4.node_tags, "node tags differ");
  ck_assert_msg(v2.xy == v4.xy, "coordinates differ");
  ck_assert_int_eq(v2.node_tags[6], 201);
  ck_assert_double_eq(v2.xy[2 * 7], 0.3333333333333333);
  // 2.2 writes the lines of two groups twice: merged, both formats have 20 elements
  ck_assert_int_eq(v2.elements.size(), 20);
  ck_assert_int_eq(v4.elements.size(), 20);
  for (size_t e = 0; e < v2.elements.size(); ++e) {
    ck_assert_int_eq(v2.elements[e].dim, v4.elements[e].dim);
    ck_assert_msg(v2.elements[e].nodes == v4.elements[e].nodes, "element %zu nodes differ", e);
    std::vector<int> p2 = v2.elements[e].physical_tags, p4 = v4.elements[e].physical_tags;
    std::sort(p2.begin(), p2.end());
    std::sort(p4.begin(), p4.end());
    ck_assert_msg(p2 == p4, "element %zu groups differ", e);
  }
  ck_assert_int_eq(v2.groups.size(), 10);
  ck_assert_int_eq(v4.groups_named("upper corner").size(), 1);  // a name with a space
  ck_assert_int_eq(v4.groups_named("upper corner")[0]->dim, 0);
  ck_assert_int_eq(v2.elements[1].physical_tags.size(), 2);  // upper_bottom and interface
}
END_TEST

START_TEST(body_nodes_compact_cells_counter_clockwise) {
  for (const char *version : {"22", "41"}) {
    const GmshMesh file = tiny(version);
    const BodyMesh upper = extract_body(file, "upper", 1), lower = extract_body(file, "lower", 2);
    ck_assert_int_eq(upper.n_nodes(), 6);
    ck_assert_int_eq(upper.n_cells(), 4);
    ck_assert_int_eq(upper.nodes_per_cell, 3);
    ck_assert_int_eq(lower.n_nodes(), 8);
    ck_assert_int_eq(lower.n_cells(), 3);
    ck_assert_int_eq(lower.nodes_per_cell, 4);
    // file order kept: upper = 101..106 -> 0..5, lower = 201..208 -> 0..7
    for (int i = 0; i < 6; ++i) ck_assert_int_eq(upper.node_tags[size_t(i)], 101 + i);
    for (int i = 0; i < 8; ++i) ck_assert_int_eq(lower.node_tags[size_t(i)], 201 + i);
    ck_assert_double_eq(lower.xy[2 * 5], std::strtod("0.3333333333333333", nullptr));  // as written
    // every cell counter-clockwise, with its own area (1/4 per triangle, 1/3 per quad)
    for (int c = 0; c < 4; ++c) ck_assert_double_eq_tol(twice_area(upper, c), 0.5, 1e-15);
    for (int c = 0; c < 3; ++c) ck_assert_double_eq_tol(twice_area(lower, c), 2.0 / 3.0, 1e-15);
    // the clockwise ones were reversed, the others kept as written
    const std::vector<int> reversed_triangle(upper.cells.begin() + 9, upper.cells.begin() + 12);
    const std::vector<int> kept_triangle(upper.cells.begin(), upper.cells.begin() + 3);
    const std::vector<int> reversed_quad(lower.cells.begin() + 4, lower.cells.begin() + 8);
    ck_assert_msg(reversed_triangle == std::vector<int>({1, 5, 4}), "clockwise triangle 102 105 106 not reversed");
    ck_assert_msg(kept_triangle == std::vector<int>({0, 1, 4}), "triangle 101 102 105 changed");
    ck_assert_msg(reversed_quad == std::vector<int>({1, 2, 6, 5}), "clockwise quad 202 206 207 203 not reversed");
    // the library accepts both (it rejects clockwise cells)
    mc_model *m = nullptr;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    ck_assert_int_eq(mc_set_mesh(m, 1, upper.n_nodes(), upper.xy.data(), upper.n_cells(), 3, upper.cells.data()), MC_OK);
    ck_assert_int_eq(mc_set_mesh(m, 2, lower.n_nodes(), lower.xy.data(), lower.n_cells(), 4, lower.cells.data()), MC_OK);
    mc_destroy(m);
  }
}
END_TEST

START_TEST(group_edges_oriented_body_on_the_left) {
  for (const char *version : {"22", "41"}) {
    const GmshMesh file = tiny(version);
    const BodyMesh upper = extract_body(file, "upper", 1), lower = extract_body(file, "lower", 2);
    // top of the upper body: right to left (106->105 as written, 104->105 reversed)
    ck_assert_msg(group_edges(upper, "upper_top") == std::vector<int>({5, 4, 4, 3}), "upper_top");
    // 'interface' holds lines of both bodies: each body takes its own, oriented as its cells
    ck_assert_msg(group_edges(upper, "interface") == std::vector<int>({0, 1, 1, 2}), "interface on upper");
    ck_assert_msg(group_edges(lower, "interface") == std::vector<int>({7, 6, 6, 5, 5, 4}), "interface on lower");
    ck_assert_msg(group_edges(lower, "lower_left") == std::vector<int>({4, 0}), "lower_left");
    ck_assert_msg(group_nodes(upper, "upper corner") == std::vector<int>({0}), "point group");
    ck_assert_msg(group_nodes(lower, "lower_top") == std::vector<int>({4, 5, 6, 7}), "line group nodes");
    ASSERT_HAS(error_of<MeshError>([&] { group_nodes(lower, "upper corner"); }), "has no node on body 2");
    ASSERT_HAS(error_of<MeshError>([&] { group_edges(lower, "upper_top"); }), "has no line on body 2");
    const std::string missing = error_of<MeshError>([&] { group_edges(upper, "top"); });
    ASSERT_HAS(missing, "no physical group named 'top'");
    ASSERT_HAS(missing, "'upper_top' (dim 1)");
    ASSERT_HAS(error_of<MeshError>([&] { group_edges(upper, "upper"); }), "has dimension 2, but edges need a line group");
  }
}
END_TEST

START_TEST(body_errors_name_element_and_line) {
  const GmshMesh file = tiny("41");
  // without a domain the file's triangles and quadrilaterals would make one body
  const std::string mixed = error_of<MeshError>([&] { extract_body(file, "", 1); });
  ASSERT_HAS(mixed, "tiny_v41.msh:");
  ASSERT_HAS(mixed, "a body takes one cell type");
  ASSERT_HAS(error_of<MeshError>([&] { extract_body(file, "upper_top", 1); }), "must be a surface group");
  ASSERT_HAS(error_of<MeshError>([&] { extract_body(file, "uper", 1); }), "no physical group named 'uper'");

  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n$EndNodes\n";
  const GmshMesh flat = parse_gmsh(head + "$Elements\n2\n7 2 0 1 2 4\n8 2 0 1 2 3\n$EndElements\n", "flat.msh");
  ASSERT_HAS(error_of<MeshError>([&] { extract_body(flat, "", 1); }), "flat.msh:14: element 8 is a degenerate cell");
  // a line between two cells is no boundary: no load or contact on it
  const GmshMesh inner = parse_gmsh(
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 5 \"diagonal\"\n$EndPhysicalNames\n"
      "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
      "$Elements\n3\n1 2 0 1 2 3\n2 2 0 1 3 4\n3 1 2 5 1 1 3\n$EndElements\n",
      "inner.msh");
  const BodyMesh square = extract_body(inner, "", 1);
  ASSERT_HAS(error_of<MeshError>([&] { group_edges(square, "diagonal"); }), "inner.msh:19: element 3");
  ASSERT_HAS(error_of<MeshError>([&] { group_edges(square, "diagonal"); }), "need boundary edges");
  ck_assert_msg(group_nodes(square, "diagonal") == std::vector<int>({0, 2}), "supports may use inner lines");
}
END_TEST

// Each malformed text gives a MeshError starting "bad.msh:<line>: " and containing `piece`.
void expect_mesh_error(const std::string &text, int line, const std::string &piece) {
  const std::string message = error_of<MeshError>([&] { parse_gmsh(text, "bad.msh"); });
  ASSERT_HAS(message, "bad.msh:" + std::to_string(line) + ": ");
  ASSERT_HAS(message, piece);
}

START_TEST(malformed_files_name_file_and_line) {
  const std::string format = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n";  // lines 4-9
  expect_mesh_error("", 1, "empty file");
  expect_mesh_error("hello\n", 1, "not a Gmsh mesh file");
  expect_mesh_error("$MeshFormat\n2.2 1 8\n$EndMeshFormat\n", 1, "binary .msh files are not supported");
  expect_mesh_error("$MeshFormat\n4 0 8\n$EndMeshFormat\n", 2, "format version 4 is not supported");
  expect_mesh_error(format + "$Nodes\n3\n1 0 0 0\n2 1 x 0\n", 7, "expected a finite number (a node's y), found 'x'");
  expect_mesh_error(format + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n", 8, "unexpected end of file");
  expect_mesh_error(format + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$Elements\n", 9, "expected $EndNodes, found '$Elements'");
  expect_mesh_error(format + "$Nodes\n2\n1 0 0 0\n2 1 0 0\n1 0 1 0\n$EndNodes\n", 8, "expected $EndNodes");
  expect_mesh_error(format + "$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n", 7, "node 1 is defined twice");
  expect_mesh_error(format + "$Nodes\n2\n1 0 0 0\n2 1 0 0.5\n$EndNodes\n", 7, "plane z = 0");
  expect_mesh_error(format + nodes + "$Elements\n1\n1 2 2 1 1 1 2 4\n$EndElements\n", 12,
                    "element 1 refers to node 4, which $Nodes does not define");
  expect_mesh_error(format + nodes + "$Elements\n1\n1 21 2 1 1 1 2 3 1 2 3 1 2 3 1\n$EndElements\n", 12,
                    "10-node triangle, order 3 or more, or incomplete) is not supported");
  expect_mesh_error(format + nodes + "$Elements\n1\n1 4 2 1 1 1 2 3 1\n$EndElements\n", 12, "3D) is not supported");
  expect_mesh_error(format + "$Elements\n0\n$EndElements\n", 4, "$Elements before $Nodes");
  expect_mesh_error(format + nodes, 10, "no $Elements section");
  expect_mesh_error(format + "$PhysicalNames\n1\n1 2 \"open\n$EndPhysicalNames\n", 6, "unterminated quoted name");
  // 4.1: counts that do not add up, an unknown entity, an element of the wrong dimension
  const std::string v4 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n";
  const std::string v4_nodes = "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n";  // lines 8-17
  expect_mesh_error(v4 + "$Nodes\n1 4 1 4\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n", 16,
                    "$Nodes announces 4 nodes but its blocks hold 3");
  expect_mesh_error(v4 + v4_nodes + "$Elements\n1 1 1 1\n2 9 2 1\n1 1 2 3\n$EndElements\n", 20,
                    "entity (dimension 2, tag 9) that $Entities does not list");
  expect_mesh_error(v4 + v4_nodes + "$Elements\n1 1 1 1\n1 1 2 1\n1 1 2 3\n$EndElements\n", 20,
                    "element type 2 has dimension 2 but its block's entity has dimension 1");
  // and the well-formed 4.1 text: its triangle is in group 7 through its entity
  const GmshMesh good = parse_gmsh(v4 + v4_nodes + "$Elements\n1 1 1 1\n2 1 2 1\n5 1 2 3\n$EndElements\n", "good.msh");
  ck_assert_int_eq(good.elements.size(), 1);
  ck_assert_int_eq(good.elements[0].physical_tags.size(), 1);
  ck_assert_int_eq(good.elements[0].physical_tags[0], 7);
  ck_assert_int_eq(good.elements[0].tag, 5);
  ck_assert_int_eq(good.elements[0].line, 21);
  ASSERT_HAS(error_of<MeshError>([] { read_gmsh("/nonexistent/x.msh"); }), "/nonexistent/x.msh: cannot open");
}
END_TEST

// ---- second-order meshes -------------------------------------------------------------------
// tiny_quadratic_v22.msh / tiny_quadratic_v41.msh: the same second-order mesh in both formats,
// node tags 101-109 (upper, written out of order: corners first) and 201-215 (lower), i.e.
// not contiguous; element tags sparse in 4.1. Upper = [0,1]^2 as two 6-node triangles (the
// second written clockwise), lower = [0,1] x [-1,0] as two 9-node quadrilaterals (the second
// clockwise); 3-node lines on the boundary, some written against their cell's direction.

GmshMesh tiny_quadratic(const char *version) { return read_gmsh(data_dir + "/tiny_quadratic_v" + version + ".msh"); }

// Twice the signed area of cell c's corner polygon.
double twice_corner_area(const BodyMesh &m, int c) {
  double sum = 0;
  const int n = m.nodes_per_cell, corners = m.corners_per_cell();
  for (int k = 0; k < corners; ++k) {
    int a = m.cells[size_t(c * n + k)], b = m.cells[size_t(c * n + (k + 1) % corners)];
    sum += m.xy[2 * size_t(a)] * m.xy[2 * size_t(b) + 1] - m.xy[2 * size_t(b)] * m.xy[2 * size_t(a) + 1];
  }
  return sum;
}

// Every mid-edge node of cell c lies midway between its side's corners (the tiny meshes are
// straight-sided), and a 9-node quad's centre at the mean of its corners: the node order is right.
void check_mid_nodes(const BodyMesh &m, int c) {
  const int n = m.nodes_per_cell, corners = m.corners_per_cell();
  const int *v = &m.cells[size_t(c * n)];
  auto x = [&](int node, int d) { return m.xy[2 * size_t(node) + size_t(d)]; };
  for (int k = 0; k < corners; ++k)
    for (int d = 0; d < 2; ++d)
      ck_assert_msg(std::fabs(x(v[corners + k], d) - 0.5 * (x(v[k], d) + x(v[(k + 1) % corners], d))) < 1e-15,
                    "cell %d: node %d is not the middle of side %d", c, corners + k, k);
  if (n == 9)
    for (int d = 0; d < 2; ++d)
      ck_assert_double_eq_tol(x(v[8], d), 0.25 * (x(v[0], d) + x(v[1], d) + x(v[2], d) + x(v[3], d)), 1e-15);
}

START_TEST(second_order_both_formats_read_the_same_mesh) {
  const GmshMesh v2 = tiny_quadratic("22"), v4 = tiny_quadratic("41");
  ck_assert_int_eq(v2.node_tags.size(), 24);
  ck_assert_msg(v2.node_tags == v4.node_tags, "node tags differ");
  ck_assert_msg(v2.xy == v4.xy, "coordinates differ");
  ck_assert_int_eq(v4.node_tags[1], 103);  // as written, not sorted
  ck_assert_int_eq(v4.node_tags[9], 201);
  // 2.2 writes the lines of two groups twice: merged, both formats have 13 elements
  ck_assert_int_eq(v2.elements.size(), 13);
  ck_assert_int_eq(v4.elements.size(), 13);
  const size_t sizes[13] = {1, 3, 3, 3, 3, 3, 3, 3, 3, 6, 6, 9, 9};
  for (size_t e = 0; e < 13; ++e) {
    ck_assert_int_eq(v2.elements[e].nodes.size(), sizes[e]);
    ck_assert_int_eq(v2.elements[e].dim, v4.elements[e].dim);
    ck_assert_msg(v2.elements[e].nodes == v4.elements[e].nodes, "element %zu nodes differ", e);
    std::vector<int> p2 = v2.elements[e].physical_tags, p4 = v4.elements[e].physical_tags;
    std::sort(p2.begin(), p2.end());
    std::sort(p4.begin(), p4.end());
    ck_assert_msg(p2 == p4, "element %zu groups differ", e);
  }
  ck_assert_int_eq(v4.elements[12].tag, 37);
  ck_assert_int_eq(v4.elements[1].physical_tags.size(), 2);  // upper_bottom and interface
}
END_TEST

START_TEST(second_order_body_cells_edges_and_supports) {
  for (const char *version : {"22", "41"}) {
    const GmshMesh file = tiny_quadratic(version);
    const BodyMesh upper = extract_body(file, "upper", 1), lower = extract_body(file, "lower", 2);
    ck_assert_int_eq(upper.nodes_per_cell, 6);
    ck_assert_int_eq(lower.nodes_per_cell, 9);
    ck_assert_int_eq(upper.n_nodes(), 9);
    ck_assert_int_eq(lower.n_nodes(), 15);
    ck_assert_int_eq(upper.n_cells(), 2);
    ck_assert_int_eq(lower.n_cells(), 2);
    // file order kept: 101 103 109 107 102 106 108 104 105 -> 0..8
    const long upper_tags[9] = {101, 103, 109, 107, 102, 106, 108, 104, 105};
    for (int i = 0; i < 9; ++i) ck_assert_int_eq(upper.node_tags[size_t(i)], upper_tags[i]);
    for (int c = 0; c < 2; ++c) {
      ck_assert_double_eq_tol(twice_corner_area(upper, c), 1.0, 1e-15);
      ck_assert_double_eq_tol(twice_corner_area(lower, c), 1.0, 1e-15);
      check_mid_nodes(upper, c);
      check_mid_nodes(lower, c);
    }
    // the clockwise cells were reversed: corners after the first, mid-edge nodes reversed,
    // the centre kept; the others as written
    ck_assert_msg(std::vector<int>(upper.cells.begin(), upper.cells.begin() + 6) == std::vector<int>({0, 1, 2, 4, 5, 8}),
                  "counter-clockwise T6 changed");
    ck_assert_msg(std::vector<int>(upper.cells.begin() + 6, upper.cells.end()) == std::vector<int>({0, 2, 3, 8, 6, 7}),
                  "clockwise T6 101 107 109 104 108 105 not reversed right");
    ck_assert_msg(std::vector<int>(lower.cells.begin() + 9, lower.cells.end()) ==
                      std::vector<int>({2, 4, 14, 12, 3, 9, 13, 7, 8}),
                  "clockwise Q9 not reversed right");
    // edges: the two corners, oriented as the cell; mid-edge nodes on request
    std::vector<int> mids;
    ck_assert_msg(group_edges(upper, "upper_top", &mids) == std::vector<int>({2, 3}), "upper_top");
    ck_assert_msg(mids == std::vector<int>({6}), "upper_top's mid-edge node");
    ck_assert_msg(group_edges(upper, "upper_left") == std::vector<int>({3, 0}), "upper_left");
    ck_assert_msg(group_edges(upper, "interface", &mids) == std::vector<int>({0, 1}), "interface on upper");
    ck_assert_msg(mids == std::vector<int>({4}), "interface mid on upper");
    ck_assert_msg(group_edges(lower, "interface", &mids) == std::vector<int>({14, 12, 12, 10}), "interface on lower");
    ck_assert_msg(mids == std::vector<int>({13, 11}), "interface mids on lower");
    ck_assert_msg(group_edges(lower, "lower_left") == std::vector<int>({10, 0}), "lower_left");
    // supports take every node of their lines, the mid-edge nodes too
    ck_assert_msg(group_nodes(upper, "upper_left") == std::vector<int>({0, 3, 7}), "upper_left nodes");
    ck_assert_msg(group_nodes(lower, "lower_top") == std::vector<int>({10, 11, 12, 13, 14}), "lower_top nodes");
    ck_assert_msg(group_nodes(lower, "lower_bottom") == std::vector<int>({0, 1, 2, 3, 4}), "lower_bottom nodes");
    ck_assert_msg(group_nodes(upper, "upper corner") == std::vector<int>({0}), "point group");

    // the library takes the cells and the corner-pair edges, and a clamped block under a
    // uniform pressure (no contact) comes out with its exact uniform stress
    mc_model *m = nullptr;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    ck_assert_int_eq(mc_set_mesh(m, 1, upper.n_nodes(), upper.xy.data(), upper.n_cells(), 6, upper.cells.data()), MC_OK);
    ck_assert_int_eq(mc_set_mesh(m, 2, lower.n_nodes(), lower.xy.data(), lower.n_cells(), 9, lower.cells.data()), MC_OK);
    for (int b = 1; b <= 2; ++b) {
      const BodyMesh &body = b == 1 ? upper : lower;
      ck_assert_int_eq(mc_set_material(m, b, 2.0, 0.3), MC_OK);
      const std::vector<int> x = group_nodes(body, b == 1 ? "upper_left" : "lower_left");
      const std::vector<int> y = group_nodes(body, b == 1 ? "upper_bottom" : "lower_bottom");
      ck_assert_int_eq(mc_fix(m, b, int(x.size()), x.data(), MC_X, nullptr), MC_OK);
      ck_assert_int_eq(mc_fix(m, b, int(y.size()), y.data(), MC_Y, nullptr), MC_OK);
      const std::vector<int> top = group_edges(body, b == 1 ? "upper_top" : "interface");
      const std::vector<double> p(top.size() / 2, 0.25);
      ck_assert_int_eq(mc_add_pressure(m, b, int(p.size()), top.data(), p.data()), MC_OK);
    }
    ck_assert_int_eq(mc_solve(m), MC_OK);
    for (int b = 1; b <= 2; ++b) {
      const BodyMesh &body = b == 1 ? upper : lower;
      std::vector<double> sigma(4 * size_t(body.n_nodes()));
      ck_assert_int_eq(mc_get_nodal_stress(m, b, sigma.data()), MC_OK);
      for (int i = 0; i < body.n_nodes(); ++i) {
        ck_assert_msg(std::fabs(sigma[4 * size_t(i) + 1] + 0.25) < 1e-12, "body %d node %d: sigma_yy %.17g", b, i,
                      sigma[4 * size_t(i) + 1]);
        ck_assert_msg(std::fabs(sigma[4 * size_t(i)]) < 1e-12, "body %d node %d: sigma_xx %.17g", b, i, sigma[4 * size_t(i)]);
      }
    }
    mc_destroy(m);
  }
}
END_TEST

START_TEST(second_order_errors_name_element_and_line) {
  // a square of four nodes plus mid-edge nodes: 1-4 corners, 5 (0.5,0) 6 (1,0.5) 7 (0.5,1)
  // 8 (0,0.5) 9 (0.5,0.5) the diagonal's middle, 10 (0.5,0.5) the centre
  const std::string head =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 5 \"bottom\"\n$EndPhysicalNames\n"
      "$Nodes\n10\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0 0\n6 1 0.5 0\n7 0.5 1 0\n8 0 0.5 0\n9 0.5 0.5 0\n"
      "10 0.5 0.5 0\n$EndNodes\n";  // lines 1-20
  auto body_error = [&](const std::string &elements) {
    return error_of<MeshError>([&] { extract_body(parse_gmsh(head + elements, "q.msh"), "", 1); });
  };
  // a 6-node and a 3-node triangle in one body
  std::string e = body_error("$Elements\n2\n1 9 0 1 2 3 5 6 9\n2 2 0 1 3 4\n$EndElements\n");
  ASSERT_HAS(e, "q.msh:24: element 2 is a 3-node triangle (first order) but element 1 (line 23) is a 6-node triangle "
                "(second order): a body takes one cell type, all first order or all second order");
  // an 8- and a 9-node quadrilateral (the same square twice: the reader keeps both)
  e = body_error("$Elements\n2\n1 16 0 1 2 3 4 5 6 7 8\n2 10 0 1 2 3 4 5 6 7 8 10\n$EndElements\n");
  ASSERT_HAS(e, "element 2 is a 9-node quadrilateral (second order) but element 1 (line 23) is an 8-node quadrilateral");
  ASSERT_HAS(e, "Mesh.SecondOrderIncomplete");
  // a Q8 body: read, and its 3-node line is a corner pair with its middle
  const GmshMesh q8 = parse_gmsh(head + "$Elements\n2\n1 16 0 1 2 3 4 5 6 7 8\n2 8 2 5 5 2 1 5\n$EndElements\n", "q8.msh");
  const BodyMesh square = extract_body(q8, "", 1);
  ck_assert_int_eq(square.nodes_per_cell, 8);
  std::vector<int> mids;
  ck_assert_msg(group_edges(square, "bottom", &mids) == std::vector<int>({0, 1}) && mids == std::vector<int>({4}),
                "Q8 bottom edge");
  ck_assert_msg(group_nodes(square, "bottom") == std::vector<int>({0, 1, 4}), "Q8 bottom nodes");
  // a 2-node line on a second-order body: its middle would be missing from a support
  // (a BodyMesh points into its file: keep the file alive)
  const GmshMesh t6_file =
      parse_gmsh(head + "$Elements\n3\n1 9 0 1 2 3 5 6 9\n2 9 0 1 3 4 9 7 8\n3 1 2 5 5 1 2\n$EndElements\n", "l.msh");
  const BodyMesh t6 = extract_body(t6_file, "", 1);
  ASSERT_HAS(error_of<MeshError>([&] { group_nodes(t6, "bottom"); }),
             "l.msh:25: element 3 (group 'bottom') is a 2-node line but body 1's cells are 6-node triangles "
             "(second order): lines and cells must have the same order");
  ASSERT_HAS(error_of<MeshError>([&] { group_edges(t6, "bottom"); }), "is a 2-node line but body 1's cells");
  // a 3-node line whose middle is not the side's mid-edge node
  const GmshMesh wrong_file =
      parse_gmsh(head + "$Elements\n3\n1 9 0 1 2 3 5 6 9\n2 9 0 1 3 4 9 7 8\n3 8 2 5 5 1 2 9\n$EndElements\n", "m.msh");
  const BodyMesh wrong = extract_body(wrong_file, "", 1);
  ASSERT_HAS(error_of<MeshError>([&] { group_edges(wrong, "bottom"); }),
             "m.msh:25: element 3 (group 'bottom'): its middle node 9 is not the mid-edge node 5 of the side 1-2");
  // a 3-node line on a first-order body
  const GmshMesh p1_file =
      parse_gmsh(head + "$Elements\n3\n1 2 0 1 2 3\n2 2 0 1 3 4\n3 8 2 5 5 1 2 5\n$EndElements\n", "p.msh");
  const BodyMesh p1 = extract_body(p1_file, "", 1);
  ASSERT_HAS(error_of<MeshError>([&] { group_edges(p1, "bottom"); }),
             "is a 3-node line but body 1's cells are 3-node triangles (first order)");
}
END_TEST

// ---- the scene -----------------------------------------------------------------------------

// A valid scene; `edit` replaces its first occurrence of `from` by `to`.
std::string scene_text(const std::string &from = "", const std::string &to = "") {
  std::string s = R"({
  "bodies": [
    { "mesh": "m.msh", "domain": "a", "material": { "E": 2, "nu": 0.3 },
      "supports": [ { "group": "left", "components": "x" } ],
      "loads": [ { "type": "pressure", "group": "top", "value": 0.25 },
                 { "type": "body_force", "value": [0, -1] } ],
      "contact": "c1" },
    { "mesh": "m.msh", "domain": "b", "material": { "E": 5, "nu": 0.25 },
      "supports": [ { "group": "bottom", "components": "both", "value": [0, 0.1] } ],
      "contact": "c2" }
  ],
  "solver": { "method": "dual_mortar" },
  "output": { "pressure_csv": "out/p.csv" }
})";
  if (!from.empty()) {
    size_t at = s.find(from);
    ck_assert_msg(at != std::string::npos, "test bug: '%s' not in the scene", from.c_str());
    s.replace(at, from.size(), to);
  }
  return s;
}

std::string scene_error(const std::string &text) {
  return error_of<SceneError>([&] { parse_scene(text, "dir/s.json"); });
}

START_TEST(valid_scene_parsed_with_defaults) {
  const Scene s = parse_scene(scene_text(), "dir/s.json");
  ck_assert_int_eq(s.plane, MC_PLANE_STRAIN);
  ck_assert_double_eq(s.thickness, 1.0);
  ck_assert_int_eq(s.solver.method, MC_METHOD_DUAL_MORTAR);
  ck_assert_int_eq(s.solver.contact_normal, MC_NORMAL_NONMORTAR);
  ck_assert_int_eq(s.solver.contact_surface, MC_SURFACE_SMOOTH);
  ck_assert_double_eq(s.solver.feature_angle, 40.0);
  ck_assert_double_eq(s.solver.tolerance, 1e-10);
  ck_assert_int_eq(s.solver.threads, 0);  // MC_OPTION_THREADS: automatic
  ck_assert_int_eq(s.solver.interface_solver, MC_INTERFACE_AUTO);  // MC_OPTION_INTERFACE_SOLVER
  ck_assert_int_eq(s.solver.multiplier, MC_MULTIPLIER_LINEAR);     // MC_OPTION_MULTIPLIER
  ck_assert_int_eq(parse_scene(scene_text("\"dual_mortar\"", "\"dual_mortar\", \"threads\": 1"), "s.json").solver.threads, 1);
  ck_assert_str_eq(s.bodies[0].mesh_path.c_str(), "dir/m.msh");  // relative to the scene file
  ck_assert_str_eq(s.output.pressure_csv.c_str(), "dir/out/p.csv");
  ck_assert(s.output.vtu.empty());
  ck_assert_double_eq(s.bodies[1].poisson, 0.25);
  ck_assert_int_eq(s.bodies[0].supports[0].components, MC_X);
  ck_assert_int_eq(s.bodies[1].supports[0].components, MC_XY);
  ck_assert_double_eq(s.bodies[1].supports[0].value[1], 0.1);
  ck_assert_int_eq(int(s.bodies[0].loads[1].type), int(LoadType::BodyForce));
  ck_assert_double_eq(s.bodies[0].loads[1].value[1], -1.0);
  ck_assert(!s.hertz.enabled);
}
END_TEST

START_TEST(contact_surface_options_parsed) {
  const Scene s = parse_scene(scene_text("\"method\": \"dual_mortar\"",
                                         "\"method\": \"dual_mortar\", \"contact_surface\": \"faceted\", "
                                         "\"feature_angle\": 30"),
                              "dir/s.json");
  ck_assert_int_eq(s.solver.contact_surface, MC_SURFACE_FACETED);
  ck_assert_double_eq(s.solver.feature_angle, 30.0);
  std::string e = scene_error(scene_text("\"method\": \"dual_mortar\"", "\"contact_surface\": \"curvy\""));
  ASSERT_HAS(e, "contact_surface");
}
END_TEST

// A solver key taking names: each name parsed to its value (read back by `field`), an unknown
// name and a non-string refused with the messages the runner prints.
template <size_t N, class Field>
static void check_solver_names(const char *key, const std::pair<const char *, int> (&values)[N], const char *bad,
                               const char *names, Field field) {
  const std::string quoted = std::string("\"") + key + "\": ";
  for (const auto &v : values) {
    const Scene s = parse_scene(scene_text("\"method\": \"dual_mortar\"",
                                           "\"method\": \"dual_mortar\", " + quoted + "\"" + v.first + "\""),
                                "dir/s.json");
    ck_assert_int_eq(field(s.solver), v.second);
  }
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", quoted + "\"" + bad + "\"")),
             std::string("solver.") + key + ": \"" + bad + "\" is not one of " + names);
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", quoted + "2")),
             std::string("solver.") + key + ": must be a string");
}

START_TEST(interface_solver_parsed) {
  const std::pair<const char *, int> values[3] = {
      {"auto", MC_INTERFACE_AUTO}, {"condensed", MC_INTERFACE_CONDENSED}, {"sparse", MC_INTERFACE_SPARSE}};
  check_solver_names("interface_solver", values, "dense", "\"auto\", \"condensed\", \"sparse\"",
                     [](const auto &solver) { return solver.interface_solver; });
}
END_TEST

START_TEST(multiplier_parsed) {
  const std::pair<const char *, int> values[2] = {{"linear", MC_MULTIPLIER_LINEAR},
                                                  {"quadratic", MC_MULTIPLIER_QUADRATIC}};
  check_solver_names("multiplier", values, "cubic", "\"linear\", \"quadratic\"",
                     [](const auto &solver) { return solver.multiplier; });
}
END_TEST

// A valid scene of three bodies and two pairs; `edit` replaces the first occurrence of `from` by `to`.
std::string pairs_scene_text(const std::string &from = "", const std::string &to = "") {
  std::string s = R"({
  "bodies": [
    { "mesh": "m.msh", "domain": "a", "material": { "E": 2, "nu": 0.3 } },
    { "mesh": "m.msh", "domain": "b", "material": { "E": 1, "nu": 0.3 } },
    { "mesh": "n.msh", "material": { "E": 3, "nu": 0.3 } }
  ],
  "pairs": [
    { "nonmortar": 1, "mortar": 2, "nonmortar_surface": "a_bottom", "mortar_surface": "b_top" },
    { "nonmortar": 2, "mortar": 3, "nonmortar_surface": "b_bottom", "mortar_surface": "c_top", "gap_offset": -0.01 }
  ]
})";
  if (!from.empty()) {
    size_t at = s.find(from);
    ck_assert_msg(at != std::string::npos, "test bug: '%s' not in the scene", from.c_str());
    s.replace(at, from.size(), to);
  }
  return s;
}

START_TEST(pairs_scene_parsed_and_checked) {
  const Scene s = parse_scene(pairs_scene_text(), "dir/s.json");
  ck_assert(s.has_pairs);
  ck_assert_int_eq(int(s.bodies.size()), 3);
  ck_assert_int_eq(int(s.pairs.size()), 2);
  ck_assert_int_eq(s.pairs[1].number, 2);
  ck_assert_int_eq(s.pairs[1].nonmortar, 2);
  ck_assert_int_eq(s.pairs[1].mortar, 3);
  ck_assert_str_eq(s.pairs[1].mortar_surface.c_str(), "c_top");
  ck_assert(s.pairs[1].has_gap_offset && !s.pairs[0].has_gap_offset);
  ck_assert_double_eq(s.pairs[1].gap_offset, -0.01);
  // Without "pairs": the implied pair 1 of the two bodies' "contact".
  const Scene two = parse_scene(scene_text(), "dir/s.json");
  ck_assert(!two.has_pairs);
  ck_assert_int_eq(int(two.pairs.size()), 1);
  ck_assert(two.pairs[0].implied);
  ck_assert_str_eq(two.pairs[0].nonmortar_surface.c_str(), "c1");
  ck_assert_str_eq(two.pairs[0].mortar_surface.c_str(), "c2");
  // Bad pairs name the pair.
  ASSERT_HAS(scene_error(pairs_scene_text("\"nonmortar\": 2, \"mortar\": 3", "\"nonmortar\": 2, \"mortar\": 4")),
             "dir/s.json: pairs[1].mortar: pair 2 names body 4, which does not exist: the scene has bodies 1 to 3");
  ASSERT_HAS(scene_error(pairs_scene_text("\"nonmortar\": 1, \"mortar\": 2", "\"nonmortar\": 0, \"mortar\": 2")),
             "pairs[0].nonmortar: pair 1 names body 0, which does not exist");
  ASSERT_HAS(scene_error(pairs_scene_text("\"nonmortar\": 1, \"mortar\": 2", "\"nonmortar\": \"top\", \"mortar\": 2")),
             "pairs[0].nonmortar: pair 1 names body string \"top\", which does not exist");
  ASSERT_HAS(scene_error(pairs_scene_text("\"nonmortar\": 2, \"mortar\": 3", "\"nonmortar\": 2, \"mortar\": 2")),
             "dir/s.json: pairs[1]: pair 2 joins body 2 with itself: nonmortar and mortar must be two different bodies");
  ASSERT_HAS(scene_error(pairs_scene_text(", \"mortar_surface\": \"b_top\"", "")),
             "dir/s.json: pairs[0].mortar_surface: missing (required)");
  ASSERT_HAS(scene_error(pairs_scene_text("\"mortar\": 2,", "")), "pairs[0].mortar: missing (required)");
  ASSERT_HAS(scene_error(pairs_scene_text("\"mortar\": 2,", "\"mortar\": 2, \"mortar_surfce\": \"x\",")),
             "pairs[0].mortar_surfce: unknown key (did you mean 'mortar_surface'?)");
  ASSERT_HAS(scene_error(pairs_scene_text("\"E\": 1, \"nu\": 0.3 } }", "\"E\": 1, \"nu\": 0.3 }, \"contact\": \"b_top\" }")),
             "bodies[1].contact: the scene lists \"pairs\": name the contact surfaces and gap offsets there");
  ASSERT_HAS(scene_error(pairs_scene_text("\"domain\": \"b\", ", "")),
             "bodies[1].domain: missing: both bodies use the mesh m.msh (bodies[0] and bodies[1])");
  // More than two bodies need pairs; the Hertz check and adaptive refinement take two.
  const std::string no_pairs = pairs_scene_text().substr(0, pairs_scene_text().find(",\n  \"pairs\"")) + "\n}";
  ASSERT_HAS(scene_error(no_pairs.substr(0, no_pairs.size() - 2) + ", \"pairs\": []}"), "pairs: must list at least one");
  ASSERT_HAS(scene_error(no_pairs), "bodies: must list exactly two bodies (body 1, the non-mortar side, first), got 3; "
                                    "a scene of other than two bodies names its contact surfaces in a \"pairs\" list");
  ASSERT_HAS(scene_error(pairs_scene_text("\"pairs\": [",
                                          "\"analytic\": { \"type\": \"hertz\", \"radius\": 1, \"load\": 1 },\n \"pairs\": [")),
             "analytic: the Hertz check compares two bodies in contact, the scene has 3");
}
END_TEST

START_TEST(friction_scene_parsed_and_checked) {
  // Defaults: no friction, one load step, c_t scaled automatically.
  const Scene plain = parse_scene(scene_text(), "dir/s.json");
  ck_assert_int_eq(plain.load_steps, 1);
  ck_assert_double_eq(plain.solver.friction_ct, 0.0);
  ck_assert_int_eq(plain.pairs[0].friction_law, MC_FRICTION_NONE);
  ck_assert(plain.pairs[0].friction_key.empty() && !has_friction(plain));
  // A two-body scene: the top-level "friction" is the implied pair's.
  const std::string top = "\"solver\": {";
  const Scene two = parse_scene(scene_text(top, "\"friction\": { \"law\": \"coulomb\", \"mu\": 0.3 }, \"load_steps\": 5,\n " +
                                                    top + " \"friction_ct\": 2.5, "),
                                "dir/s.json");
  ck_assert_int_eq(two.pairs[0].friction_law, MC_FRICTION_COULOMB);
  ck_assert_double_eq(two.pairs[0].friction_value, 0.3);
  ck_assert_str_eq(two.pairs[0].friction_key.c_str(), "friction");
  ck_assert_int_eq(two.load_steps, 5);
  ck_assert_double_eq(two.solver.friction_ct, 2.5);
  ck_assert(has_friction(two));
  // Pairs: each its own law; "none" is no friction.
  const Scene pairs = parse_scene(
      pairs_scene_text("\"b_top\" }", "\"b_top\", \"friction\": { \"law\": \"tresca\", \"bound\": 0.02 } }"),
      "dir/s.json");
  ck_assert_int_eq(pairs.pairs[0].friction_law, MC_FRICTION_TRESCA);
  ck_assert_double_eq(pairs.pairs[0].friction_value, 0.02);
  ck_assert_str_eq(pairs.pairs[0].friction_key.c_str(), "pairs[0].friction");
  ck_assert_int_eq(pairs.pairs[1].friction_law, MC_FRICTION_NONE);
  const Scene none = parse_scene(pairs_scene_text("\"b_top\" }", "\"b_top\", \"friction\": { \"law\": \"none\" } }"), "s.json");
  ck_assert(!has_friction(none) && none.pairs[0].friction_key == "pairs[0].friction");
  // Mistakes name the key.
  auto top_error = [&](const std::string &keys) { return scene_error(scene_text(top, keys + ",\n " + top)); };
  auto pair_error = [&](const std::string &friction) {
    return scene_error(pairs_scene_text("\"b_top\" }", "\"b_top\", \"friction\": " + friction + " }"));
  };
  ASSERT_HAS(top_error("\"friction\": { \"law\": \"coulomb\", \"mu\": -0.1 }"),
             "dir/s.json: friction.mu: the friction coefficient must be >= 0, got number -0.1");
  ASSERT_HAS(pair_error("{ \"law\": \"tresca\", \"bound\": -1 }"),
             "pairs[0].friction.bound: the Tresca slip bound must be >= 0");
  ASSERT_HAS(pair_error("{ \"law\": \"coulomb\" }"), "pairs[0].friction.mu: missing (required)");
  ASSERT_HAS(pair_error("{ \"law\": \"coulomb\", \"bound\": 0.1 }"), "pairs[0].friction.bound: unknown key");
  ASSERT_HAS(pair_error("{ \"law\": \"coulomb\", \"muu\": 0.1 }"), "pairs[0].friction.muu: unknown key (did you mean 'mu'?)");
  ASSERT_HAS(pair_error("{ \"lwa\": \"coulomb\", \"mu\": 0.1 }"), "pairs[0].friction.lwa: unknown key (did you mean 'law'?)");
  ASSERT_HAS(pair_error("{ \"law\": \"amontons\", \"mu\": 0.1 }"),
             "pairs[0].friction.law: \"amontons\" is not one of \"none\", \"tresca\", \"coulomb\"");
  ASSERT_HAS(pair_error("0.3"), "pairs[0].friction: must be an object");
  ASSERT_HAS(scene_error(pairs_scene_text("\"pairs\": [", "\"friction\": { \"law\": \"coulomb\", \"mu\": 0.3 },\n \"pairs\": [")),
             "friction: the scene lists \"pairs\": give each pair its friction (pairs[].friction)");
  ASSERT_HAS(top_error("\"load_steps\": 0"), "load_steps: must be an integer from 1 to 1000000, got number 0");
  ASSERT_HAS(top_error("\"load_steps\": 2.5"), "load_steps: must be an integer from 1 to 1000000");
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", "\"friction_ct\": -1")),
             "solver.friction_ct: must be >= 0 (0: scaled automatically)");
}
END_TEST

START_TEST(scene_errors_name_the_key) {
  std::string e = scene_error(scene_text("\"material\": { \"E\": 2", "\"materail\": { \"E\": 2"));
  ASSERT_HAS(e, "dir/s.json: bodies[0].materail: unknown key (did you mean 'material'?)");
  e = scene_error(scene_text("\"E\": 2, \"nu\": 0.3", "\"E\": 2, \"nu\": 0.3, \"E\": 3"));
  ASSERT_HAS(e, "dir/s.json: bodies[0].material.E: duplicated key");
  e = scene_error(scene_text("\"value\": [0, 0.1]", "\"value\": [0, 0.1], \"value\": [0, 0.1]"));
  ASSERT_HAS(e, "bodies[1].supports[0].value: duplicated key");
  ASSERT_HAS(scene_error(scene_text(",\n      \"contact\": \"c2\"", "")), "bodies[1].contact: missing");
  ASSERT_HAS(scene_error(scene_text("\"E\": 2", "\"E\": \"2\"")), "bodies[0].material.E: must be a number");
  ASSERT_HAS(scene_error(scene_text("\"E\": 2", "\"E\": 0")), "bodies[0].material.E: must be > 0");
  ASSERT_HAS(scene_error(scene_text("\"nu\": 0.3", "\"nu\": 0.5")), "bodies[0].material.nu: must be in (-1, 0.5)");
  ASSERT_HAS(scene_error(scene_text("\"dual_mortar\"", "\"dual\"")),
             "solver.method: \"dual\" is not one of \"mortar\", \"dual_mortar\", \"node_to_segment\"");
  ASSERT_HAS(scene_error(scene_text("\"components\": \"x\"", "\"components\": \"z\"")),
             "bodies[0].supports[0].components: \"z\" is not one of");
  ASSERT_HAS(scene_error(scene_text("\"value\": [0, -1]", "\"value\": [0, -1], \"group\": \"a\"")),
             "bodies[0].loads[1].group: a body force acts on the whole body");
  ASSERT_HAS(scene_error(scene_text("\"value\": 0.25", "\"value\": [0.25]")),
             "bodies[0].loads[0].value: must be a number");
  ASSERT_HAS(scene_error(scene_text("\"value\": [0, 0.1]", "\"value\": [0]")),
             "bodies[1].supports[0].value: must be an array of two numbers");
  ASSERT_HAS(scene_error(scene_text("\"domain\": \"b\", ", "")),
             "bodies[1].domain: missing: both bodies use the mesh m.msh");
  ASSERT_HAS(scene_error(scene_text("\"contact\": \"c2\"", "\"contact\": \"c2\", \"gap_offset\": 0.1")),
             "bodies[1].gap_offset: only body 1");
  ASSERT_HAS(scene_error(scene_text("\"solver\"", "\"solvr\"")), "solvr: unknown key (did you mean 'solver'?)");
  ASSERT_HAS(scene_error(scene_text("\"solver\": {", "\"plane\": \"axisymmetric\", \"thickness\": 2,\n \"solver\": {")),
             "thickness: an axisymmetric scene has no thickness");
  ASSERT_HAS(scene_error(scene_text("\"solver\": {", "\"plane\": \"axi\",\n \"solver\": {")),
             "plane: \"axi\" is not one of \"strain\", \"stress\", \"axisymmetric\"");
  ASSERT_HAS(scene_error(scene_text("\"solver\": {", "\"analytic\": { \"type\": \"hertz\", \"radius\": 1 },\n \"solver\": {")),
             "analytic.load: missing");
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", "\"max_iterations\": 2.5")),
             "solver.max_iterations: must be an integer >= 1");
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", "\"threads\": -1")),
             "solver.threads: must be an integer from 0 to 1024, got number -1");
  ASSERT_HAS(scene_error("{ \"bodies\": [ {} ] }"), "bodies: must list exactly two bodies");
  ASSERT_HAS(scene_error("[1, 2]"), "top level: must be an object");
  e = scene_error("{\n  \"bodies\": [\n  ,\n]}");
  ASSERT_HAS(e, "dir/s.json: invalid JSON: ");
  ASSERT_HAS(e, "line 3");
  ASSERT_HAS(error_of<SceneError>([] { load_scene("/nonexistent/s.json"); }), "/nonexistent/s.json: cannot open");
}
END_TEST

START_TEST(adaptive_scene_parsed) {
  const std::string adaptive = ",\n  \"adaptive\": { \"geo\": \"g/m.geo\", \"target_error\": 0.01 }\n}";
  auto with = [&](const std::string &keys) {
    return scene_text("\n}", ",\n  \"adaptive\": { \"geo\": \"g/m.geo\", " + keys + " }\n}");
  };
  const Scene s = parse_scene(scene_text("\n}", adaptive), "dir/s.json");
  ck_assert(s.adaptive.enabled);
  ck_assert_str_eq(s.adaptive.geo_path.c_str(), "dir/g/m.geo");  // relative to the scene file
  ck_assert_double_eq(s.adaptive.target_error, 0.01);
  ck_assert_int_eq(s.adaptive.max_steps, 8);
  ck_assert_int_eq(s.adaptive.order, 1);
  ck_assert_double_eq(s.adaptive.aim, 0.8);
  ck_assert_double_eq(s.adaptive.max_refinement, 4);
  ck_assert_double_eq(s.adaptive.max_coarsening, 2);
  ck_assert(s.adaptive.gmsh_arguments.empty() && s.adaptive.max_dofs == 0 && s.adaptive.min_size == 0);
  ck_assert(s.solver.error_estimate);
  ck_assert(!parse_scene(scene_text(), "s.json").adaptive.enabled);
  const Scene t = parse_scene(with("\"target_error\": 0.005, \"max_steps\": 3, \"order\": 2, \"aim\": 1, "
                                   "\"gmsh_arguments\": [\"-setnumber\", \"h\", \"0.1\"], \"max_refinement\": 8, "
                                   "\"max_coarsening\": 1, \"min_size\": 1e-3, \"max_size\": 0.5, \"max_dofs\": 100000"),
                              "s.json");
  ck_assert_int_eq(t.adaptive.max_steps, 3);
  ck_assert_int_eq(t.adaptive.order, 2);
  ck_assert_int_eq(t.adaptive.gmsh_arguments.size(), 3);
  ck_assert_str_eq(t.adaptive.gmsh_arguments[1].c_str(), "h");
  ck_assert_double_eq(t.adaptive.max_refinement, 8);
  ck_assert_double_eq(t.adaptive.max_size, 0.5);
  ck_assert_int_eq(t.adaptive.max_dofs, 100000);
  ASSERT_HAS(scene_error(with("\"target_error\": 1.5")), "adaptive.target_error: is a relative error: must be in (0, 1)");
  ASSERT_HAS(scene_error(with("\"target_eror\": 0.01")), "adaptive.target_eror: unknown key (did you mean 'target_error'?)");
  ASSERT_HAS(scene_error(scene_text("\n}", ",\n  \"adaptive\": { \"target_error\": 0.01 }\n}")),
             "adaptive.geo: missing (required)");
  ASSERT_HAS(scene_error(with("\"target_error\": 0.01, \"order\": 3")), "adaptive.order: must be an integer from 1 to 2");
  ASSERT_HAS(scene_error(with("\"target_error\": 0.01, \"gmsh_arguments\": [\"-o\", \"x.msh\"]")),
             "adaptive.gmsh_arguments[0]: the runner sets -o itself");
  ASSERT_HAS(scene_error(with("\"target_error\": 0.01, \"max_refinement\": 1")), "adaptive.max_refinement: must be > 1");
  ASSERT_HAS(scene_error(with("\"target_error\": 0.01, \"aim\": 1.2")), "adaptive.aim: must be in (0, 1]");
  ASSERT_HAS(scene_error(with("\"target_error\": 0.01, \"min_size\": 0.5, \"max_size\": 0.1")),
             "adaptive.max_size: must be larger than adaptive.min_size");
  std::string two = scene_text("\"mesh\": \"m.msh\", \"domain\": \"b\"", "\"mesh\": \"n.msh\", \"domain\": \"b\"");
  ck_assert_str_eq(scene_error(two).c_str(), "");  // two files: fine without adaptive refinement
  two.replace(two.rfind("\n}"), 2, adaptive);
  ASSERT_HAS(error_of<SceneError>([&] { parse_scene(two, "s.json"); }),
             "bodies[1].mesh: adaptive refinement meshes adaptive.geo into one file for both bodies");
  std::string off = scene_text("\"method\": \"dual_mortar\"", "\"error_estimate\": false");
  ck_assert(!parse_scene(off, "s.json").solver.error_estimate);  // fine without adaptive refinement
  off.replace(off.rfind("\n}"), 2, adaptive);
  ASSERT_HAS(error_of<SceneError>([&] { parse_scene(off, "s.json"); }),
             "solver.error_estimate: adaptive refinement needs the error estimate");
  ASSERT_HAS(scene_error(scene_text("\"method\": \"dual_mortar\"", "\"error_estimate\": 1")),
             "solver.error_estimate: must be true or false");
}
END_TEST

// The tiny mesh's two bodies (3-node triangles on 4-node quadrilaterals, first order).
struct TinyBodies {
  GmshMesh file = read_gmsh(data_dir + "/tiny_v41.msh");
  BodyMesh bodies[2] = {extract_body(file, "upper", 1), extract_body(file, "lower", 2)};
};

START_TEST(size_field_equidistributes) {
  const TinyBodies tiny_bodies;
  const BodyMesh *bodies = tiny_bodies.bodies;
  const int n = bodies[0].n_cells() + bodies[1].n_cells();
  Adaptive a;
  a.target_error = 0.01;
  a.aim = 1;
  std::vector<double> eta[2];
  auto set_eta = [&](double value) {
    for (int b = 0; b < 2; ++b) eta[b].assign(size_t(bodies[b].n_cells()), value);
  };
  // Every cell with an equal share of an estimate equal to the aim: that mesh is the one asked for.
  set_eta(0.01 / std::sqrt(double(n)));
  SizeField f = make_size_field(bodies, eta, a, 1.0);
  ck_assert_int_eq(f.cells, n);
  ck_assert_msg(std::fabs(f.optimal_cells - n) < 1e-9 * n, "optimal cells %g for %d", f.optimal_cells, n);
  ck_assert_msg(std::fabs(f.predicted_cells - n) < 1e-9 * n, "predicted cells %g", f.predicted_cells);
  ck_assert_int_eq(f.refined + f.coarsened + f.limited, 0);
  for (int b = 0; b < 2; ++b) {  // each node: the smallest size of its cells
    std::vector<double> expected(size_t(bodies[b].n_nodes()), 1e300);
    for (int c = 0; c < bodies[b].n_cells(); ++c)
      for (int k = 0; k < bodies[b].nodes_per_cell; ++k) {
        double &e = expected[size_t(bodies[b].cells[size_t(c * bodies[b].nodes_per_cell + k)])];
        e = std::min(e, cell_size(bodies[b], c));
      }
    for (int i = 0; i < bodies[b].n_nodes(); ++i)
      ck_assert_msg(std::fabs(f.node_size[b][size_t(i)] - expected[size_t(i)]) < 1e-12, "body %d node %d", b + 1, i);
  }
  // Twice that error on first-order cells (error ~ N^-1/2): four times the cells, each size halved;
  // a calibration multiplies the sizes asked for, not the cells counted.
  set_eta(0.02 / std::sqrt(double(n)));
  const SizeField g = make_size_field(bodies, eta, a, 1.5);
  ck_assert_msg(std::fabs(g.optimal_cells - 4 * n) < 1e-9 * n && std::fabs(g.predicted_cells - 4 * n) < 1e-9 * n,
                "%g, %g cells for %d", g.optimal_cells, g.predicted_cells, n);
  ck_assert_int_eq(g.refined, n);
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < bodies[b].n_nodes(); ++i)
      ck_assert_msg(std::fabs(g.node_size[b][size_t(i)] - 0.75 * f.node_size[b][size_t(i)]) < 1e-12,
                    "halved, times the calibration 1.5");
  // All the error in one cell: it alone is refined, by max_refinement at most; the others
  // coarsened by max_coarsening at most; the bounds hold.
  set_eta(0);
  eta[0][0] = 0.5;
  const SizeField h = make_size_field(bodies, eta, a, 1.0);
  ck_assert_int_eq(h.limited, 1);
  ck_assert_int_eq(h.refined, 1);
  ck_assert_int_eq(h.coarsened, n - 1);
  ck_assert_msg(std::fabs(h.predicted_cells - (16 + 0.25 * (n - 1))) < 1e-9, "%g", h.predicted_cells);
  const int *first = &bodies[0].cells[0];
  for (int k = 0; k < bodies[0].nodes_per_cell; ++k)
    ck_assert(h.node_size[0][size_t(first[k])] <= 0.25 * cell_size(bodies[0], 0) * (1 + 1e-12));
  a.min_size = 0.3;
  a.max_size = 0.4;
  const SizeField bounded = make_size_field(bodies, eta, a, 1.0);
  for (int b = 0; b < 2; ++b)
    for (double size : bounded.node_size[b]) ck_assert(size >= 0.3 && size <= 0.4);
  // Second order: error ~ N^-1, so twice the error asks for twice the cells.
  const GmshMesh q = read_gmsh(data_dir + "/tiny_quadratic_v41.msh");
  const BodyMesh quadratic[2] = {extract_body(q, "upper", 1), extract_body(q, "lower", 2)};
  const int nq = quadratic[0].n_cells() + quadratic[1].n_cells();
  for (int b = 0; b < 2; ++b) eta[b].assign(size_t(quadratic[b].n_cells()), 0.02 / std::sqrt(double(nq)));
  a = Adaptive();
  a.target_error = 0.01;
  a.aim = 1;
  const SizeField p2 = make_size_field(quadratic, eta, a, 1.0);
  ck_assert_msg(std::fabs(p2.predicted_cells - 2 * nq) < 1e-9 * nq, "%g cells for %d", p2.predicted_cells, nq);
}
END_TEST

START_TEST(size_view_step_geo_and_vtu_array) {
  const TinyBodies tiny_bodies;
  const BodyMesh *bodies = tiny_bodies.bodies;
  const SizeField f = current_size_field(bodies);
  const std::string view = data_dir + "/unit_size.pos", geo = data_dir + "/unit_step.geo";
  write_size_view(view, bodies, f);
  std::ifstream in(view);
  std::stringstream text;
  text << in.rdbuf();
  const std::string pos = text.str();
  int st = 0, sq = 0, boundary = 0;
  for (size_t at = pos.find("\nST("); at != std::string::npos; at = pos.find("\nST(", at + 1)) ++st;
  for (size_t at = pos.find("\nSQ("); at != std::string::npos; at = pos.find("\nSQ(", at + 1)) ++sq;
  for (int b = 0; b < 2; ++b)
    for (const auto &e : bodies[b].edges) boundary += e.second.cells == 1;
  ck_assert_int_eq(st, bodies[0].n_cells());                  // the triangles
  ck_assert_int_eq(sq, bodies[1].n_cells() + boundary);       // the quadrilaterals and the skirt
  ASSERT_HAS(pos, "View \"mesh size\" {");
  write_step_geo(geo, "/a/b.geo", view, "a test.");
  std::ifstream g(geo);
  std::stringstream gtext;
  gtext << g.rdbuf();
  ASSERT_HAS(gtext.str(), "Include \"/a/b.geo\";");
  ASSERT_HAS(gtext.str(), "Mesh.MeshSizeFromPoints = 0;");
  ASSERT_HAS(gtext.str(), "unit_size.pos\";\nBackground Mesh View[PostProcessing.NbViews - 1];");
  ASSERT_HAS(error_of<std::runtime_error>([&] { write_step_geo(geo, "/a/\"b.geo", view, ""); }), "double quote");
  // An array added before the end of <CellData>, once.
  const std::string vtu = data_dir + "/unit.vtu";
  std::ofstream(vtu) << "<VTKFile>\n      <CellData Scalars=\"von_mises\">\n        <DataArray Name=\"body\">\n1\n2\n"
                        "        </DataArray>\n      </CellData>\n      <Points>\n</VTKFile>\n";
  add_vtu_cell_data(vtu, "error_indicator", {0.25, 0.5});
  add_vtu_cell_data(vtu, "error_indicator", {9, 9});
  std::ifstream v(vtu);
  std::stringstream vtext;
  vtext << v.rdbuf();
  ASSERT_HAS(vtext.str(), "        </DataArray>\n        <DataArray type=\"Float64\" Name=\"error_indicator\" format=\"ascii\">\n"
                          "0.25\n0.5\n        </DataArray>\n      </CellData>\n");
  ck_assert(vtext.str().find("\n9\n") == std::string::npos);
  std::ofstream(vtu) << "<VTKFile>\n</VTKFile>\n";
  ASSERT_HAS(error_of<std::runtime_error>([&] { add_vtu_cell_data(vtu, "x", {1}); }), "not one <CellData> section");
  // Gmsh named by a path that is not there: what to do.
  ASSERT_HAS(error_of<GmshError>([] { find_gmsh("/nonexistent/gmsh"); }),
             "--gmsh names '/nonexistent/gmsh', which is not an executable file");
}
END_TEST

// ---- the runner, end to end ----------------------------------------------------------------

std::vector<std::vector<double>> read_csv(const std::string &path, std::string *text) {
  std::ifstream in(path);
  ck_assert_msg(bool(in), "cannot read %s", path.c_str());
  std::stringstream all;
  all << in.rdbuf();
  *text = all.str();
  std::istringstream lines(*text);
  std::string line;
  std::getline(lines, line);
  ck_assert_str_eq(line.c_str(), "x,y,pressure,gap");
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::strtod(field.c_str(), nullptr));
    ck_assert_int_eq(row.size(), 4);
    rows.push_back(row);
  }
  return rows;
}

START_TEST(runner_patch_test_both_formats) {
  std::string text[2];
  const char *versions[2] = {"22", "41"};
  for (int k = 0; k < 2; ++k) {
    const std::string out = data_dir + "/out_v" + versions[k];
    const std::string command = "rm -rf '" + out + "' && '" + runner + "' --quiet '" + data_dir + "/tiny_v" +
                                versions[k] + ".json'";
    ck_assert_int_eq(std::system(command.c_str()), 0);
    const auto rows = read_csv(out + "/pressure.csv", &text[k]);
    // body 1's bottom: 3 nodes at y = 0; uniform pressure 0.25 through non-matching meshes
    ck_assert_int_eq(rows.size(), 3);
    for (const auto &r : rows) {
      ck_assert_double_eq(r[1], 0.0);
      ck_assert_msg(std::fabs(r[2] - 0.25) < 1e-12, "pressure %.17g at x = %g", r[2], r[0]);
      ck_assert_msg(std::fabs(r[3]) < 1e-12, "gap %.3g at x = %g", r[3], r[0]);
    }
    std::ifstream vtu(out + "/patch.vtu");
    ck_assert_msg(bool(vtu) && vtu.peek() != EOF, "no VTU written");
  }
  ck_assert_msg(text[0] == text[1], "the two formats give different results:\n%s\n%s", text[0].c_str(), text[1].c_str());
}
END_TEST

// The patch test on the second-order meshes (6-node triangles on 9-node quadrilaterals, non-
// matching): the uniform pressure reaches every contact node exactly, the mid-edge node too;
// both formats give the same CSV; the VTU holds VTK quadratic triangles (22) and biquadratic
// quadrilaterals (28).
START_TEST(runner_second_order_patch_test_both_formats) {
  std::string text[2];
  const char *versions[2] = {"22", "41"};
  for (int k = 0; k < 2; ++k) {
    const std::string out = data_dir + "/out_quadratic_v" + versions[k];
    const std::string command = "rm -rf '" + out + "' && '" + runner + "' --quiet '" + data_dir + "/tiny_quadratic_v" +
                                versions[k] + ".json'";
    ck_assert_int_eq(std::system(command.c_str()), 0);
    const auto rows = read_csv(out + "/pressure.csv", &text[k]);
    ck_assert_int_eq(rows.size(), 3);  // body 1's bottom: corner, mid-edge node, corner
    const double x[3] = {0, 0.5, 1};
    for (size_t j = 0; j < 3; ++j) {
      ck_assert_double_eq(rows[j][0], x[j]);
      ck_assert_double_eq(rows[j][1], 0.0);
      ck_assert_msg(std::fabs(rows[j][2] - 0.25) < 1e-12, "pressure %.17g at x = %g", rows[j][2], rows[j][0]);
      ck_assert_msg(std::fabs(rows[j][3]) < 1e-12, "gap %.3g at x = %g", rows[j][3], rows[j][0]);
    }
    std::ifstream vtu(out + "/patch.vtu");
    std::stringstream xml;
    xml << vtu.rdbuf();
    const std::string file = xml.str();
    const size_t types = file.find("Name=\"types\"");
    ck_assert_msg(types != std::string::npos, "no VTU written");
    const size_t begin = file.find('>', types) + 1, end = file.find("</DataArray>", types);
    std::istringstream values(file.substr(begin, end - begin));
    std::vector<int> cell_types;
    for (int t; values >> t;) cell_types.push_back(t);
    ck_assert_msg(cell_types == std::vector<int>({22, 22, 28, 28}), "VTK cell types of the two bodies");
  }
  ck_assert_msg(text[0] == text[1], "the two formats give different results:\n%s\n%s", text[0].c_str(), text[1].c_str());
}
END_TEST

// Body 1's top pushed down by 0.004 plus an interference of 0.006 (gap offset): the two blocks,
// free to expand sideways, are compressed by 0.01 in total under uniaxial stress (plane strain):
// 0.01 = (1 - nu^2) p (h1/E1 + h2/E2), which linear elements reproduce exactly.
static void check_interference_exact(const std::string &scene, const std::string &out) {
  const std::string command = "rm -rf '" + out + "' && '" + runner + "' --quiet '" + data_dir + "/" + scene + "'";
  ck_assert_int_eq(std::system(command.c_str()), 0);
  std::string text;
  const auto rows = read_csv(out + "/pressure.csv", &text);
  const double nu = 0.3, expected = 0.01 / ((1 - nu * nu) * (1 / 2.0 + 1 / 5.0));
  ck_assert_int_eq(rows.size(), 3);
  for (const auto &r : rows) {
    ck_assert_msg(std::fabs(r[2] / expected - 1) < 1e-12, "%s: pressure %.17g, expected %.17g", scene.c_str(), r[2],
                  expected);
    ck_assert_msg(std::fabs(r[3]) < 1e-14, "%s: gap %.3g at x = %g", scene.c_str(), r[3], r[0]);
  }
}

START_TEST(runner_interference_gap_offset_exact) {
  check_interference_exact("interference.json", data_dir + "/out_interference");
}
END_TEST

// The interference fit on the second-order meshes (quadratic_interference.json, mortar method):
// exact only if the support of body 1's top holds its mid-edge node too and the gap offset
// reaches the mid-edge node of the contact surface (without it: pressure 0.0094, gaps -0.004).
START_TEST(runner_second_order_interference_exact) {
  check_interference_exact("quadratic_interference.json", data_dir + "/out_quadratic_interference");
}
END_TEST

// "plane": "axisymmetric": the same meshes read as two stacked cylinders (x = r, the left side
// on the axis, held radially by the library; body 1 floats axially). The uniform pressure
// reaches the contact surface exactly, at the axis node too.
START_TEST(runner_axisymmetric_patch_exact) {
  const std::string out = data_dir + "/out_axisymmetric";
  const std::string command = "rm -rf '" + out + "' && '" + runner + "' --quiet '" + data_dir + "/tiny_axisymmetric.json'";
  ck_assert_int_eq(std::system(command.c_str()), 0);
  std::string text;
  const auto rows = read_csv(out + "/pressure.csv", &text);
  ck_assert_int_eq(rows.size(), 3);
  for (const auto &r : rows) {
    ck_assert_msg(std::fabs(r[2] - 0.25) < 1e-12, "pressure %.17g at r = %g", r[2], r[0]);
    ck_assert_msg(std::fabs(r[3]) < 1e-12, "gap %.3g at r = %g", r[3], r[0]);
  }
}
END_TEST

// The patch test of tiny_v41.json with "interface_solver" forced to each path: the same exact
// pressure, and the runner says which path ran (MC_INFO_INTERFACE_SOLVER) and that the scene set it.
START_TEST(runner_interface_solver_forced) {
  std::ifstream in(data_dir + "/tiny_v41.json");
  std::stringstream all;
  all << in.rdbuf();
  const std::string base = all.str(), output = "\"output\": { \"pressure_csv\": \"out_v41/pressure.csv\", "
                                               "\"vtu\": \"out_v41/patch.vtu\" }";
  ck_assert_msg(base.find(output) != std::string::npos, "test bug: tiny_v41.json's output changed");
  for (const char *name : {"sparse", "condensed"}) {
    std::string scene = base;
    const std::string out = std::string("out_interface_") + name;
    scene.replace(scene.find(output), output.size(),
                  std::string("\"solver\": { \"interface_solver\": \"") + name + "\" },\n  \"output\": { "
                  "\"pressure_csv\": \"" + out + "/pressure.csv\" }");
    const std::string path = data_dir + "/tiny_v41_" + name + ".json";
    std::ofstream(path) << scene;
    const std::string command = "rm -rf '" + data_dir + "/" + out + "' && '" + runner + "' --quiet '" + path + "'";
    FILE *pipe = popen(command.c_str(), "r");
    ck_assert_ptr_nonnull(pipe);
    std::string printed;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) printed += buffer;
    ck_assert_msg(pclose(pipe) == 0, "%s failed:\n%s", command.c_str(), printed.c_str());
    ASSERT_HAS(printed, std::string("interface solver: ") + name + " (set by the scene)");
    std::string text;
    const auto rows = read_csv(data_dir + "/" + out + "/pressure.csv", &text);
    ck_assert_int_eq(rows.size(), 3);
    for (const auto &r : rows)
      ck_assert_msg(std::fabs(r[2] - 0.25) < 1e-12, "%s: pressure %.17g at x = %g", name, r[2], r[0]);
  }
}
END_TEST

}  // namespace

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s DATA_DIR RUNNER\n", argv[0]);
    return 2;
  }
  data_dir = argv[1];
  runner = argv[2];
  Suite *suite = suite_create("runner");
  TCase *tc = tcase_create("runner");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, both_formats_read_the_same_mesh);
  tcase_add_test(tc, body_nodes_compact_cells_counter_clockwise);
  tcase_add_test(tc, group_edges_oriented_body_on_the_left);
  tcase_add_test(tc, body_errors_name_element_and_line);
  tcase_add_test(tc, malformed_files_name_file_and_line);
  tcase_add_test(tc, second_order_both_formats_read_the_same_mesh);
  tcase_add_test(tc, second_order_body_cells_edges_and_supports);
  tcase_add_test(tc, second_order_errors_name_element_and_line);
  tcase_add_test(tc, valid_scene_parsed_with_defaults);
  tcase_add_test(tc, friction_scene_parsed_and_checked);
  tcase_add_test(tc, contact_surface_options_parsed);
  tcase_add_test(tc, interface_solver_parsed);
  tcase_add_test(tc, multiplier_parsed);
  tcase_add_test(tc, scene_errors_name_the_key);
  tcase_add_test(tc, pairs_scene_parsed_and_checked);
  tcase_add_test(tc, adaptive_scene_parsed);
  tcase_add_test(tc, size_field_equidistributes);
  tcase_add_test(tc, size_view_step_geo_and_vtu_array);
  tcase_add_test(tc, runner_patch_test_both_formats);
  tcase_add_test(tc, runner_second_order_patch_test_both_formats);
  tcase_add_test(tc, runner_interference_gap_offset_exact);
  tcase_add_test(tc, runner_second_order_interference_exact);
  tcase_add_test(tc, runner_axisymmetric_patch_exact);
  tcase_add_test(tc, runner_interface_solver_forced);
  suite_add_tcase(suite, tc);
  SRunner *sr = srunner_create(suite);
  srunner_run_all(sr, CK_NORMAL);
  const int failed = srunner_ntests_failed(sr);
  srunner_free(sr);
  return failed == 0 ? 0 : 1;
}
