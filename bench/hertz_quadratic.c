/*
 * hertz_quadratic.c - quadratic cells on the plane-strain Hertz scene: speed against error
 * (issue 21, docs/benchmarks.md "Quadratic cells: Hertz speed against error"; the record of
 * what was tried: docs/notes/quadratic-cells.md).
 *
 * The Hertz scene of examples/scenes/hertz_scene.h (hertz_scene_build_cells: graded meshes,
 * h2 = ratio * h1, body 1's arc and its mid-edge nodes on the circle) is solved with
 * MC_NORMAL_MORTAR for each cell kind (P1, Q1, T6, Q8, Q9) over a list of h1: the total force
 * 0.01 as a uniform traction on body 1's flat top, u_x = 0 on body 1's axis nodes, body 2's
 * bottom clamped (as bench/hertz_sweep.c). h1 is a cell's size: a quadratic mesh at h1 has the
 * nodes of a P1 mesh at h1 / 2.
 *
 * Measured per solve:
 *   DOFs      MC_INFO_DOFS;
 *   time      wall seconds from mc_create to the results read back, median of --repeat runs
 *             (threads: the library's default, automatic);
 *   p0        the largest contact pressure (mc_get_contact_pressure) over every contact
 *             position (a quadratic body 1: the multiplier field, P1 on the corners, linear at
 *             the middles);
 *   a         contact_half_width below (bench/hertz_sweep.c's estimator) over the positions
 *             that carry the multiplier: all of them for P1 and Q1 and with --multiplier
 *             quadratic, the cells' corners for T6, Q8 and Q9 with linear multipliers (a middle's pressure is its corners' mean, and p^2 extrapolated through
 *             a corner and a middle scatters by tens of %; the all-positions value is in the
 *             JSON as a_all_positions);
 *   a_moment  2 sqrt(sum f_j x_j^2 / sum f_j) from the contact forces (exact for Hertz's
 *             elliptical distribution);
 *   W         MC_INFO_STRAIN_ENERGY (1/2 u^T K u over both bodies).
 * Errors against a reference solution of this same scene (--ref KIND:h1, default Q9 at 0.0025,
 * solved first; the fine solutions of --check are compared with it to show how converged it
 * is) and, for p0 and a, against Hertz's closed form (hertz_analytic, the half-space answer,
 * which the finite bodies miss by 0.1-0.2 %):
 *   p0, a     relative errors; the reference a is the reference's a_moment (contact_half_width
 *             itself scatters by +-0.5 % at the finest sizes);
 *   p L2      || p_h - p_ref ||_L2 / || p_ref ||_L2, each profile the piecewise-linear
 *             interpolant in x (undeformed) of its nodal pressures, over the contact surface
 *             |x| <= 0.5 (both vanish outside the contact zone), integrated exactly (Simpson on
 *             the union of both profiles' nodes);
 *   energy (local)  the energy-norm error of the displacements over the box `region`
 *             (|x|, |y| <= 0.3 about the contact point, inside both meshes' uniformly fine
 *             zones): sqrt(int e(u_h - u_ref) : C : e(u_h - u_ref) / int e(u_ref) : C : e(u_ref)),
 *             see local_energy();
 *   energy (global W)  sqrt(|W_h - W_ref| / W_ref): for a Galerkin solution of linear
 *             elasticity the relative energy-norm error over both bodies
 *             (a(u - u_h, u - u_h) = a(u,u) - a(u_h,u_h)), approximately so with contact. On
 *             these graded meshes it levels off (their outer cells, about 0.5, do not shrink
 *             with h1), hence the local measure.
 * Rates: log-log slopes between successive sizes of a kind and least squares over all of its
 * sizes, against h1 and against DOFs (e ~ DOFs^-k reported as k). At equal error: the DOFs and
 * time from which on each kind's error stays below a level, and their ratios to P1's.
 *
 * usage: hertz_quadratic [--repeat n] [--ratio r] [--ref KIND:h1] [--check KIND:h1 ...]
 *                        [--json file] [--quick] [--global]
 *                        [--multiplier linear|quadratic] [--method mortar|dual] [--growth KIND:g] [--fine KIND:w] [KIND:h1,h1,... ...]
 *   --multiplier linear|quadratic: MC_OPTION_MULTIPLIER of the solves (the reference: linear);
 *   --method dual: T6, Q8 and Q9 by MC_METHOD_DUAL_MORTAR (their quadratic trace's dual basis;
 *   P1, Q1 and the reference keep MC_METHOD_MORTAR);
 *   --growth KIND:g, --fine KIND:w: that kind's meshes with growth g outside a fine zone of
 *   half-width w (hertz_scene_build_graded; defaults 1.15 and 0.4, the reference's always);
 *   --global: the energy error over both bodies whole instead of the box around the contact, and
 *   beside it MC_INFO_ERROR_ESTIMATE and its effectivity (estimate / error)
 *   KIND: P1, Q1, T6, Q8, Q9; a size is an h1 or a geometric range from..to/n (n sizes, e.g.
 *   P1:0.03..0.0025/29: the dense sampling of docs/benchmarks.md, where "from which on the error
 *   stays below" is not set by where a few sizes happen to fall). Defaults: see default_runs below (about 70 s with --repeat 5,
 *   1.6 GB peak for the reference). --quick: two coarse sizes of each kind against a coarse
 *   reference, one run each (ctest bench_hertz_quadratic_quick: that the program runs, 0.2 s;
 *   its numbers mean nothing). Exit status 1 if a solve failed or a measure is not finite.
 */
#define _POSIX_C_SOURCE 200809L
#include "cell_kind_name.h"
#include "bench_timing.h"
#include "contact_half_width.h"
#include "hertz_model.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_REPEAT 15

/* --multiplier: MC_OPTION_MULTIPLIER of every solve but the reference's (always the default,
   MC_MULTIPLIER_LINEAR, so that runs with either value share one reference). */
static int multiplier = MC_MULTIPLIER_LINEAR;
/* --method dual: the quadratic kinds (T6, Q8, Q9; not the reference) by MC_METHOD_DUAL_MORTAR,
   the dual basis of their quadratic trace; P1 and Q1 keep the paper's mortar. */
static int dual = 0;
/* --growth KIND:g: the meshes' growth outside the fine zone per cell kind (hertz_scene_build_graded;
   the reference keeps the default 1.15). Indexed by nodes per cell. */
