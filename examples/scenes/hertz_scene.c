/*
 * hertz_scene.c - graded meshes of the shared Hertz scene (see hertz_scene.h).
 *
 * Both bodies are logically structured grids, so one 1D grading routine builds
 * every axis:
 *   - body 2: x and y directly (tensor grid of the block);
 *   - body 1: the square coordinates (s,t) in [-1,1]x[-1,0], mapped onto the
 *     half-disc by the elliptical-grid map
 *         x = s sqrt(1 - t^2/2),   y = 1 + t sqrt(1 - s^2/2),
 *     which sends t = -1 and s = +-1 onto the arc and t = 0 onto the flat top.
 *     Near the contact point (s,t) = (0,-1) dx/ds = 1/sqrt(2) and dy/dt = 1,
 *     hence the square spacing hs = sqrt(2) h1 gives the physical arc spacing h1.
 *
 * bench/getfem_hertz.py mirrors this construction in numpy; keep them in step.
 */
#include "hertz_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The grading of hertz_scene_build_cells (hertz_scene_build_graded takes others). */
#define GROWTH 1.15          /* ratio of successive cells outside the fine zone */
#define FINE_HALF_WIDTH 0.4  /* physical half-width of the uniformly fine zone */
#define MAX_SCALED_CELLS 8   /* how many of the last growth cells absorb the length mismatch */
#define PI 3.14159265358979323846 /* M_PI is not C99 */

/*
 * Positions 0 = p[0] < ... < p[n] = len of a graded 1D grid: n_u uniform cells
 * of size w/n_u (n_u = round(w/h), so the fine zone ends exactly at w), then
 * cells growing by `growth`. A pure geometric sequence almost never ends exactly
 * at len, so the last few cells are rescaled: only the coarse tail moves and the
 * fine zone plus the first growth cells keep their exact sizes.
 * Returns NULL on allocation failure; *n receives the number of cells.
 */
static double *graded_axis(double w, double h, double len, double growth, int *n)
{
  int n_u = (int)floor(w / h + 0.5);
  if (n_u < 1) n_u = 1;
  const double hu = w / n_u;
  const double rest = len - w;

  /* N_hi: first count of growth cells whose total reaches the rest. */
  int n_hi = 0;
  double s_hi = 0.0, a = hu;
  while (s_hi < rest) { a *= growth; s_hi += a; ++n_hi; }
  const double s_lo = s_hi - a; /* total of n_hi - 1 cells, < rest */

  /* The nearer of the two totals distorts the tail least; shrinking (n_hi) can
     however make a rescaled cell smaller than its predecessor on very coarse
     grids, and then growing (n_hi - 1, scale factor >= 1) is always monotone. */
  int n_g = (n_hi > 1 && rest - s_lo < s_hi - rest) ? n_hi - 1 : n_hi;
  double *d = NULL;
  for (int attempt = 0; attempt < 2; ++attempt) {
    free(d);
    d = malloc((size_t)n_g * sizeof *d);
    if (!d) return NULL;
    double total = 0.0, c = hu;
    for (int k = 0; k < n_g; ++k) { c *= growth; d[k] = c; total += c; }
    const int m = n_g < MAX_SCALED_CELLS ? n_g : MAX_SCALED_CELLS;
    double tail = 0.0;
    for (int k = n_g - m; k < n_g; ++k) tail += d[k];
    const double scale = (rest - (total - tail)) / tail;
    for (int k = n_g - m; k < n_g; ++k) d[k] *= scale;
    int monotone = d[0] >= hu;
    for (int k = 1; k < n_g; ++k) monotone = monotone && d[k] >= d[k - 1];
    if (monotone || n_g == n_hi - 1 || n_hi == 1) break;
    n_g = n_hi - 1;
  }

  *n = n_u + n_g;
  double *p = malloc((size_t)(*n + 1) * sizeof *p);
  if (!p) { free(d); return NULL; }
  for (int i = 0; i < n_u; ++i) p[i] = i * hu;
  p[n_u] = w;
  for (int k = 0; k < n_g; ++k) p[n_u + k + 1] = p[n_u + k] + d[k];
  p[*n] = len; /* exact end, whatever the rounding of the sum */
  free(d);
  return p;
}

