/*
 * hertz_scene_check.c - self-check of the Hertz scene generator (ctest hertz_scene runs it on
 * three size pairs with P1 and Q1, and T6, Q8 and Q9 on the first; examples/CMakeLists.txt). By hand:
 *   gcc -std=c99 -O2 -Wall -Wextra hertz_scene_check.c hertz_scene.c -lm -o hertz_scene_check
 *   ./hertz_scene_check            # default size list
 *   ./hertz_scene_check h1 h2 ...  # pairs of sizes
 * Exits nonzero if any check fails.
 */
#include "hertz_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static int failures = 0;
#define CHECK(cond, ...)                                    \
  do {                                                      \
    if (!(cond)) {                                          \
      ++failures;                                           \
      printf("  FAIL %s:%d: ", __FILE__, __LINE__);         \
      printf(__VA_ARGS__);                                  \
      printf("\n");                                         \
    }                                                       \
  } while (0)

static const double *g_xy; /* qsort has no context argument in C99 */
static int cmp_node(const void *a, const void *b)
{
  const double *p = g_xy + 2 * *(const int *)a, *q = g_xy + 2 * *(const int *)b;
  if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
  if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
  return 0;
}
static int cmp_edge(const void *a, const void *b)
{
  const long long x = *(const long long *)a, y = *(const long long *)b;
  return x < y ? -1 : x > y;
}
static long long edge_key(int a, int b, int n)
{
  return a < b ? (long long)a * n + b : (long long)b * n + a;
}