static double growth_of[10] = {1.15, 1.15, 1.15, 1.15, 1.15, 1.15, 1.15, 1.15, 1.15, 1.15};
/* --fine KIND:w: the half-width of the uniformly fine zone per cell kind (default 0.4; the
   reference keeps 0.4). */
static double fine_of[10] = {0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4};
#define MAX_RUNS 96

typedef struct solution {
  int npc;
  double h1;
  int ok;
  char message[256];
  long dofs, positions, active, iterations;
  double t_wall, t_library;
  double p0, a_moment, energy, force_sum;
  double a;        /* contact_half_width over every contact position */
  double a_vertex; /* contact_half_width over the corner positions (the reported a) */
  int n;           /* contact positions, sorted by x */
  double *x, *p;   /* undeformed x and pressure of each */
  char *vertex;    /* whether each is a cell corner (a multiplier node of a quadratic body 1) */
  double *u[2];  /* displacements, kept until the local error is measured */
  double local_err2, local_ref2; /* local_energy() against the reference */
  double estimate;               /* MC_INFO_ERROR_ESTIMATE (relative) */
  long far_points;
} solution;

static int kind_npc(const char *s, size_t len) {
  static const char *names[] = {"P1", "Q1", "T6", "Q8", "Q9"};
  static const int npc[] = {3, 4, 6, 8, 9};
  for (int k = 0; k < 5; ++k)
    if (len == 2 && !strncmp(s, names[k], 2)) return npc[k];
  return 0;
}

/* contact_half_width(): bench/contact_half_width.h, the Hertz benchmarks' estimator. */

/* The piecewise-linear interpolant of (x, p) (x sorted) at t; 0 outside [x_0, x_n-1]. */
static double interpolate(int n, const double *x, const double *p, double t) {
  if (n == 0 || t < x[0] || t > x[n - 1]) return 0;
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (x[mid] <= t) lo = mid;
    else hi = mid;
  }
  if (x[hi] == x[lo]) return p[lo];
  double w = (t - x[lo]) / (x[hi] - x[lo]);
  return (1 - w) * p[lo] + w * p[hi];
}

static int compare_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* || p_a - p_b ||_L2 over [-half, half] and || p_b ||_L2 there: both interpolants are linear
   between consecutive points of the union of their nodes, so Simpson's rule is exact. */
static void profile_l2(const solution *a, const solution *b, double half, double *diff, double *norm_b) {
  int n = a->n + b->n + 2, m = 0;
  double *t = malloc(sizeof(double) * n);
  t[m++] = -half, t[m++] = half;
  for (int j = 0; j < a->n; ++j)
    if (fabs(a->x[j]) < half) t[m++] = a->x[j];
  for (int j = 0; j < b->n; ++j)
    if (fabs(b->x[j]) < half) t[m++] = b->x[j];
  qsort(t, m, sizeof(double), compare_double);
  double d2 = 0, b2 = 0;
  for (int k = 0; k + 1 < m; ++k) {
    double l = t[k + 1] - t[k];
    if (l <= 0) continue;
    double s[3] = {t[k], 0.5 * (t[k] + t[k + 1]), t[k + 1]}, w[3] = {1, 4, 1};
    for (int q = 0; q < 3; ++q) {
      double pa = interpolate(a->n, a->x, a->p, s[q]), pb = interpolate(b->n, b->x, b->p, s[q]);
      d2 += l / 6 * w[q] * (pa - pb) * (pa - pb);
      b2 += l / 6 * w[q] * pb * pb;
    }
  }
  free(t);
  *diff = sqrt(d2), *norm_b = sqrt(b2);
}

/* ---- the local energy-norm error against the reference (see the file header) ---------- */

/* Shape functions of the five kinds at (xi, eta) and their derivatives, in the library's (Gmsh's)
   node order: triangles on (0,0) (1,0) (0,1), then the middles of edges 0-1, 1-2, 2-0;
   quadrilaterals on [-1,1]^2 with corners (-1,-1) (1,-1) (1,1) (-1,1), then the middles of
   edges 0-1, 1-2, 2-3, 3-0, then (Q9) the centre. */
static void shapes(int npc, double xi, double eta, double *n, double *dxi, double *deta) {
  static const double cx[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0}, cy[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};
  if (npc == 3) {
    n[0] = 1 - xi - eta, n[1] = xi, n[2] = eta;
    dxi[0] = -1, dxi[1] = 1, dxi[2] = 0, deta[0] = -1, deta[1] = 0, deta[2] = 1;
  } else if (npc == 6) {
    const double l[3] = {1 - xi - eta, xi, eta}, lx[3] = {-1, 1, 0}, ly[3] = {-1, 0, 1};
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      n[a] = l[a] * (2 * l[a] - 1), dxi[a] = (4 * l[a] - 1) * lx[a], deta[a] = (4 * l[a] - 1) * ly[a];
      n[3 + a] = 4 * l[a] * l[b], dxi[3 + a] = 4 * (lx[a] * l[b] + l[a] * lx[b]);
      deta[3 + a] = 4 * (ly[a] * l[b] + l[a] * ly[b]);
    }
  } else if (npc == 4) {
    for (int a = 0; a < 4; ++a) {
      n[a] = 0.25 * (1 + xi * cx[a]) * (1 + eta * cy[a]);
      dxi[a] = 0.25 * cx[a] * (1 + eta * cy[a]), deta[a] = 0.25 * cy[a] * (1 + xi * cx[a]);
    }
  } else if (npc == 8) {
    for (int a = 0; a < 4; ++a) {
      const double gx = 1 + xi * cx[a], gy = 1 + eta * cy[a], sum = xi * cx[a] + eta * cy[a] - 1;
      n[a] = 0.25 * gx * gy * sum, dxi[a] = 0.25 * cx[a] * gy * (sum + gx), deta[a] = 0.25 * cy[a] * gx * (sum + gy);
    }
    for (int a = 4; a < 8; ++a)
      if (cx[a] == 0) {
        n[a] = 0.5 * (1 - xi * xi) * (1 + eta * cy[a]);
        dxi[a] = -xi * (1 + eta * cy[a]), deta[a] = 0.5 * (1 - xi * xi) * cy[a];
      } else {
        n[a] = 0.5 * (1 + xi * cx[a]) * (1 - eta * eta);
        dxi[a] = 0.5 * cx[a] * (1 - eta * eta), deta[a] = -eta * (1 + xi * cx[a]);
      }
  } else { /* 9: tensor products of the 1D quadratic Lagrange shapes on -1, 0, 1 */
    double lx[3] = {0.5 * xi * (xi - 1), 1 - xi * xi, 0.5 * xi * (xi + 1)}, dlx[3] = {xi - 0.5, -2 * xi, xi + 0.5};
    double ly[3] = {0.5 * eta * (eta - 1), 1 - eta * eta, 0.5 * eta * (eta + 1)}, dly[3] = {eta - 0.5, -2 * eta, eta + 0.5};
    for (int a = 0; a < 9; ++a) {
      const int i = (int)cx[a] + 1, j = (int)cy[a] + 1;
      n[a] = lx[i] * ly[j], dxi[a] = dlx[i] * ly[j], deta[a] = lx[i] * dly[j];
    }
  }
}