/* Symmetric axis on [-len, len] with 0 a node: mirrored exactly so the mesh is
   symmetric bit for bit. Returns 2n+1 positions, *n_cells = 2n. */
static double *symmetric_axis(double w, double h, double len, double growth, int *n_cells)
{
  int n;
  double *p = graded_axis(w, h, len, growth, &n);
  if (!p) return NULL;
  double *x = malloc((size_t)(2 * n + 1) * sizeof *x);
  if (x) {
    x[n] = 0.0;
    for (int k = 1; k <= n; ++k) { x[n + k] = p[k]; x[n - k] = -p[k]; }
    *n_cells = 2 * n;
  }
  free(p);
  return x;
}

/* The positions p[0..n] with the parameter midpoint of each cell inserted: 2n + 1 positions (the
   lattice of a quadratic grid, whose mid-edge nodes then sit at the middle of each cell's
   parameter interval and on the mapped curves). order 1: a copy. */
static double *refined_axis(const double *p, int n, int order)
{
  double *r = malloc((size_t)(order * n + 1) * sizeof *r);
  if (!r) return NULL;
  for (int k = 0; k <= n; ++k) {
    r[order * k] = p[k];
    if (order == 2 && k < n) r[2 * k + 1] = 0.5 * (p[k] + p[k + 1]);
  }
  return r;
}

/*
 * Cells of an (nx x ny)-cell structured grid of any kind (npc = 3, 4, 6, 8, 9) on its lattice of
 * (order nx + 1) x (order ny + 1) points, point (I,J) = J*(order nx+1)+I, counter-clockwise as
 * long as the grid maps (I,J) orientation-preservingly; quadratic cells list their mid-edge
 * nodes (and Q9 its centre) in Gmsh's order. Triangles as grid_cells below. A Q8 grid leaves
 * the cells' centres unused (compact_lattice drops them).
 */
static int *lattice_cells(int nx, int ny, int npc, int flip_i, int flip_j, int *n_cells)
{
  const int quads = npc == 4 || npc == 8 || npc == 9, o = npc > 4 ? 2 : 1, row = o * nx + 1;
  *n_cells = quads ? nx * ny : 2 * nx * ny;
  int *c = malloc((size_t)*n_cells * npc * sizeof *c);
  if (!c) return NULL;
  int *q = c;
#define P(I, J) ((J) * row + (I))
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int I = o * i, J = o * j;
      const int ll = P(I, J), lr = P(I + o, J), ul = P(I, J + o), ur = P(I + o, J + o);
      if (quads) {
        q[0] = ll; q[1] = lr; q[2] = ur; q[3] = ul;
        if (o == 2) {
          q[4] = P(I + 1, J); q[5] = P(I + 2, J + 1); q[6] = P(I + 1, J + 2); q[7] = P(I, J + 1);
          if (npc == 9) q[8] = P(I + 1, J + 1);
        }
        q += npc;
      } else if (i == flip_i && j == flip_j) { /* (ll, lr, ul) and (lr, ur, ul) */
        q[0] = ll; q[1] = lr; q[2] = ul;
        if (o == 2) { q[3] = P(I + 1, J); q[4] = P(I + 1, J + 1); q[5] = P(I, J + 1); }
        q += npc;
        q[0] = lr; q[1] = ur; q[2] = ul;
        if (o == 2) { q[3] = P(I + 2, J + 1); q[4] = P(I + 1, J + 2); q[5] = P(I + 1, J + 1); }
        q += npc;
      } else { /* (ll, lr, ur) and (ll, ur, ul) */
        q[0] = ll; q[1] = lr; q[2] = ur;
        if (o == 2) { q[3] = P(I + 1, J); q[4] = P(I + 2, J + 1); q[5] = P(I + 1, J + 1); }
        q += npc;
        q[0] = ll; q[1] = ur; q[2] = ul;
        if (o == 2) { q[3] = P(I + 1, J + 1); q[4] = P(I + 1, J + 2); q[5] = P(I, J + 1); }
        q += npc;
      }
    }