/* 2 x signed area of triangle (a,b,c) */
static double cross(const double *xy, int a, int b, int c)
{
  return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
         (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

/* Boundary edges (appearing in exactly one cell), sorted keys; returns count. */
static long long *boundary_edges(const hertz_mesh *m, int *nb)
{
  const int npc = m->nodes_per_cell, ne = m->n_cells * npc;
  long long *k = malloc((size_t)ne * sizeof *k);
  for (int c = 0; c < m->n_cells; ++c)
    for (int v = 0; v < npc; ++v)
      k[c * npc + v] = edge_key(m->cells[c * npc + v], m->cells[c * npc + (v + 1) % npc], m->n_nodes);
  qsort(k, (size_t)ne, sizeof *k, cmp_edge);
  int n = 0;
  for (int i = 0; i < ne;) {
    int j = i;
    while (j < ne && k[j] == k[i]) ++j;
    if (j - i == 1) k[n++] = k[i];
    i = j;
  }
  *nb = n;
  return k;
}

static int is_boundary(const long long *b, int nb, int u, int v, int n)
{
  const long long key = edge_key(u, v, n);
  return bsearch(&key, b, (size_t)nb, sizeof key, cmp_edge) != NULL;
}

/* Checks that hold for both bodies; returns the area, prints the worst cell. */
static double check_mesh(const hertz_mesh *m, const char *name)
{
  const int npc = m->nodes_per_cell;
  double area = 0.0, min_rel = INFINITY, min_sin = INFINITY;
  int *used = calloc((size_t)m->n_nodes, sizeof *used);
  for (int c = 0; c < m->n_cells; ++c) {
    const int *v = m->cells + c * npc;
    double a = 0.0, lmax = 0.0;
    for (int k = 0; k < npc; ++k) {
      const int p = v[k], q = v[(k + 1) % npc], r = v[(k + npc - 1) % npc];
      const double l = hypot(m->xy[2 * q] - m->xy[2 * p], m->xy[2 * q + 1] - m->xy[2 * p + 1]);
      const double l2 = hypot(m->xy[2 * r] - m->xy[2 * p], m->xy[2 * r + 1] - m->xy[2 * p + 1]);
      if (l > lmax) lmax = l;
      /* corner cross products: all > 0 means a convex quad, i.e. a bilinear
         map with positive Jacobian everywhere; for triangles it is the area */
      const double cr = cross(m->xy, p, q, r);
      CHECK(cr > 0.0, "%s cell %d corner %d: cross product %.3e <= 0", name, c, k, cr);
      if (cr / (l * l2) < min_sin) min_sin = cr / (l * l2);
      used[p] = 1;
    }
    for (int k = 1; k + 1 < npc; ++k) a += 0.5 * cross(m->xy, v[0], v[k], v[k + 1]);
    if (a / (lmax * lmax) < min_rel) min_rel = a / (lmax * lmax);
    area += a;
  }
  for (int i = 0; i < m->n_nodes; ++i) CHECK(used[i], "%s node %d unused", name, i);
  free(used);

  /* duplicates and mirror symmetry: sort nodes lexicographically */
  int *idx = malloc((size_t)m->n_nodes * sizeof *idx);
  for (int i = 0; i < m->n_nodes; ++i) idx[i] = i;
  g_xy = m->xy;
  qsort(idx, (size_t)m->n_nodes, sizeof *idx, cmp_node);
  double dmin = INFINITY;
  for (int i = 0; i + 1 < m->n_nodes; ++i) {
    const double *p = m->xy + 2 * idx[i], *q = m->xy + 2 * idx[i + 1];
    const double d = hypot(q[0] - p[0], q[1] - p[1]);
    if (d < dmin) dmin = d;
  }
  CHECK(dmin > 1e-9, "%s: duplicate nodes (min distance %.3e)", name, dmin);
  int asym = 0;
  for (int i = 0; i < m->n_nodes; ++i) {
    /* the mirror image must exist bit for bit */
    double mir[2] = {-m->xy[2 * i], m->xy[2 * i + 1]};
    if (mir[0] == 0.0) continue;
    int lo = 0, hi = m->n_nodes - 1, found = 0;
    while (lo <= hi) {
      const int mid = (lo + hi) / 2;
      const double *p = m->xy + 2 * idx[mid];
      const int c = p[0] != mir[0] ? (p[0] < mir[0] ? -1 : 1) : p[1] != mir[1] ? (p[1] < mir[1] ? -1 : 1) : 0;
      if (c == 0) { found = 1; break; }
      if (c < 0) lo = mid + 1; else hi = mid - 1;
    }
    asym += !found;
  }
  CHECK(asym == 0, "%s: %d nodes without an exact mirror image", name, asym);
  free(idx);
  printf("  %s: %7d nodes %8d cells  area %.10f  min area/h^2 %.3f  min |sin angle| %.3f\n",
         name, m->n_nodes, m->n_cells, area, min_rel, min_sin);
  return area;
}

static void check_scene(double h1, double h2, int quads)
{
  hertz_scene s;
  printf("h1 = %g, h2 = %g, %s\n", h1, h2, quads ? "Q1" : "P1");
  if (hertz_scene_build(&s, h1, h2, quads)) {
    CHECK(0, "build failed");
    return;
  }
  const hertz_mesh *b1 = &s.body[0], *b2 = &s.body[1];
  const double area1 = check_mesh(b1, "body 1"), area2 = check_mesh(b2, "body 2");
  int nb1, nb2;
  long long *bd1 = boundary_edges(b1, &nb1), *bd2 = boundary_edges(b2, &nb2);
  /* Body 1 is the polygon inscribed in the half-disc: it misses one circular
     segment (theta - sin theta)/2 per arc chord, O(h^3) each and O(h^2) in all
     (h the coarsest chord, in the graded tail). Adding them back must give
     pi/2 to rounding, which checks the arc nodes and the cell cover at once. */
  double segments = 0.0, chord_max = 0.0;
  for (int e = 0; e < nb1; ++e) {
    const int u = (int)(bd1[e] / b1->n_nodes), v = (int)(bd1[e] % b1->n_nodes);
    if (b1->xy[2 * u + 1] == 1.0 && b1->xy[2 * v + 1] == 1.0) continue; /* flat top */
    const double c = hypot(b1->xy[2 * u] - b1->xy[2 * v], b1->xy[2 * u + 1] - b1->xy[2 * v + 1]);
    const double theta = 2.0 * asin(0.5 * c);
    segments += 0.5 * (theta - sin(theta));
    if (c > chord_max) chord_max = c;
  }
  const double tol = 1e-15 * (b1->n_cells + b2->n_cells) + 1e-13; /* summation rounding */
  CHECK(area1 < PI / 2 && fabs(area1 + segments - PI / 2) < tol,
        "body 1 area %.15f + segments %.3e vs pi/2", area1, segments);
  CHECK(fabs(area2 - 32.0) < 32.0 * tol, "body 2 area %.15f vs 32", area2);
  printf("  body 1: pi/2 - area = %.3e (coarsest arc chord %.4f), body 2: area - 32 = %.1e\n",
         PI / 2 - area1, chord_max, area2 - 32.0);
  double len_top = 0.0, len_c1 = 0.0;
  for (int e = 0; e < s.n_top_edges; ++e) {
    const int u = s.top_edges[2 * e], v = s.top_edges[2 * e + 1];
    CHECK(b1->xy[2 * u + 1] == 1.0 && b1->xy[2 * v + 1] == 1.0, "top edge %d not at y == 1", e);
    CHECK(is_boundary(bd1, nb1, u, v, b1->n_nodes), "top edge %d not a boundary edge", e);
    len_top += fabs(b1->xy[2 * u] - b1->xy[2 * v]);
  }
  CHECK(fabs(len_top - 2.0) < 1e-15 * s.n_top_edges + 1e-15, "top length %.16f", len_top);
  int n_arc_c = 0;
  for (int e = 0; e < s.n_contact_edges[0]; ++e) {
    const int u = s.contact_edges[0][2 * e], v = s.contact_edges[0][2 * e + 1];
    for (int k = 0; k < 2; ++k) {
      const int p = k ? v : u;
      CHECK(fabs(hypot(b1->xy[2 * p], b1->xy[2 * p + 1] - 1.0) - 1.0) < 1e-15, "contact node %d off the circle", p);
      CHECK(fabs(b1->xy[2 * p]) <= 0.5, "contact node %d: |x| > 0.5", p);
    }
    CHECK(is_boundary(bd1, nb1, u, v, b1->n_nodes), "body-1 contact edge %d not a boundary edge", e);
    len_c1 += hypot(b1->xy[2 * u] - b1->xy[2 * v], b1->xy[2 * u + 1] - b1->xy[2 * v + 1]);
    ++n_arc_c;
  }
  for (int e = 0; e < s.n_contact_edges[1]; ++e) {
    const int u = s.contact_edges[1][2 * e], v = s.contact_edges[1][2 * e + 1];
    CHECK(b2->xy[2 * u + 1] == 0.0 && b2->xy[2 * v + 1] == 0.0, "body-2 contact edge %d not at y == 0", e);
    CHECK(fabs(b2->xy[2 * u]) <= 1.0 && fabs(b2->xy[2 * v]) <= 1.0, "body-2 contact edge %d: |x| > 1", e);
    CHECK(is_boundary(bd2, nb2, u, v, b2->n_nodes), "body-2 contact edge %d not a boundary edge", e);
  }
  int n_axis = 0, n_bottom = 0, has_origin1 = 0, has_origin2 = 0;
  for (int i = 0; i < b1->n_nodes; ++i) {
    n_axis += b1->xy[2 * i] == 0.0;
    has_origin1 |= b1->xy[2 * i] == 0.0 && b1->xy[2 * i + 1] == 0.0;
  }
  for (int i = 0; i < b2->n_nodes; ++i) {
    n_bottom += b2->xy[2 * i + 1] == -4.0;
    has_origin2 |= b2->xy[2 * i] == 0.0 && b2->xy[2 * i + 1] == 0.0;
  }
  CHECK(n_axis == s.n_axis_nodes, "axis: %d nodes with x == 0, %d listed", n_axis, s.n_axis_nodes);
  for (int k = 0; k < s.n_axis_nodes; ++k) CHECK(b1->xy[2 * s.axis_nodes[k]] == 0.0, "axis node %d x != 0", k);
  CHECK(n_bottom == s.n_bottom_nodes, "bottom: %d nodes with y == -4, %d listed", n_bottom, s.n_bottom_nodes);
  for (int k = 0; k < s.n_bottom_nodes; ++k)
    CHECK(b2->xy[2 * s.bottom_nodes[k] + 1] == -4.0, "bottom node %d y != -4", k);
  CHECK(has_origin1 && has_origin2, "the contact point (0,0) is not a node of both bodies");
  /* the arc length of |x| <= x_max is 2 asin(x_max); chords are a little shorter */
  printf("  contact edges %d (arc length %.6f, |x| <= %.4f) / %d, top edges %d, axis nodes %d, bottom nodes %d\n",
         n_arc_c, len_c1, 0.5, s.n_contact_edges[1], s.n_top_edges, s.n_axis_nodes, s.n_bottom_nodes);
  const long dofs1 = 2L * b1->n_nodes, dofs2 = 2L * b2->n_nodes;
  printf("  DOFs: body 1 %ld + body 2 %ld = %ld\n", dofs1, dofs2, dofs1 + dofs2);
  free(bd1);
  free(bd2);
  hertz_scene_free(&s);
}

/* The mid-edge node of the edge (u, v) of a quadratic mesh (corner ids), or -1: from the cell
   that has that edge. */
static int middle_of(const hertz_mesh *m, int u, int v)
{
  const int npc = m->nodes_per_cell, corners = npc == 6 ? 3 : 4;
  for (int c = 0; c < m->n_cells; ++c) {
    const int *w = m->cells + c * npc;
    for (int k = 0; k < corners; ++k) {
      const int a = w[k], b = w[(k + 1) % corners];
      if ((a == u && b == v) || (a == v && b == u)) return w[corners + k];
    }
  }
  return -1;
}

/* A quadratic scene (T6, Q8, Q9): the corners as in check_mesh (counter-clockwise, convex);
   every node used; body 2, the block, has straight cells (each middle at its edge's midpoint, a
   Q9 centre at the corners' mean, to rounding) whose corner polygons tile its 32; body 1's
   contact edges have their middles on the circle, between their corners; the axis, bottom and
   top lists hold the middles there too. */
static void check_quadratic_scene(double h1, double h2, int npc)
{
  hertz_scene s;
  const char *kind = npc == 6 ? "T6" : npc == 8 ? "Q8" : "Q9";
  const int corners = npc == 6 ? 3 : 4;
  printf("h1 = %g, h2 = %g, %s\n", h1, h2, kind);
  if (hertz_scene_build_cells(&s, h1, h2, npc)) {
    CHECK(0, "%s build failed", kind);
    return;
  }
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *m = &s.body[b];
    CHECK(m->nodes_per_cell == npc, "%s body %d: %d nodes per cell", kind, b + 1, m->nodes_per_cell);
    int *used = calloc((size_t)m->n_nodes, sizeof *used);
    double area = 0.0, off_chord = 0.0;
    for (int c = 0; c < m->n_cells; ++c) {
      const int *v = m->cells + c * npc;
      for (int k = 0; k < npc; ++k) used[v[k]] = 1;
      for (int k = 0; k < corners; ++k) {
        const int p = v[k], q = v[(k + 1) % corners], r = v[(k + corners - 1) % corners];
        CHECK(cross(m->xy, p, q, r) > 0.0, "%s body %d cell %d corner %d: not counter-clockwise and convex", kind,
              b + 1, c, k);
        const int mid = v[corners + k];
        const double dx = m->xy[2 * mid] - 0.5 * (m->xy[2 * p] + m->xy[2 * q]);
        const double dy = m->xy[2 * mid + 1] - 0.5 * (m->xy[2 * p + 1] + m->xy[2 * q + 1]);
        const double edge = hypot(m->xy[2 * q] - m->xy[2 * p], m->xy[2 * q + 1] - m->xy[2 * p + 1]);
        if (hypot(dx, dy) / edge > off_chord) off_chord = hypot(dx, dy) / edge;
      }
      for (int k = 1; k + 1 < corners; ++k) area += 0.5 * cross(m->xy, v[0], v[k], v[k + 1]);
      if (npc == 9 && b == 1) {
        double x = 0, y = 0;
        for (int k = 0; k < 4; ++k) x += 0.25 * m->xy[2 * v[k]], y += 0.25 * m->xy[2 * v[k] + 1];
        CHECK(hypot(m->xy[2 * v[8]] - x, m->xy[2 * v[8] + 1] - y) < 1e-12, "Q9 body 2 cell %d: centre off", c);
      }
    }
    int unused = 0;
    for (int i = 0; i < m->n_nodes; ++i) unused += !used[i];
    CHECK(unused == 0, "%s body %d: %d nodes unused", kind, b + 1, unused);
    free(used);
    /* body 2 is straight-sided; body 1's mapped cells bend, but a middle stays well inside its
       edge's middle half (the library's check) */
    if (b == 1) {
      CHECK(off_chord < 1e-12, "%s body 2: a middle %.3e of its edge off the midpoint", kind, off_chord);
      CHECK(fabs(area - 32.0) < 1e-10, "%s body 2: corner polygons cover %.15f, not 32", kind, area);
    } else {
      CHECK(off_chord < 0.25, "%s body 1: a middle %.3f of its edge off the midpoint", kind, off_chord);
    }
    printf("  %s body %d: %7d nodes %8d cells, largest middle offset %.2e of its edge\n", kind, b + 1, m->n_nodes,
           m->n_cells, off_chord);
  }
  const hertz_mesh *b1 = &s.body[0];
  for (int e = 0; e < s.n_contact_edges[0]; ++e) {
    const int u = s.contact_edges[0][2 * e], v = s.contact_edges[0][2 * e + 1], m = middle_of(b1, u, v);
    CHECK(m >= 0, "%s body-1 contact edge %d (%d, %d) is no cell's edge", kind, e, u, v);
    if (m < 0) continue;
    const double *x = b1->xy;
    CHECK(fabs(hypot(x[2 * m], x[2 * m + 1] - 1.0) - 1.0) < 1e-15, "%s contact edge %d: middle off the circle", kind, e);
    CHECK((x[2 * m] - x[2 * u]) * (x[2 * m] - x[2 * v]) < 0, "%s contact edge %d: middle not between its corners", kind,
          e);
  }
  int axis = 0, bottom = 0, top = 0;
  for (int i = 0; i < b1->n_nodes; ++i) axis += b1->xy[2 * i] == 0.0, top += b1->xy[2 * i + 1] == 1.0;
  for (int i = 0; i < s.body[1].n_nodes; ++i) bottom += s.body[1].xy[2 * i + 1] == -4.0;
  CHECK(axis == s.n_axis_nodes, "%s axis: %d nodes with x == 0, %d listed", kind, axis, s.n_axis_nodes);
  CHECK(bottom == s.n_bottom_nodes, "%s bottom: %d nodes with y == -4, %d listed", kind, bottom, s.n_bottom_nodes);
  CHECK(2 * s.n_top_edges + 1 == top, "%s top: %d edges for %d nodes at y == 1 (corners and middles)", kind,
        s.n_top_edges, top);
  hertz_scene_free(&s);
}

int main(int argc, char **argv)
{
  hertz_scene s;
  /* argument validation and NULL-safety */
  CHECK(hertz_scene_build(&s, 0.0, 0.02, 0) != 0, "h1 = 0 accepted");
  CHECK(hertz_scene_build(&s, 0.02, NAN, 0) != 0, "h2 = NaN accepted");
  CHECK(hertz_scene_build(&s, 0.02, 0.02, 2) != 0, "quads = 2 accepted");
  CHECK(hertz_scene_build(NULL, 0.02, 0.02, 0) != 0, "NULL scene accepted");
  /* hertz_scene_build_graded's own arguments: growth in [1.01, 3], the fine zone's half-width
     from max(h1, h2) to 0.5, nodes per cell 3, 4, 6, 8, 9; each refused (1) and *s left zeroed */
  const struct { double h1, h2; int npc; double growth, fine; const char *what; } bad[] = {
      {0.02, 0.02, 8, 1.0, 0.4, "growth 1.0"},      {0.02, 0.02, 8, 3.5, 0.4, "growth 3.5"},
      {0.02, 0.02, 8, NAN, 0.4, "growth NaN"},      {0.02, 0.02, 8, 1.15, 0.6, "fine half-width 0.6"},
      {0.02, 0.05, 8, 1.15, 0.04, "fine half-width below h2"}, {0.05, 0.02, 6, 1.15, 0.04, "fine half-width below h1"},
      {0.02, 0.02, 8, 1.15, NAN, "fine half-width NaN"}, {0.02, 0.02, 5, 1.15, 0.4, "5 nodes per cell"},
      {0.3, 0.02, 9, 1.15, 0.4, "h1 0.3"}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    s.n_top_edges = -1;
    CHECK(hertz_scene_build_graded(&s, bad[i].h1, bad[i].h2, bad[i].npc, bad[i].growth, bad[i].fine) == 1,
          "hertz_scene_build_graded: %s accepted", bad[i].what);
    CHECK(s.n_top_edges == 0 && s.body[0].xy == NULL, "hertz_scene_build_graded: %s left *s set", bad[i].what);
  }
  CHECK(hertz_scene_build_graded(NULL, 0.02, 0.02, 8, 1.15, 0.4) == 1, "hertz_scene_build_graded: NULL scene accepted");
  /* the extremes it accepts build */
  CHECK(hertz_scene_build_graded(&s, 0.05, 0.05, 8, 3.0, 0.05) == 0, "growth 3, fine half-width h refused");
  hertz_scene_free(&s);
  CHECK(hertz_scene_build_graded(&s, 0.05, 0.05, 6, 1.01, 0.5) == 0, "growth 1.01, fine half-width 0.5 refused");
  hertz_scene_free(&s);
  hertz_scene_free(NULL);

  double a, p0;
  hertz_analytic(&a, &p0);
  printf("Hertz: a = %.10f, p0 = %.10f\n", a, p0);

  if (argc > 2) {
    for (int i = 1; i + 1 < argc; i += 2) {
      check_scene(atof(argv[i]), atof(argv[i + 1]), 0);
      check_scene(atof(argv[i]), atof(argv[i + 1]), 1);
    }
  } else {
    const double h[][2] = {{0.2, 0.2}, {0.1, 0.137}, {0.05, 0.05}, {0.02, 0.02}, {0.02, 0.0274},
                           {0.01, 0.0137}, {0.005, 0.00685}, {0.0008, 0.0008}, {0.0008, 0.001096}};
    for (size_t i = 0; i < sizeof h / sizeof h[0]; ++i)
      for (int quads = 0; quads < 2; ++quads) check_scene(h[i][0], h[i][1], quads);
  }
  /* quadratic scenes: at the first size pair given (or 0.1, 0.137) */
  for (int npc = 6; npc <= 9; npc += npc == 6 ? 2 : 1)
    check_quadratic_scene(argc > 2 ? atof(argv[1]) : 0.1, argc > 2 ? atof(argv[2]) : 0.137, npc);
  printf(failures ? "%d FAILURES\n" : "all checks passed\n", failures);
  return failures != 0;
}