static int triangle(int npc) { return npc == 3 || npc == 6; }

/* The isoparametric map of a cell at (xi, eta): the point, det J and the shapes' x, y gradients. */
static double cell_map(const hertz_mesh *m, int c, double xi, double eta, double *x, double *y, double *gx, double *gy) {
  const int npc = m->nodes_per_cell, *v = m->cells + (size_t)npc * c;
  double n[9], dxi[9], deta[9], j00 = 0, j01 = 0, j10 = 0, j11 = 0;
  shapes(npc, xi, eta, n, dxi, deta);
  *x = *y = 0;
  for (int a = 0; a < npc; ++a) {
    const double px = m->xy[2 * v[a]], py = m->xy[2 * v[a] + 1];
    *x += n[a] * px, *y += n[a] * py;
    j00 += dxi[a] * px, j01 += deta[a] * px, j10 += dxi[a] * py, j11 += deta[a] * py;
  }
  const double det = j00 * j11 - j01 * j10;
  if (gx)
    for (int a = 0; a < npc; ++a) gx[a] = (j11 * dxi[a] - j10 * deta[a]) / det, gy[a] = (-j01 * dxi[a] + j00 * deta[a]) / det;
  return det;
}

/* Engineering strain (xx, yy, 2xy) of displacement u in cell c at (xi, eta). */
static void cell_strain(const hertz_mesh *m, const double *u, int c, double xi, double eta, double e[3]) {
  const int npc = m->nodes_per_cell, *v = m->cells + (size_t)npc * c;
  double gx[9], gy[9], x, y;
  cell_map(m, c, xi, eta, &x, &y, gx, gy);
  e[0] = e[1] = e[2] = 0;
  for (int a = 0; a < npc; ++a) {
    const double ux = u[2 * v[a]], uy = u[2 * v[a] + 1];
    e[0] += ux * gx[a], e[1] += uy * gy[a], e[2] += ux * gy[a] + uy * gx[a];
  }
}

/* e^T D e, plane strain, E = 1, nu = 0.3 (both bodies). */
static double energy_density(const double e[3]) {
  const double nu = 0.3, f = 1.0 / ((1 + nu) * (1 - 2 * nu));
  return f * ((1 - nu) * (e[0] * e[0] + e[1] * e[1]) + 2 * nu * e[0] * e[1] + 0.5 * (1 - 2 * nu) * e[2] * e[2]);
}

/* How far (xi, eta) lies outside the reference cell, 0 inside. */
static double outside(int npc, double xi, double eta) {
  if (triangle(npc)) return fmax(0, fmax(fmax(-xi, -eta), xi + eta - 1));
  return fmax(0, fmax(fabs(xi) - 1, fabs(eta) - 1));
}

/* Newton on the isoparametric map: the reference coordinates of (x, y) in cell c. */
static double invert(const hertz_mesh *m, int c, double x, double y, double *xi, double *eta) {
  const int npc = m->nodes_per_cell, *v = m->cells + (size_t)npc * c;
  double s = triangle(npc) ? 1.0 / 3 : 0, t = s;
  for (int it = 0; it < 12; ++it) {
    double n[9], dxi[9], deta[9], px = 0, py = 0, j00 = 0, j01 = 0, j10 = 0, j11 = 0;
    shapes(npc, s, t, n, dxi, deta);
    for (int a = 0; a < npc; ++a) {
      const double qx = m->xy[2 * v[a]], qy = m->xy[2 * v[a] + 1];
      px += n[a] * qx, py += n[a] * qy;
      j00 += dxi[a] * qx, j01 += deta[a] * qx, j10 += dxi[a] * qy, j11 += deta[a] * qy;
    }
    const double det = j00 * j11 - j01 * j10, rx = x - px, ry = y - py;
    const double ds = (j11 * rx - j01 * ry) / det, dt = (-j10 * rx + j00 * ry) / det;
    s += ds, t += dt;
    if (fabs(ds) + fabs(dt) < 1e-14 || fabs(s) + fabs(t) > 10) break;
  }
  *xi = s, *eta = t;
  return outside(npc, s, t);
}

/* The reference's cells near the box, in buckets, for point location. */
typedef struct locator {
  const hertz_mesh *mesh;
  const double *u;
  double x0, y0, size;
  int nx, ny;
  int *start, *list;
} locator;

static void cell_box(const hertz_mesh *m, int c, double box[4]) {
  const int npc = m->nodes_per_cell, *v = m->cells + (size_t)npc * c;
  box[0] = box[2] = INFINITY, box[1] = box[3] = -INFINITY;
  for (int a = 0; a < npc; ++a) {
    const double x = m->xy[2 * v[a]], y = m->xy[2 * v[a] + 1];
    box[0] = fmin(box[0], x), box[1] = fmax(box[1], x), box[2] = fmin(box[2], y), box[3] = fmax(box[3], y);
  }
}

static int boxes_meet(const double a[4], const double b[4]) {
  return a[0] <= b[1] && b[0] <= a[1] && a[2] <= b[3] && b[2] <= a[3];
}