#undef P
  return c;
}

/* Drops the lattice points no cell uses (a Q8 cell's centre) and renumbers the cells; new_id
   (n_points long) receives the map, -1 for a dropped point. Returns the number kept. */
static int compact_lattice(hertz_mesh *m, int *new_id)
{
  const int n_points = m->n_nodes;
  for (int k = 0; k < n_points; ++k) new_id[k] = -1;
  for (int k = 0; k < m->n_cells * m->nodes_per_cell; ++k) new_id[m->cells[k]] = 0;
  int n = 0;
  for (int k = 0; k < n_points; ++k)
    if (new_id[k] == 0) {
      new_id[k] = n;
      m->xy[2 * n] = m->xy[2 * k], m->xy[2 * n + 1] = m->xy[2 * k + 1];
      ++n;
    }
  for (int k = 0; k < m->n_cells * m->nodes_per_cell; ++k) m->cells[k] = new_id[m->cells[k]];
  m->n_nodes = n;
  return n;
}

/* Appends the edge (a,b) to e if both ends satisfy |x| <= xmax. */
static void add_if_inside(int *e, int *n, const double *xy, int a, int b, double xmax)
{
  if (fabs(xy[2 * a]) <= xmax && fabs(xy[2 * b]) <= xmax) {
    e[2 * *n] = a; e[2 * *n + 1] = b; ++*n;
  }
}

/* Renumbers a list of lattice ids through new_id (compact_lattice's map). */
static void renumber(int *ids, int n, const int *new_id)
{
  for (int k = 0; k < n; ++k) ids[k] = new_id[ids[k]];
}

static int build_block(hertz_scene *sc, double h2, int npc, double growth, double fine)
{
  hertz_mesh *m = &sc->body[1];
  const int o = npc > 4 ? 2 : 1;
  int nx, ny;
  double *x0 = symmetric_axis(fine, h2, 4.0, growth, &nx);
  double *p0 = graded_axis(fine, h2, 4.0, growth, &ny);
  double *x = x0 ? refined_axis(x0, nx, o) : NULL, *p = p0 ? refined_axis(p0, ny, o) : NULL;
  int *new_id = NULL;
  int rc = 1;
  if (!x || !p) goto done;
  const int nI = o * nx + 1, nJ = o * ny + 1;

  m->n_nodes = nI * nJ;
  m->xy = malloc((size_t)m->n_nodes * 2 * sizeof *m->xy);
  if (!m->xy) goto done;
  for (int J = 0; J < nJ; ++J) {
    /* graded_axis runs from the fine end (y = 0) down to y = -4 */
    const double y = J == nJ - 1 ? 0.0 : -p[nJ - 1 - J];
    for (int I = 0; I < nI; ++I) {
      m->xy[2 * (J * nI + I)] = x[I];
      m->xy[2 * (J * nI + I) + 1] = y;
    }
  }
  m->nodes_per_cell = npc;
  m->cells = lattice_cells(nx, ny, npc, -1, -1, &m->n_cells);
  if (!m->cells) goto done;

  sc->bottom_nodes = malloc((size_t)nI * sizeof *sc->bottom_nodes);
  sc->contact_edges[1] = malloc((size_t)nx * 2 * sizeof *sc->contact_edges[1]);
  new_id = malloc((size_t)m->n_nodes * sizeof *new_id);
  if (!sc->bottom_nodes || !sc->contact_edges[1] || !new_id) goto done;
  sc->n_bottom_nodes = nI;
  for (int I = 0; I < nI; ++I) sc->bottom_nodes[I] = I;
  /* top edges, by their corners, oriented as the counter-clockwise boundary walk (right to left) */
  sc->n_contact_edges[1] = 0;
  const int top = (nJ - 1) * nI;
  for (int i = nx - 1; i >= 0; --i)
    add_if_inside(sc->contact_edges[1], &sc->n_contact_edges[1], m->xy, top + o * (i + 1), top + o * i, 1.0);
  if (npc == 8) { /* the cells' centres are no nodes */
    compact_lattice(m, new_id);
    renumber(sc->bottom_nodes, sc->n_bottom_nodes, new_id);
    renumber(sc->contact_edges[1], 2 * sc->n_contact_edges[1], new_id);
  }
  rc = 0;
done:
  free(x0), free(p0), free(x), free(p), free(new_id);
  return rc;
}

