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

#define GROWTH 1.15          /* ratio of successive cells outside the fine zone */
#define FINE_HALF_WIDTH 0.4  /* physical half-width of the uniformly fine zone */
#define MAX_SCALED_CELLS 8   /* how many of the last growth cells absorb the length mismatch */
#define PI 3.14159265358979323846 /* M_PI is not C99 */

/*
 * Positions 0 = p[0] < ... < p[n] = len of a graded 1D grid: n_u uniform cells
 * of size w/n_u (n_u = round(w/h), so the fine zone ends exactly at w), then
 * cells growing by GROWTH. A pure geometric sequence almost never ends exactly
 * at len, so the last few cells are rescaled: only the coarse tail moves and the
 * fine zone plus the first growth cells keep their exact sizes.
 * Returns NULL on allocation failure; *n receives the number of cells.
 */
static double *graded_axis(double w, double h, double len, int *n)
{
  int n_u = (int)floor(w / h + 0.5);
  if (n_u < 1) n_u = 1;
  const double hu = w / n_u;
  const double rest = len - w;

  /* N_hi: first count of growth cells whose total reaches the rest. */
  int n_hi = 0;
  double s_hi = 0.0, a = hu;
  while (s_hi < rest) { a *= GROWTH; s_hi += a; ++n_hi; }
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
    for (int k = 0; k < n_g; ++k) { c *= GROWTH; d[k] = c; total += c; }
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
static double *symmetric_axis(double w, double h, double len, int *n_cells)
{
  int n;
  double *p = graded_axis(w, h, len, &n);
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

/*
 * Cells of an (nx x ny)-cell structured grid with node (i,j) = j*(nx+1)+i,
 * counter-clockwise as long as the grid maps (i,j) orientation-preservingly.
 * Triangles split along lower-left/upper-right, except in the cell at
 * (flip_i, flip_j) (pass -1 for none), which is split along the other diagonal.
 */
static int *grid_cells(int nx, int ny, int quads, int flip_i, int flip_j, int *n_cells)
{
  const int npc = quads ? 4 : 3;
  *n_cells = quads ? nx * ny : 2 * nx * ny;
  int *c = malloc((size_t)*n_cells * npc * sizeof *c);
  if (!c) return NULL;
  int *q = c;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ll = j * (nx + 1) + i, lr = ll + 1, ul = ll + nx + 1, ur = ul + 1;
      if (quads) {
        q[0] = ll; q[1] = lr; q[2] = ur; q[3] = ul; q += 4;
      } else if (i == flip_i && j == flip_j) {
        q[0] = ll; q[1] = lr; q[2] = ul; q[3] = lr; q[4] = ur; q[5] = ul; q += 6;
      } else {
        q[0] = ll; q[1] = lr; q[2] = ur; q[3] = ll; q[4] = ur; q[5] = ul; q += 6;
      }
    }
  return c;
}

/* Appends the edge (a,b) to e if both ends satisfy |x| <= xmax. */
static void add_if_inside(int *e, int *n, const double *xy, int a, int b, double xmax)
{
  if (fabs(xy[2 * a]) <= xmax && fabs(xy[2 * b]) <= xmax) {
    e[2 * *n] = a; e[2 * *n + 1] = b; ++*n;
  }
}

static int build_block(hertz_scene *sc, double h2, int quads)
{
  hertz_mesh *m = &sc->body[1];
  int nx, ny;
  double *x = symmetric_axis(FINE_HALF_WIDTH, h2, 4.0, &nx);
  double *p = graded_axis(FINE_HALF_WIDTH, h2, 4.0, &ny);
  int rc = 1;
  if (!x || !p) goto done;

  m->n_nodes = (nx + 1) * (ny + 1);
  m->xy = malloc((size_t)m->n_nodes * 2 * sizeof *m->xy);
  if (!m->xy) goto done;
  for (int j = 0; j <= ny; ++j) {
    /* graded_axis runs from the fine end (y = 0) down to y = -4 */
    const double y = j == ny ? 0.0 : -p[ny - j];
    for (int i = 0; i <= nx; ++i) {
      m->xy[2 * (j * (nx + 1) + i)] = x[i];
      m->xy[2 * (j * (nx + 1) + i) + 1] = y;
    }
  }
  m->nodes_per_cell = quads ? 4 : 3;
  m->cells = grid_cells(nx, ny, quads, -1, -1, &m->n_cells);
  if (!m->cells) goto done;

  sc->bottom_nodes = malloc((size_t)(nx + 1) * sizeof *sc->bottom_nodes);
  sc->contact_edges[1] = malloc((size_t)nx * 2 * sizeof *sc->contact_edges[1]);
  if (!sc->bottom_nodes || !sc->contact_edges[1]) goto done;
  sc->n_bottom_nodes = nx + 1;
  for (int i = 0; i <= nx; ++i) sc->bottom_nodes[i] = i;
  /* top edges oriented as the counter-clockwise boundary walk (right to left) */
  sc->n_contact_edges[1] = 0;
  for (int i = nx - 1; i >= 0; --i)
    add_if_inside(sc->contact_edges[1], &sc->n_contact_edges[1], m->xy,
                  ny * (nx + 1) + i + 1, ny * (nx + 1) + i, 1.0);
  rc = 0;
done:
  free(x);
  free(p);
  return rc;
}

static int build_disc(hertz_scene *sc, double h1, int quads)
{
  hertz_mesh *m = &sc->body[0];
  const double r2 = sqrt(2.0);
  int ns, nt;
  double *s = symmetric_axis(FINE_HALF_WIDTH * r2, h1 * r2, 1.0, &ns);
  double *q = graded_axis(FINE_HALF_WIDTH * r2, h1 * r2, 1.0, &nt); /* t = -1 + q */
  int rc = 1;
  if (!s || !q) goto done;

  m->n_nodes = (ns + 1) * (nt + 1);
  m->xy = malloc((size_t)m->n_nodes * 2 * sizeof *m->xy);
  if (!m->xy) goto done;
  for (int j = 0; j <= nt; ++j) {
    const double t = j == nt ? 0.0 : -1.0 + q[j];
    for (int i = 0; i <= ns; ++i) {
      double x = s[i] * sqrt(1.0 - 0.5 * t * t);
      double y = t * sqrt(1.0 - 0.5 * s[i] * s[i]); /* relative to the centre (0,1) */
      if (j == 0 || i == 0 || i == ns) {
        /* the map puts these on the circle only up to rounding; the contact
           geometry and the area check want them exactly at radius 1 */
        const double r = hypot(x, y);
        x /= r;
        y /= r;
      }
      if (i == ns / 2) x = 0.0; /* s = 0 gives 0 anyway; keep the axis exact by construction */
      m->xy[2 * (j * (ns + 1) + i)] = x;
      m->xy[2 * (j * (ns + 1) + i) + 1] = j == nt ? 1.0 : 1.0 + y;
    }
  }
  /* At the corner (s,t) = (1,-1) the map is singular (both grid directions turn
     tangent to the arc): the default diagonal of the cell just left of it would
     make a sliver with all three vertices on the arc. The other diagonal gives
     two triangles that each use the interior vertex. At (s,t) = (-1,-1) the
     default diagonal already does so. */
  m->nodes_per_cell = quads ? 4 : 3;
  m->cells = grid_cells(ns, nt, quads, ns - 1, 0, &m->n_cells);
  if (!m->cells) goto done;

  sc->axis_nodes = malloc((size_t)(nt + 1) * sizeof *sc->axis_nodes);
  sc->top_edges = malloc((size_t)ns * 2 * sizeof *sc->top_edges);
  sc->contact_edges[0] = malloc((size_t)(ns + 2 * nt) * 2 * sizeof *sc->contact_edges[0]);
  if (!sc->axis_nodes || !sc->top_edges || !sc->contact_edges[0]) goto done;
  sc->n_axis_nodes = nt + 1;
  for (int j = 0; j <= nt; ++j) sc->axis_nodes[j] = j * (ns + 1) + ns / 2;
  sc->n_top_edges = ns;
  for (int k = 0; k < ns; ++k) { /* right to left: counter-clockwise boundary walk */
    const int i = ns - 1 - k;
    sc->top_edges[2 * k] = nt * (ns + 1) + i + 1;
    sc->top_edges[2 * k + 1] = nt * (ns + 1) + i;
  }
  /* The whole arc is t = -1 plus the sides s = +-1; the |x| <= 0.5 filter keeps
     only part of t = -1 (the sides have |x| >= 1/sqrt(2)), but testing every arc
     edge keeps the rule what the header says. Walk: left side down, bottom
     left to right, right side up. */
  int *e = sc->contact_edges[0];
  int ne = 0;
  for (int j = nt; j > 0; --j) add_if_inside(e, &ne, m->xy, j * (ns + 1), (j - 1) * (ns + 1), 0.5);
  for (int i = 0; i < ns; ++i) add_if_inside(e, &ne, m->xy, i, i + 1, 0.5);
  for (int j = 0; j < nt; ++j)
    add_if_inside(e, &ne, m->xy, j * (ns + 1) + ns, (j + 1) * (ns + 1) + ns, 0.5);
  sc->n_contact_edges[0] = ne;
  rc = 0;
done:
  free(s);
  free(q);
  return rc;
}

int hertz_scene_build(hertz_scene *s, double h1, double h2, int quads)
{
  if (!s) return 1;
  memset(s, 0, sizeof *s);
  /* Upper bound: coarser spacings leave no room for a graded tail in body 1
     (fine zone 0.4 sqrt(2) of the unit square side). !(a > 0) also rejects NaN. */
  if (!(h1 > 0.0) || !(h2 > 0.0) || h1 > 0.2 || h2 > 0.2 || (quads != 0 && quads != 1)) return 1;
  if (build_disc(s, h1, quads) || build_block(s, h2, quads)) {
    hertz_scene_free(s);
    return 2;
  }
  return 0;
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
  int b, status = hertz_scene_build(s, h1, h2, quads);
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