static void locator_build(locator *l, const hertz_mesh *m, const double *u, const double region[4]) {
  memset(l, 0, sizeof *l);
  l->mesh = m, l->u = u;
  double area = 0, box[4];
  int count = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    cell_box(m, c, box);
    if (boxes_meet(box, region)) area += (box[1] - box[0]) * (box[3] - box[2]), ++count;
  }
  l->size = count ? 1.5 * sqrt(area / count) : 1;
  l->x0 = region[0], l->y0 = region[2];
  l->nx = (int)ceil((region[1] - region[0]) / l->size) + 1, l->ny = (int)ceil((region[3] - region[2]) / l->size) + 1;
  l->start = calloc((size_t)l->nx * l->ny + 1, sizeof(int));
  for (int pass = 0; pass < 2; ++pass) {
    int *fill = pass ? calloc((size_t)l->nx * l->ny, sizeof(int)) : NULL;
    for (int c = 0; c < m->n_cells; ++c) {
      cell_box(m, c, box);
      if (!boxes_meet(box, region)) continue;
      const double pad = 1e-3 * l->size;
      int i0 = (int)floor((box[0] - pad - l->x0) / l->size), i1 = (int)floor((box[1] + pad - l->x0) / l->size);
      int j0 = (int)floor((box[2] - pad - l->y0) / l->size), j1 = (int)floor((box[3] + pad - l->y0) / l->size);
      for (int j = j0 < 0 ? 0 : j0; j <= j1 && j < l->ny; ++j)
        for (int i = i0 < 0 ? 0 : i0; i <= i1 && i < l->nx; ++i) {
          const int k = j * l->nx + i;
          if (pass) l->list[l->start[k] + fill[k]++] = c;
          else ++l->start[k + 1];
        }
    }
    if (!pass) {
      for (int k = 0; k < l->nx * l->ny; ++k) l->start[k + 1] += l->start[k];
      l->list = malloc(sizeof(int) * (size_t)(l->start[l->nx * l->ny] + 1));
    }
    free(fill);
  }
}

static void locator_free(locator *l) { free(l->start), free(l->list); }

/* The reference cell holding (x, y), or the one it lies least outside of (a point of a coarse
   curved boundary may lie a little outside the reference's); the strain there. */
static int locate_strain(const locator *l, double x, double y, double e[3]) {
  int i = (int)floor((x - l->x0) / l->size), j = (int)floor((y - l->y0) / l->size), best = -1;
  double best_out = INFINITY, bxi = 0, beta = 0;
  for (int ring = 0; ring <= 1 && best_out > 1e-10; ++ring)
    for (int jj = j - ring; jj <= j + ring; ++jj)
      for (int ii = i - ring; ii <= i + ring; ++ii) {
        if (ii < 0 || jj < 0 || ii >= l->nx || jj >= l->ny || (ring && ii != i - 1 && ii != i + 1 && jj != j - 1 && jj != j + 1))
          continue;
        const int k = jj * l->nx + ii;
        for (int q = l->start[k]; q < l->start[k + 1] && best_out > 1e-10; ++q) {
          double xi, eta, out = invert(l->mesh, l->list[q], x, y, &xi, &eta);
          if (out < best_out) best_out = out, best = l->list[q], bxi = xi, beta = eta;
        }
      }
  if (best < 0) return -1;
  cell_strain(l->mesh, l->u, best, bxi, beta, e);
  return best_out < 0.25 ? 0 : 1;
}

/* sum over both bodies of the integrals over the box of (e_h - e_ref)^T D (e_h - e_ref) and of
   e_ref^T D e_ref; each cell of the solution's mesh that meets the box is split into k x k
   squares of its reference square (a triangle through (u, v) -> (u, v (1 - u))), k about its
   size over the reference's cell size, with 3 x 3 Gauss points each; points outside the box are
   dropped. Returns the number of points located more than a quarter cell outside any reference
   cell (0 expected). */
static long local_energy(const hertz_scene *s, double *const u[2], const locator ref[2], double h_ref,
                         const double region[4], double *err2, double *ref2) {
  static const double g[3] = {0.1127016653792583, 0.5, 0.8872983346207417}, w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  long far = 0;
  *err2 = *ref2 = 0;
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *m = &s->body[b];
    const int npc = m->nodes_per_cell;
    for (int c = 0; c < m->n_cells; ++c) {
      double box[4];
      cell_box(m, c, box);
      if (!boxes_meet(box, region)) continue;
      int k = (int)ceil(fmax(box[1] - box[0], box[3] - box[2]) / h_ref);
      k = k < 1 ? 1 : k > 24 ? 24 : k;
      for (int si = 0; si < k; ++si)
        for (int sj = 0; sj < k; ++sj)
          for (int qi = 0; qi < 3; ++qi)
            for (int qj = 0; qj < 3; ++qj) {
              const double uu = (si + g[qi]) / k, vv = (sj + g[qj]) / k;
              double xi, eta, weight = w[qi] * w[qj] / (k * k);
              if (triangle(npc)) xi = uu, eta = vv * (1 - uu), weight *= 1 - uu;
              else xi = 2 * uu - 1, eta = 2 * vv - 1, weight *= 4;
              double x, y;
              const double det = cell_map(m, c, xi, eta, &x, &y, NULL, NULL);
              if (x < region[0] || x > region[1] || y < region[2] || y > region[3]) continue;
              double eh[3], er[3];
              cell_strain(m, u[b], c, xi, eta, eh);
              if (locate_strain(&ref[b], x, y, er)) ++far;
              const double d[3] = {eh[0] - er[0], eh[1] - er[1], eh[2] - er[2]};
              *err2 += weight * det * energy_density(d);
              *ref2 += weight * det * energy_density(er);
            }
    }
  }
  return far;
}