static int build_disc(hertz_scene *sc, double h1, int npc, double growth, double fine)
{
  hertz_mesh *m = &sc->body[0];
  const double r2 = sqrt(2.0);
  const int o = npc > 4 ? 2 : 1;
  int ns, nt;
  double *s0 = symmetric_axis(fine * r2, h1 * r2, 1.0, growth, &ns);
  double *q0 = graded_axis(fine * r2, h1 * r2, 1.0, growth, &nt); /* t = -1 + q */
  double *s = s0 ? refined_axis(s0, ns, o) : NULL, *q = q0 ? refined_axis(q0, nt, o) : NULL;
  int *new_id = NULL;
  int rc = 1;
  if (!s || !q) goto done;
  const int nI = o * ns + 1, nJ = o * nt + 1, axis = o * ns / 2;

  m->n_nodes = nI * nJ;
  m->xy = malloc((size_t)m->n_nodes * 2 * sizeof *m->xy);
  if (!m->xy) goto done;
  for (int J = 0; J < nJ; ++J) {
    const double t = J == nJ - 1 ? 0.0 : -1.0 + q[J];
    for (int I = 0; I < nI; ++I) {
      double x = s[I] * sqrt(1.0 - 0.5 * t * t);
      double y = t * sqrt(1.0 - 0.5 * s[I] * s[I]); /* relative to the centre (0,1) */
      if (J == 0 || I == 0 || I == nI - 1) {
        /* the map puts these on the circle only up to rounding; the contact
           geometry and the area check want them exactly at radius 1 (a quadratic
           mesh's mid-edge nodes too: its edges are then parabolas through three
           points of the circle) */
        const double r = hypot(x, y);
        x /= r;
        y /= r;
      }
      if (I == axis) x = 0.0; /* s = 0 gives 0 anyway; keep the axis exact by construction */
      m->xy[2 * (J * nI + I)] = x;
      m->xy[2 * (J * nI + I) + 1] = J == nJ - 1 ? 1.0 : 1.0 + y;
    }
  }
  /* At the corner (s,t) = (1,-1) the map is singular (both grid directions turn
     tangent to the arc): the default diagonal of the cell just left of it would
     make a sliver with all three vertices on the arc. The other diagonal gives
     two triangles that each use the interior vertex. At (s,t) = (-1,-1) the
     default diagonal already does so. */
  m->nodes_per_cell = npc;
  m->cells = lattice_cells(ns, nt, npc, ns - 1, 0, &m->n_cells);
  if (!m->cells) goto done;

  sc->axis_nodes = malloc((size_t)nJ * sizeof *sc->axis_nodes);
  sc->top_edges = malloc((size_t)ns * 2 * sizeof *sc->top_edges);
  sc->contact_edges[0] = malloc((size_t)(ns + 2 * nt) * 2 * sizeof *sc->contact_edges[0]);
  new_id = malloc((size_t)m->n_nodes * sizeof *new_id);
  if (!sc->axis_nodes || !sc->top_edges || !sc->contact_edges[0] || !new_id) goto done;
  sc->n_axis_nodes = nJ;
  for (int J = 0; J < nJ; ++J) sc->axis_nodes[J] = J * nI + axis;
  sc->n_top_edges = ns;
  const int top = (nJ - 1) * nI;
  for (int k = 0; k < ns; ++k) { /* right to left: counter-clockwise boundary walk */
    const int i = ns - 1 - k;
    sc->top_edges[2 * k] = top + o * (i + 1);
    sc->top_edges[2 * k + 1] = top + o * i;
  }
  /* The whole arc is t = -1 plus the sides s = +-1; the |x| <= 0.5 filter keeps
     only part of t = -1 (the sides have |x| >= 1/sqrt(2)), but testing every arc
     edge keeps the rule what the header says. Walk: left side down, bottom
     left to right, right side up. Edges by their corners. */
  int *e = sc->contact_edges[0];
  int ne = 0;
  for (int j = nt; j > 0; --j) add_if_inside(e, &ne, m->xy, o * j * nI, o * (j - 1) * nI, 0.5);
  for (int i = 0; i < ns; ++i) add_if_inside(e, &ne, m->xy, o * i, o * (i + 1), 0.5);
  for (int j = 0; j < nt; ++j) add_if_inside(e, &ne, m->xy, o * j * nI + nI - 1, o * (j + 1) * nI + nI - 1, 0.5);
  sc->n_contact_edges[0] = ne;
  if (npc == 8) {
    compact_lattice(m, new_id);
    renumber(sc->axis_nodes, sc->n_axis_nodes, new_id);
    renumber(sc->top_edges, 2 * sc->n_top_edges, new_id);
    renumber(sc->contact_edges[0], 2 * ne, new_id);
  }
  rc = 0;
done:
  free(s0), free(q0), free(s), free(q), free(new_id);
  return rc;
}