#define TRY(call)                                                                                \
  do {                                                                                           \
    if ((call) != MC_OK) {                                                                       \
      snprintf(r->message, sizeof r->message, "%s: %s", #call, m ? mc_errmsg(m) : "no model");   \
      goto done;                                                                                 \
    }                                                                                            \
  } while (0)

/* One solve (setup included in *t_wall); fills r on the last run. */
static void run_once(const hertz_scene *s, int last, solution *r, double *t_wall) {
  mc_model *m = NULL;
  mc_int n = 0, *nodes = NULL;
  double *pressure = NULL, *force = NULL, *u[2] = {NULL, NULL};
  double start = bench_wall();
  TRY(mc_create(&m));
  TRY(hertz_model_bodies(m, s));
  TRY(mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]));
  TRY(mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]));
  TRY(mc_set_option_int(m, MC_OPTION_METHOD, dual && s->body[0].nodes_per_cell > 4 ? MC_METHOD_DUAL_MORTAR : MC_METHOD_MORTAR));
  TRY(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, MC_NORMAL_MORTAR));
  TRY(mc_set_option_int(m, MC_OPTION_MULTIPLIER, multiplier));
  TRY(mc_solve(m));
  /* results read back, as a host would */
  for (int b = 0; b < 2; ++b) {
    u[b] = malloc(sizeof(double) * 2 * s->body[b].n_nodes);
    TRY(mc_get_displacement(m, b + 1, u[b]));
  }
  TRY(mc_get_contact_count(m, &n));
  nodes = malloc(sizeof(mc_int) * n);
  pressure = malloc(sizeof(double) * n), force = malloc(sizeof(double) * n);
  TRY(mc_get_contact_nodes(m, nodes));
  TRY(mc_get_contact_pressure(m, pressure));
  TRY(mc_get_contact_force(m, force));
  *t_wall = bench_wall() - start;
  if (last) {
    int64_t v;
    mc_get_info_int(m, MC_INFO_DOFS, &v), r->dofs = v;
    mc_get_info_int(m, MC_INFO_ITERATIONS, &v), r->iterations = v;
    mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &v), r->active = v;
    mc_get_info_real(m, MC_INFO_TIME_TOTAL, &r->t_library);
    mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &r->energy);
    mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &r->estimate);
    r->n = (int)n, r->positions = n;
    r->x = malloc(sizeof(double) * n), r->p = malloc(sizeof(double) * n), r->vertex = malloc((size_t)n + 1);
    char *corner = calloc((size_t)s->body[0].n_nodes, 1);
    for (int e = 0; e < 2 * s->n_contact_edges[0]; ++e) corner[s->contact_edges[0][e]] = 1;
    if (multiplier == MC_MULTIPLIER_QUADRATIC || dual) memset(corner, 1, (size_t)s->body[0].n_nodes); /* a value at every node */
    /* sorted by x (insertion sort: the positions come in order along the surface) */
    for (mc_int j = 0; j < n; ++j) {
      double xj = s->body[0].xy[2 * nodes[j]], pj = pressure[j];
      int k = (int)j;
      while (k > 0 && r->x[k - 1] > xj) r->x[k] = r->x[k - 1], r->p[k] = r->p[k - 1], r->vertex[k] = r->vertex[k - 1], --k;
      r->x[k] = xj, r->p[k] = pj, r->vertex[k] = corner[nodes[j]];
    }
    free(corner);
    {
      double *xv = malloc(sizeof(double) * n), *pv = malloc(sizeof(double) * n);
      int m_v = 0;
      for (int j = 0; j < r->n; ++j)
        if (r->vertex[j]) xv[m_v] = r->x[j], pv[m_v++] = r->p[j];
      r->a_vertex = contact_half_width(m_v, xv, pv);
      free(xv), free(pv);
    }
    r->u[0] = u[0], r->u[1] = u[1], u[0] = u[1] = NULL; /* for the local error */
    double moment = 0, sum = 0;
    r->p0 = 0;
    for (mc_int j = 0; j < n; ++j) {
      double xj = s->body[0].xy[2 * nodes[j]];
      r->p0 = fmax(r->p0, pressure[j]), sum += force[j], moment += force[j] * xj * xj;
    }
    r->force_sum = sum;
    r->a_moment = 2 * sqrt(moment / sum);
    r->a = contact_half_width(r->n, r->x, r->p);
    r->ok = 1;
  }
done:
  free(nodes), free(pressure), free(force), free(u[0]), free(u[1]);
  mc_destroy(m);
}

/* The box of the local energy error: around the contact point, inside both bodies' uniformly fine
   zones (|x| <= 0.4 and 0.4 deep, hertz_scene.c); Hertz's a = 0.152. */
static double region[4] = {-0.3, 0.3, -0.3, 0.3};

/* The reference: its scene, solution and locators (set by main before the other solves). */
static hertz_scene ref_scene;
static locator ref_locator[2];
static double ref_h1;
static int have_ref;

/* Solves r (repeat runs, median time); measures the local error against the reference if there
   is one; keeps the scene in *keep if given (the reference), else frees it. */
static void solve(solution *r, int repeat, double ratio, hertz_scene *keep) {
  hertz_scene s;
  double times[MAX_REPEAT];
  const double growth = keep ? 1.15 : growth_of[r->npc], fine = keep ? 0.4 : fine_of[r->npc];
  if (hertz_scene_build_graded(&s, r->h1, ratio * r->h1, r->npc, growth, fine) != 0) {
    snprintf(r->message, sizeof r->message, "hertz_scene_build_graded(h1 = %g, %s, growth %g) failed", r->h1,
             cell_kind_name(r->npc), growth);
    return;
  }
  for (int k = 0; k < repeat; ++k) {
    run_once(&s, k == repeat - 1, r, &times[k]);
    if (r->message[0]) break;
  }
  if (r->ok) r->t_wall = bench_median(times, repeat);
  if (r->ok && have_ref)
    r->far_points = local_energy(&s, r->u, ref_locator, ref_h1, region, &r->local_err2, &r->local_ref2);
  if (keep) {
    *keep = s;
    return;
  }
  free(r->u[0]), free(r->u[1]), r->u[0] = r->u[1] = NULL;
  hertz_scene_free(&s);
}

/* "KIND:h1,h1,..." into runs, each item an h1 or a geometric range "from..to/n" (n sizes from
   `from` to `to`, both included: a dense sampling, e.g. T6:0.06..0.005/29, 2^(1/8) apart);
   returns the number added, -1 on a bad spec. */
static int parse_spec(const char *spec, solution *runs, int room) {
  const char *colon = strchr(spec, ':');
  int npc = colon ? kind_npc(spec, (size_t)(colon - spec)) : 0, added = 0;
  if (!npc) return -1;
  const char *q = colon + 1;
  while (*q) {
    char *end;
    double h = strtod(q, &end), to = h;
    long n = 1;
    if (end == q || !(h > 0)) return -1;
    if (end[0] == '.' && end[1] == '.') {
      const char *t = end + 2;
      to = strtod(t, &end);
      if (end == t || !(to > 0) || *end != '/') return -1;
      t = end + 1;
      n = strtol(t, &end, 10);
      if (end == t || n < 2 || n > MAX_RUNS) return -1;
    }
    for (long k = 0; k < n; ++k) {
      if (added >= room) return -1;
      memset(&runs[added], 0, sizeof runs[added]);
      runs[added].npc = npc, runs[added].h1 = n == 1 ? h : h * pow(to / h, (double)k / (double)(n - 1));
      ++added;
    }
    q = *end == ',' ? end + 1 : end;
    if (*end && *end != ',') return -1;
  }
  return added;
}