int hertz_scene_build_graded(hertz_scene *s, double h1, double h2, int nodes_per_cell, double growth,
                             double fine_half_width)
{
  if (!s) return 1;
  memset(s, 0, sizeof *s);
  /* Upper bound: coarser spacings leave no room for a graded tail in body 1
     (fine zone fine_half_width sqrt(2) of the unit square side, at most 0.5). !(a > 0) also
     rejects NaN. */
  const int npc = nodes_per_cell;
  if (!(h1 > 0.0) || !(h2 > 0.0) || h1 > 0.2 || h2 > 0.2 || (npc != 3 && npc != 4 && npc != 6 && npc != 8 && npc != 9) ||
      !(growth >= 1.01 && growth <= 3.0) || !(fine_half_width >= h1 && fine_half_width >= h2 && fine_half_width <= 0.5))
    return 1;
  if (build_disc(s, h1, npc, growth, fine_half_width) || build_block(s, h2, npc, growth, fine_half_width)) {
    hertz_scene_free(s);
    return 2;
  }
  return 0;
}

int hertz_scene_build_cells(hertz_scene *s, double h1, double h2, int nodes_per_cell)
{
  return hertz_scene_build_graded(s, h1, h2, nodes_per_cell, GROWTH, FINE_HALF_WIDTH);
}

int hertz_scene_build(hertz_scene *s, double h1, double h2, int quads)
{
  if (s && quads != 0 && quads != 1) {
    memset(s, 0, sizeof *s);
    return 1;
  }
  return hertz_scene_build_cells(s, h1, h2, quads ? 4 : 3);
}

void hertz_scene_free(hertz_scene *s)
{
  if (!s) return;
  for (int b = 0; b < 2; ++b) {
    free(s->body[b].xy);
    free(s->body[b].cells);
    free(s->contact_edges[b]);
  }
  free(s->top_edges);
  free(s->axis_nodes);
  free(s->bottom_nodes);
  memset(s, 0, sizeof *s);
}

void hertz_analytic(double *a, double *p0)
{
  const double R = 1.0, E = 1.0, nu = 0.3, P = 0.01;
  const double e_star = 1.0 / (2.0 * (1.0 - nu * nu) / E); /* plane strain, two equal bodies */
  const double a_ = sqrt(4.0 * P * R / (PI * e_star));
  if (a) *a = a_;
  if (p0) *p0 = 2.0 * P / (PI * a_);
}

/* Keeps the part x >= 0 of a mesh (x = 0 is a grid line of both bodies, so no cell straddles
   it): new[] maps old node ids to new ones (-1: dropped). Returns nonzero if a cell straddles
   the axis or on allocation failure. */
static int keep_right_half(hertz_mesh *m, int *new_id)
{
  int n = 0, c, k, kept = 0, npc = m->nodes_per_cell;
  for (k = 0; k < m->n_nodes; ++k) new_id[k] = m->xy[2 * k] >= 0.0 ? n++ : -1;
  for (c = 0; c < m->n_cells; ++c) {
    int left = 0, right = 0;
    for (k = 0; k < npc; ++k) {
      double x = m->xy[2 * m->cells[npc * c + k]];
      left += x < 0.0, right += x > 0.0;
    }
    if (left > 0 && right > 0) return 1; /* straddles the axis */
    if (left > 0) continue;
    for (k = 0; k < npc; ++k) m->cells[npc * kept + k] = new_id[m->cells[npc * c + k]];
    ++kept;
  }
  for (k = 0; k < m->n_nodes; ++k)
    if (new_id[k] >= 0) m->xy[2 * new_id[k]] = m->xy[2 * k], m->xy[2 * new_id[k] + 1] = m->xy[2 * k + 1];
  m->n_nodes = n;
  m->n_cells = kept;
  return 0;
}

/* Keeps the edges with both ends kept, renumbered. */
static int keep_edges(int *edges, int n, const int *new_id)
{
  int e, kept = 0;
  for (e = 0; e < n; ++e) {
    int a = new_id[edges[2 * e]], b = new_id[edges[2 * e + 1]];
    if (a >= 0 && b >= 0) edges[2 * kept] = a, edges[2 * kept + 1] = b, ++kept;
  }
  return kept;
}

static int keep_nodes(int *nodes, int n, const int *new_id)
{
  int k, kept = 0;
  for (k = 0; k < n; ++k)
    if (new_id[nodes[k]] >= 0) nodes[kept++] = new_id[nodes[k]];
  return kept;
}

int hertz_scene_axisymmetric(hertz_scene *s, double h1, double h2, int quads)
{
  if (s && quads != 0 && quads != 1) {
    memset(s, 0, sizeof *s);
    return 1;
  }
  return hertz_scene_axisymmetric_cells(s, h1, h2, quads ? 4 : 3);
}

int hertz_scene_axisymmetric_cells(hertz_scene *s, double h1, double h2, int nodes_per_cell)
{
  int b, status = hertz_scene_build_cells(s, h1, h2, nodes_per_cell);
  if (status) return status;
  for (b = 0; b < 2; ++b) {
    int *new_id = malloc(sizeof(int) * (size_t)s->body[b].n_nodes);
    if (!new_id || keep_right_half(&s->body[b], new_id)) {
      free(new_id);
      hertz_scene_free(s);
      return 3;
    }
    s->n_contact_edges[b] = keep_edges(s->contact_edges[b], s->n_contact_edges[b], new_id);
    if (b == 0) {
      s->n_top_edges = keep_edges(s->top_edges, s->n_top_edges, new_id);
      s->n_axis_nodes = keep_nodes(s->axis_nodes, s->n_axis_nodes, new_id);
    } else {
      s->n_bottom_nodes = keep_nodes(s->bottom_nodes, s->n_bottom_nodes, new_id);
    }
    free(new_id);
  }
  return 0;
}

void hertz_analytic_sphere(double load, double *a, double *p0, double *approach)
{
  const double R = 1.0, E = 1.0, nu = 0.3;
  const double e_star = 1.0 / (2.0 * (1.0 - nu * nu) / E); /* two equal bodies */
  const double a_ = cbrt(3.0 * load * R / (4.0 * e_star));
  if (a) *a = a_;
  if (p0) *p0 = 3.0 * load / (2.0 * PI * a_ * a_);
  if (approach) *approach = a_ * a_ / R;
}