static double rel(double value, double reference) { return value / reference - 1; }

static double slope(double e0, double e1, double x0, double x1) {
  if (!(e0 > 0) || !(e1 > 0)) return NAN;
  return log(e1 / e0) / log(x1 / x0);
}

/* The DOFs (and time) at which a kind's error stays at or below e: on the envelope
   E(N) = max |err| of that kind's rows with at least N DOFs ("from this size on the error stays
   below"), log-log interpolated between the two sizes where the envelope crosses e. Returns 1,
   or -1 if already below at the kind's coarsest size (its DOFs returned), 0 if never below. */
static int dofs_at_error(const solution *runs, const double *err, int n_runs, int npc, double e, double *dofs,
                         double *time) {
  int idx[MAX_RUNS], m = 0;
  for (int i = 0; i < n_runs; ++i)
    if (runs[i].ok && runs[i].npc == npc) idx[m++] = i;
  for (int i = 1; i < m; ++i) /* by DOFs */
    for (int k = i; k > 0 && runs[idx[k - 1]].dofs > runs[idx[k]].dofs; --k) {
      int t = idx[k];
      idx[k] = idx[k - 1], idx[k - 1] = t;
    }
  if (m == 0) return 0;
  double env[MAX_RUNS];
  for (int k = m - 1; k >= 0; --k) env[k] = fmax(fabs(err[idx[k]]), k + 1 < m ? env[k + 1] : 0);
  if (env[0] <= e) {
    *dofs = (double)runs[idx[0]].dofs, *time = runs[idx[0]].t_wall;
    return -1;
  }
  for (int k = 1; k < m; ++k)
    if (env[k] <= e) {
      const solution *lo = &runs[idx[k - 1]], *hi = &runs[idx[k]];
      double w = env[k] > 0 ? log(e / env[k - 1]) / log(env[k] / env[k - 1]) : 1;
      if (!(w >= 0 && w <= 1)) w = 1;
      *dofs = exp(log((double)lo->dofs) + w * (log((double)hi->dofs) - log((double)lo->dofs)));
      *time = exp(log(lo->t_wall) + w * (log(hi->t_wall) - log(lo->t_wall)));
      return 1;
    }
  return 0;
}

/* Least-squares slope of log |e| against log x over the rows of a kind (NAN if fewer than 2). */
static double fitted_slope(const solution *runs, const double *err, int n_runs, int npc, int against_dofs) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (int i = 0; i < n_runs; ++i) {
    if (!runs[i].ok || runs[i].npc != npc || !(fabs(err[i]) > 0)) continue;
    double x = log(against_dofs ? (double)runs[i].dofs : runs[i].h1), y = log(fabs(err[i]));
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++k;
  }
  return k < 2 ? NAN : (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

static double json_number(double v) { return isfinite(v) ? v : -1; }

int main(int argc, char **argv) {
  static const char *default_runs[] = {
      "P1:0.08,0.04,0.02,0.014,0.01,0.007,0.005,0.0035,0.0025",
      "Q1:0.08,0.04,0.02,0.014,0.01,0.007,0.005,0.0035,0.0025",
      "T6:0.14,0.1,0.07,0.05,0.035,0.025,0.0175,0.0125,0.00875,0.00625",
      "Q8:0.14,0.1,0.07,0.05,0.035,0.025,0.0175,0.0125,0.00875,0.00625",
      "Q9:0.14,0.1,0.07,0.05,0.035,0.025,0.0175,0.0125,0.00875,0.00625"};
  static const char *quick_runs[] = {"P1:0.08,0.04", "Q1:0.08,0.04", "T6:0.14,0.1", "Q8:0.14,0.1", "Q9:0.14,0.1"};
  static const int kinds[5] = {3, 4, 6, 8, 9};
  static solution runs[MAX_RUNS], checks[8];
  solution ref;
  memset(&ref, 0, sizeof ref);
  ref.npc = 9, ref.h1 = 0.0025;
  int n_runs = 0, n_checks = 0, repeat = 3, quick = 0, explicit_ref = 0;
  double ratio = 1.37;
  const char *json_path = NULL;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--ratio") && i + 1 < argc) ratio = atof(argv[++i]);
    else if (!strcmp(argv[i], "--json") && i + 1 < argc) json_path = argv[++i];
    else if (!strcmp(argv[i], "--quick")) quick = 1;
    else if ((!strcmp(argv[i], "--growth") || !strcmp(argv[i], "--fine")) && i + 1 < argc) {
      const int growth = !strcmp(argv[i], "--growth");
      const char *spec = argv[++i], *colon = strchr(spec, ':');
      int npc = 0;
      for (int k = 3; k <= 9; ++k)
        if (colon && colon - spec == 2 && !strncmp(spec, cell_kind_name(k), 2)) npc = k;
      const double v = colon ? atof(colon + 1) : 0;
      if (!npc || (growth && !(v >= 1.01 && v <= 3)) || (!growth && !(v > 0 && v <= 0.5))) goto usage;
      (growth ? growth_of : fine_of)[npc] = v;
    }
    else if (!strcmp(argv[i], "--method") && i + 1 < argc) {
      ++i;
      if (!strcmp(argv[i], "dual")) dual = 1;
      else if (!strcmp(argv[i], "mortar")) dual = 0;
      else goto usage;
    }
    else if (!strcmp(argv[i], "--multiplier") && i + 1 < argc) {
      ++i;
      if (!strcmp(argv[i], "linear")) multiplier = MC_MULTIPLIER_LINEAR;
      else if (!strcmp(argv[i], "quadratic")) multiplier = MC_MULTIPLIER_QUADRATIC;
      else goto usage;
    }
    else if (!strcmp(argv[i], "--global")) {
      /* the energy error over both bodies whole (for the error estimate's effectivity) */
      region[0] = -4, region[1] = 4, region[2] = -4, region[3] = 1;
    }
    else if (!strcmp(argv[i], "--ref") && i + 1 < argc) {
      if (parse_spec(argv[++i], &ref, 1) != 1) goto usage;
      explicit_ref = 1;
    } else if (!strcmp(argv[i], "--check") && i + 1 < argc) {
      int k = parse_spec(argv[++i], checks + n_checks, 8 - n_checks);
      if (k < 0) goto usage;
      n_checks += k;
    } else {
      int k = parse_spec(argv[i], runs + n_runs, MAX_RUNS - n_runs);
      if (k < 0) goto usage;
      n_runs += k;
    }
  }
  if (repeat < 1 || repeat > MAX_REPEAT) goto usage;
  if (quick) {
    if (!explicit_ref) ref.npc = 8, ref.h1 = 0.035;
    repeat = 1;
  }
  if (n_runs == 0) {
    const char **list = quick ? quick_runs : default_runs;
    for (int k = 0; k < 5; ++k) n_runs += parse_spec(list[k], runs + n_runs, MAX_RUNS - n_runs);
  }
  if (n_checks == 0 && !quick) {
    n_checks += parse_spec("Q8:0.0025", checks + n_checks, 1);
    n_checks += parse_spec("Q9:0.0035", checks + n_checks, 1);
    n_checks += parse_spec("P1:0.00125", checks + n_checks, 1);
  }

  double a_hertz, p0_hertz;
  hertz_analytic(&a_hertz, &p0_hertz);
  printf("Hertz scene (hertz_scene_build_cells), MC_METHOD_MORTAR, MC_NORMAL_MORTAR, h2 = %g h1, %ld cores, "
         "OPENBLAS_NUM_THREADS=%s, time: median of %d runs\n",
         ratio, sysconf(_SC_NPROCESSORS_ONLN), getenv("OPENBLAS_NUM_THREADS") ? getenv("OPENBLAS_NUM_THREADS") : "unset",
         repeat);
  printf("Hertz (half-space): p0 = %.8g, a = %.8g\n\n", p0_hertz, a_hertz);
  fflush(stdout);

  /* the reference, then the checks against it */
  const int requested_multiplier = multiplier, requested_dual = dual;
  multiplier = MC_MULTIPLIER_LINEAR, dual = 0;
  solve(&ref, 1, ratio, &ref_scene);
  multiplier = requested_multiplier, dual = requested_dual;
  if (!ref.ok) {
    printf("reference %s h1 = %g failed: %s\n", cell_kind_name(ref.npc), ref.h1, ref.message);
    return 1;
  }
  {
    const double margin[4] = {region[0] - 0.05, region[1] + 0.05, region[2] - 0.05, region[3] + 0.05};
    for (int b = 0; b < 2; ++b) locator_build(&ref_locator[b], &ref_scene.body[b], ref.u[b], margin);
    ref_h1 = ref.h1, have_ref = 1;
  }
  /* the reference half-width: the second moment of its contact forces (the most stable of the
     estimators, see the notes) */
  const double a_ref = ref.a_moment;
  printf("Reference: %s h1 = %g, %ld DOFs, %.2f s: p0 = %.8g (%+.3f %% from Hertz), a_moment = %.8g (%+.3f %%; the "
         "reference a), contact_half_width over the corners %.8g (%+.3f %%), over every position %.8g (%+.3f %%), "
         "W = %.10g\n",
         cell_kind_name(ref.npc), ref.h1, ref.dofs, ref.t_wall, ref.p0, 100 * rel(ref.p0, p0_hertz), ref.a_moment,
         100 * rel(ref.a_moment, a_hertz), ref.a_vertex, 100 * rel(ref.a_vertex, a_hertz), ref.a,
         100 * rel(ref.a, a_hertz), ref.energy);
  if (n_checks)
    printf("\nOther fine solutions against the reference:\n\n"
           "| kind | h1 | DOFs | time s | p0 | a (contact_half_width) | a_moment | p L2 | energy (local) | W |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n");
  for (int c = 0; c < n_checks; ++c) {
    solution *r = &checks[c];
    solve(r, 1, ratio, NULL);
    if (!r->ok) {
      printf("| %s | %g | FAILED: %s |\n", cell_kind_name(r->npc), r->h1, r->message);
      continue;
    }
    double d, nb;
    profile_l2(r, &ref, 0.5, &d, &nb);
    printf("| %s | %g | %ld | %.2f | %+.4f %% | %+.2f %% | %+.4f %% | %.2e | %.2e | %+.2e |\n", cell_kind_name(r->npc), r->h1,
           r->dofs, r->t_wall, 100 * rel(r->p0, ref.p0), 100 * rel(r->a_vertex, a_ref), 100 * rel(r->a_moment, a_ref),
           d / nb, sqrt(r->local_err2 / r->local_ref2), rel(r->energy, ref.energy));
    fflush(stdout);
  }
  printf("\n");

  FILE *json = json_path ? fopen(json_path, "w") : NULL;
  if (json) fprintf(json, "[\n");
  static double err_p0[MAX_RUNS], err_a[MAX_RUNS], err_am[MAX_RUNS], err_l2[MAX_RUNS], err_energy[MAX_RUNS],
      err_w[MAX_RUNS];
  printf("| kind | h1 | DOFs | time s | p0 err vs ref | p0 err vs Hertz | a err vs ref | a err vs Hertz | "
         "a_moment err vs ref | p L2 err | energy err (local) | energy err (global W) |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int failed = 0;
  for (int i = 0; i < n_runs; ++i) {
    solution *r = &runs[i];
    solve(r, repeat, ratio, NULL);
    if (!r->ok) {
      printf("| %s | %g | FAILED: %s |\n", cell_kind_name(r->npc), r->h1, r->message);
      failed = 1;
      continue;
    }
    double d, nb;
    profile_l2(r, &ref, 0.5, &d, &nb);
    err_p0[i] = rel(r->p0, ref.p0), err_a[i] = rel(r->a_vertex, a_ref), err_am[i] = rel(r->a_moment, a_ref);
    err_l2[i] = d / nb, err_energy[i] = sqrt(r->local_err2 / r->local_ref2);
    err_w[i] = sqrt(fabs(r->energy - ref.energy) / ref.energy);
    if (!isfinite(err_p0[i]) || !isfinite(err_energy[i]) || r->far_points) failed = 1;
    printf("| %s | %g | %ld | %.4f | %+.3f %% | %+.3f %% | %+.2f %% | %+.2f %% | %+.3f %% | %.2e | %.2e | %.2e |\n",
           cell_kind_name(r->npc), r->h1, r->dofs, r->t_wall, 100 * err_p0[i], 100 * rel(r->p0, p0_hertz), 100 * err_a[i],
           100 * rel(r->a_vertex, a_hertz), 100 * err_am[i], err_l2[i], err_energy[i], err_w[i]);
    if (region[0] == -4) {
      /* --global: the estimate against the energy error of both bodies (relative to the
         reference's energy norm; the estimate's own normalization is sqrt(2W + eta^2), the same
         to the error's second order) */
      printf("|  | estimate %.3e | effectivity %.3f |\n", r->estimate, r->estimate / err_energy[i]);
    }
    fflush(stdout);
    if (json) {
      fprintf(json,
              "%s {\"kind\": \"%s\", \"h1\": %.17g, \"h2\": %.17g, \"dofs\": %ld, \"positions\": %ld, \"active\": %ld, "
              "\"iterations\": %ld, \"time\": %.6g, \"time_library\": %.6g, \"p0\": %.17g, \"a\": %.17g, "
              "\"a_all_positions\": %.17g, \"a_moment\": %.17g, \"energy\": %.17g, "
              "\"force_sum\": %.17g, \"err_p0\": %.6g, \"err_a\": %.6g, \"err_a_moment\": %.6g, \"err_l2\": %.6g, "
              "\"err_energy_local\": %.6g, \"err_energy_global\": %.6g, \"far_points\": %ld, \"repeat\": %d}",
              i ? ",\n" : "", cell_kind_name(r->npc), r->h1, ratio * r->h1, r->dofs, r->positions, r->active, r->iterations,
              r->t_wall, r->t_library, r->p0, json_number(r->a_vertex), json_number(r->a), r->a_moment,
              r->energy, r->force_sum, err_p0[i], json_number(err_a[i]), err_am[i], err_l2[i],
              err_energy[i], err_w[i], r->far_points, repeat);
      fflush(json);
    }
  }
  if (json) fprintf(json, "\n]\n"), fclose(json);

  /* rates: between successive sizes of each kind (in the order given), then least squares */
  const double *errs[5] = {err_p0, err_a, err_am, err_l2, err_energy};
  printf("\nRates: log-log slopes of |error| between successive sizes, against h1 / against DOFs "
         "(e ~ h1^k / e ~ DOFs^-k: k)\n\n"
         "| kind | h1 | DOFs | p0 | a | a_moment | p L2 | energy (local) |\n|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < n_runs; ++i) {
    const solution *r0 = &runs[i - 1], *r1 = &runs[i];
    if (r0->npc != r1->npc || !r0->ok || !r1->ok) continue;
    printf("| %s | %g -> %g | %ld -> %ld |", cell_kind_name(r1->npc), r0->h1, r1->h1, r0->dofs, r1->dofs);
    for (int k = 0; k < 5; ++k)
      printf(" %.2f / %.2f |", slope(fabs(errs[k][i - 1]), fabs(errs[k][i]), r0->h1, r1->h1),
             -slope(fabs(errs[k][i - 1]), fabs(errs[k][i]), (double)r0->dofs, (double)r1->dofs));
    printf("\n");
  }
  for (int q = 0; q < 5; ++q) {
    int any = 0;
    for (int i = 0; i < n_runs; ++i) any |= runs[i].ok && runs[i].npc == kinds[q];
    if (!any) continue;
    printf("| %s | all sizes, least squares | |", cell_kind_name(kinds[q]));
    for (int k = 0; k < 5; ++k)
      printf(" %.2f / %.2f |", fitted_slope(runs, errs[k], n_runs, kinds[q], 0), -fitted_slope(runs, errs[k], n_runs, kinds[q], 1));
    printf("\n");
  }

  /* equal error: the DOFs and time from which on each kind's error stays below a threshold */
  static const struct {
    const char *name;
    int which;
    double levels[5];
  } measures[] = {{"p0", 0, {3e-3, 1e-3, 3e-4, 1e-4, 0}},
                  {"a (contact_half_width)", 1, {3e-2, 1e-2, 5e-3, 0, 0}},
                  {"a_moment", 2, {3e-2, 1e-2, 3e-3, 1e-3, 0}},
                  {"energy (local)", 4, {1e-1, 5e-2, 3e-2, 2e-2, 1e-2}}};
  printf("\nAt equal error: DOFs (and time s) from which on the error stays at or below the level (log-log "
         "interpolated between the two sizes where it gets there; '<=': already at the coarsest size; '-': not "
         "within the sizes run); in brackets the ratio to P1's\n\n| error | level |");
  for (int q = 0; q < 5; ++q) printf(" %s |", cell_kind_name(kinds[q]));
  printf("\n|---|---|---|---|---|---|---|\n");
  for (size_t m = 0; m < sizeof measures / sizeof measures[0]; ++m)
    for (int l = 0; l < 5 && measures[m].levels[l] > 0; ++l) {
      const double e = measures[m].levels[l];
      double p1_dofs = NAN, p1_time = NAN;
      printf("| %s | %g %% |", measures[m].name, 100 * e);
      for (int q = 0; q < 5; ++q) {
        double dofs, time;
        int st = dofs_at_error(runs, errs[measures[m].which], n_runs, kinds[q], e, &dofs, &time);
        if (st == 0) {
          printf(" - |");
          continue;
        }
        if (q == 0) p1_dofs = dofs, p1_time = time;
        printf(" %s%.0f (%.3f s)", st < 0 ? "<= " : "", dofs, time);
        if (q > 0 && isfinite(p1_dofs)) printf(" [%.2f, %.2f]", dofs / p1_dofs, time / p1_time);
        printf(" |");
      }
      printf("\n");
    }

  for (int i = 0; i < n_runs; ++i) free(runs[i].x), free(runs[i].p), free(runs[i].vertex);
  for (int c = 0; c < n_checks; ++c) free(checks[c].x), free(checks[c].p), free(checks[c].vertex);
  free(ref.x), free(ref.p), free(ref.vertex), free(ref.u[0]), free(ref.u[1]);
  for (int b = 0; b < 2; ++b) locator_free(&ref_locator[b]);
  hertz_scene_free(&ref_scene);
  return failed;
usage:
  fprintf(stderr,
          "usage: %s [--repeat n] [--ratio r] [--ref KIND:h1] [--check KIND:h1] [--json file] [--quick] [--global]\n"
          "       [--multiplier linear|quadratic] [--method mortar|dual] [--growth KIND:g] [--fine KIND:w]\n"
          "       [KIND:h1,h1,... ...]   (KIND: P1 Q1 T6 Q8 Q9; an h1 may be a range from..to/n, n sizes\n"
          "       geometrically spaced)\n",
          argv[0]);
  return 2;
}
