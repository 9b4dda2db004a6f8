/* scenes.c - shared helpers for the Check test suite; see scenes.h. */
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

double sc_random(unsigned *state) {
  unsigned x = *state ? *state : 2463534242u;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return (double)x / 4294967296.0;
}

double sc_reldiff(double a, double b, double floor) {
  double s = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
  if (s < floor) s = floor;
  return fabs(a - b) / s;
}

int sc_mesh_cells(sc_mesh *mesh, int npc, int nx, int ny, double x0, double y0, double lx, double ly, int criss_cross) {
  const int order = npc > 4 ? 2 : 1, quad = npc == 4 || npc == 8 || npc == 9;
  const int nI = order * nx + 1, nJ = order * ny + 1;
  int i, j, s, k;
  memset(mesh, 0, sizeof *mesh);
  if ((npc != 3 && npc != 4 && npc != 6 && npc != 8 && npc != 9) || nx < 1 || ny < 1 || !(lx > 0) || !(ly > 0)) return 1;
  mesh->nx = nx, mesh->ny = ny, mesh->npc = npc;
  mesh->n_cells = (mc_int)(quad ? nx * ny : 2 * nx * ny);
  mesh->cells = malloc(sizeof(mc_int) * (size_t)npc * (size_t)mesh->n_cells);
  mesh->lattice = malloc(sizeof(mc_int) * (size_t)nI * (size_t)nJ);
  /* cells in lattice indices first, then the used points numbered */
  {
    mc_int *c = mesh->cells;
#define L(I, J) ((mc_int)((J) * nI + (I)))
    for (j = 0; j < ny; ++j)
      for (i = 0; i < nx; ++i) {
        const int I = order * i, J = order * j, o = order;
        const mc_int a = L(I, J), b = L(I + o, J), cc = L(I + o, J + o), d = L(I, J + o);
        if (quad) {
          c[0] = a, c[1] = b, c[2] = cc, c[3] = d;
          if (order == 2) {
            c[4] = L(I + 1, J), c[5] = L(I + 2, J + 1), c[6] = L(I + 1, J + 2), c[7] = L(I, J + 1);
            if (npc == 9) c[8] = L(I + 1, J + 1);
          }
          c += npc;
        } else if (!criss_cross || (i + j) % 2 == 0) { /* diagonal a-cc: (a, b, cc) and (a, cc, d) */
          c[0] = a, c[1] = b, c[2] = cc;
          if (order == 2) c[3] = L(I + 1, J), c[4] = L(I + 2, J + 1), c[5] = L(I + 1, J + 1);
          c += npc;
          c[0] = a, c[1] = cc, c[2] = d;
          if (order == 2) c[3] = L(I + 1, J + 1), c[4] = L(I + 1, J + 2), c[5] = L(I, J + 1);
          c += npc;
        } else { /* diagonal b-d: (a, b, d) and (b, cc, d) */
          c[0] = a, c[1] = b, c[2] = d;
          if (order == 2) c[3] = L(I + 1, J), c[4] = L(I + 1, J + 1), c[5] = L(I, J + 1);
          c += npc;
          c[0] = b, c[1] = cc, c[2] = d;
          if (order == 2) c[3] = L(I + 2, J + 1), c[4] = L(I + 1, J + 2), c[5] = L(I + 1, J + 1);
          c += npc;
        }
      }
#undef L
  }
  for (k = 0; k < nI * nJ; ++k) mesh->lattice[k] = -1;
  for (k = 0; k < mesh->n_cells * npc; ++k) mesh->lattice[mesh->cells[k]] = 0;
  mesh->n_nodes = 0;
  for (k = 0; k < nI * nJ; ++k)
    if (mesh->lattice[k] == 0) mesh->lattice[k] = mesh->n_nodes++;
  for (k = 0; k < mesh->n_cells * npc; ++k) mesh->cells[k] = mesh->lattice[mesh->cells[k]];
  mesh->xy = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
  mesh->on_boundary = calloc((size_t)mesh->n_nodes, 1);
  for (j = 0; j < nJ; ++j)
    for (i = 0; i < nI; ++i) {
      const mc_int id = mesh->lattice[j * nI + i];
      if (id < 0) continue;
      mesh->xy[2 * id] = i == nI - 1 ? x0 + lx : x0 + i * lx / (nI - 1);
      mesh->xy[2 * id + 1] = j == nJ - 1 ? y0 + ly : y0 + j * ly / (nJ - 1);
      mesh->on_boundary[id] = i == 0 || j == 0 || i == nI - 1 || j == nJ - 1;
    }
  mesh->n_side_nodes[SC_BOTTOM] = mesh->n_side_nodes[SC_TOP] = nI;
  mesh->n_side_nodes[SC_LEFT] = mesh->n_side_nodes[SC_RIGHT] = nJ;
  for (s = 0; s < 4; ++s) {
    const mc_int n = mesh->n_side_nodes[s], edges = (n - 1) / order;
    mesh->side_nodes[s] = malloc(sizeof(mc_int) * (size_t)n);
    mesh->n_side_edges[s] = edges;
    mesh->side_edges[s] = malloc(sizeof(mc_int) * 2 * (size_t)edges);
    for (k = 0; k < n; ++k) {
      int I = 0, J = 0;
      switch (s) {
        case SC_BOTTOM: I = k, J = 0; break;
        case SC_RIGHT: I = nI - 1, J = k; break;
        case SC_TOP: I = nI - 1 - k, J = nJ - 1; break;
        default: I = 0, J = nJ - 1 - k; break;
      }
      mesh->side_nodes[s][k] = mesh->lattice[J * nI + I];
    }
    for (k = 0; k < edges; ++k) {
      mesh->side_edges[s][2 * k] = mesh->side_nodes[s][order * k];
      mesh->side_edges[s][2 * k + 1] = mesh->side_nodes[s][order * (k + 1)];
    }
  }
  mesh->boundary_nodes = malloc(sizeof(mc_int) * (size_t)mesh->n_nodes);
  for (k = 0; k < mesh->n_nodes; ++k)
    if (mesh->on_boundary[k]) mesh->boundary_nodes[mesh->n_boundary_nodes++] = (mc_int)k;
  return 0;
}

mc_int sc_node(const sc_mesh *mesh, int i, int j) { return (mc_int)(j * (mesh->nx + 1) + i); }

double sc_cell_area(const sc_mesh *mesh, mc_int c) {
  const mc_int *v = mesh->cells + (size_t)c * mesh->npc;
  double a = 0;
  int k;
  for (k = 0; k < mesh->npc; ++k) {
    const double *p = mesh->xy + 2 * v[k], *q = mesh->xy + 2 * v[(k + 1) % mesh->npc];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return 0.5 * a;
}

/* Strictly convex and counter-clockwise: every corner turns left. */
static int cell_convex(const sc_mesh *mesh, mc_int c) {
  const mc_int *v = mesh->cells + (size_t)c * mesh->npc;
  int k, n = mesh->npc;
  for (k = 0; k < n; ++k) {
    const double *p = mesh->xy + 2 * v[k], *q = mesh->xy + 2 * v[(k + 1) % n], *r = mesh->xy + 2 * v[(k + 2) % n];
    double cross = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]);
    if (!(cross > 0)) return 0;
  }
  return 1;
}

int sc_mesh_rect(sc_mesh *mesh, int npc, int nx, int ny, double x0, double y0, double lx, double ly,
                 double distortion, unsigned seed) {
  int i, j, s;
  double hx, hy, h;
  unsigned state = seed ? seed : 12345u;
  memset(mesh, 0, sizeof *mesh);
  if ((npc != 3 && npc != 4) || nx < 1 || ny < 1 || !(lx > 0) || !(ly > 0) || distortion < 0 || distortion > 0.25)
    return 1;
  mesh->nx = nx;
  mesh->ny = ny;
  mesh->npc = npc;
  mesh->n_nodes = (mc_int)((nx + 1) * (ny + 1));
  mesh->n_cells = (mc_int)(npc == 4 ? nx * ny : 2 * nx * ny);
  mesh->xy = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
  mesh->cells = malloc(sizeof(mc_int) * (size_t)npc * (size_t)mesh->n_cells);
  mesh->on_boundary = calloc((size_t)mesh->n_nodes, 1);
  hx = lx / nx;
  hy = ly / ny;
  h = hx < hy ? hx : hy;
  for (j = 0; j <= ny; ++j)
    for (i = 0; i <= nx; ++i) {
      mc_int id = sc_node(mesh, i, j);
      mesh->xy[2 * id] = i == nx ? x0 + lx : x0 + i * hx;
      mesh->xy[2 * id + 1] = j == ny ? y0 + ly : y0 + j * hy;
      if (i == 0 || j == 0 || i == nx || j == ny) {
        mesh->on_boundary[id] = 1;
      } else if (distortion > 0) {
        /* uniform in the disk of radius distortion*h; always draw two numbers */
        double r = distortion * h * sqrt(sc_random(&state));
        double t = 2 * M_PI * sc_random(&state);
        mesh->xy[2 * id] += r * cos(t);
        mesh->xy[2 * id + 1] += r * sin(t);
      }
    }
  for (j = 0; j < ny; ++j)
    for (i = 0; i < nx; ++i) {
      mc_int a = sc_node(mesh, i, j), b = sc_node(mesh, i + 1, j), c = sc_node(mesh, i + 1, j + 1),
             d = sc_node(mesh, i, j + 1);
      if (npc == 4) {
        mc_int *q = mesh->cells + 4 * (size_t)(j * nx + i);
        q[0] = a, q[1] = b, q[2] = c, q[3] = d;
      } else {
        mc_int *t = mesh->cells + 6 * (size_t)(j * nx + i);
        t[0] = a, t[1] = b, t[2] = c;
        t[3] = a, t[4] = c, t[5] = d;
      }
    }
  /* sides */
  mesh->n_side_nodes[SC_BOTTOM] = mesh->n_side_nodes[SC_TOP] = nx + 1;
  mesh->n_side_nodes[SC_LEFT] = mesh->n_side_nodes[SC_RIGHT] = ny + 1;
  for (s = 0; s < 4; ++s) {
    mc_int k, n = mesh->n_side_nodes[s];
    mesh->side_nodes[s] = malloc(sizeof(mc_int) * (size_t)n);
    mesh->n_side_edges[s] = n - 1;
    mesh->side_edges[s] = malloc(sizeof(mc_int) * 2 * (size_t)(n - 1));
    for (k = 0; k < n; ++k) {
      mc_int id = 0;
      switch (s) {
        case SC_BOTTOM: id = sc_node(mesh, k, 0); break;
        case SC_RIGHT: id = sc_node(mesh, nx, k); break;
        case SC_TOP: id = sc_node(mesh, nx - k, ny); break;
        default: id = sc_node(mesh, 0, ny - k); break;
      }
      mesh->side_nodes[s][k] = id;
    }
    for (k = 0; k + 1 < n; ++k) {
      mesh->side_edges[s][2 * k] = mesh->side_nodes[s][k];
      mesh->side_edges[s][2 * k + 1] = mesh->side_nodes[s][k + 1];
    }
  }
  mesh->n_boundary_nodes = 0;
  mesh->boundary_nodes = malloc(sizeof(mc_int) * (size_t)mesh->n_nodes);
  for (i = 0; i < mesh->n_nodes; ++i)
    if (mesh->on_boundary[i]) mesh->boundary_nodes[mesh->n_boundary_nodes++] = (mc_int)i;
  {
    mc_int c;
    for (c = 0; c < mesh->n_cells; ++c)
      if (!cell_convex(mesh, c)) return 2;
  }
  return 0;
}

void sc_mesh_free(sc_mesh *mesh) {
  int s;
  if (!mesh) return;
  free(mesh->xy);
  free(mesh->cells);
  free(mesh->on_boundary);
  free(mesh->boundary_nodes);
  free(mesh->lattice);
  for (s = 0; s < 4; ++s) {
    free(mesh->side_nodes[s]);
    free(mesh->side_edges[s]);
  }
  memset(mesh, 0, sizeof *mesh);
}

void sc_mesh_map(sc_mesh *mesh, void (*map)(double *x, double *y, void *ctx), void *ctx) {
  mc_int i;
  for (i = 0; i < mesh->n_nodes; ++i) map(&mesh->xy[2 * i], &mesh->xy[2 * i + 1], ctx);
}

mc_int *sc_ids(const mc_int *ids, mc_int n, int base) {
  mc_int k, *out = malloc(sizeof(mc_int) * (size_t)(n > 0 ? n : 1));
  for (k = 0; k < n; ++k) out[k] = ids[k] + base;
  return out;
}

mc_status sc_set_mesh(mc_model *m, int body, const sc_mesh *mesh, int base) {
  mc_int *cells = sc_ids(mesh->cells, mesh->n_cells * mesh->npc, base);
  mc_status st = mc_set_mesh(m, body, mesh->n_nodes, mesh->xy, mesh->n_cells, mesh->npc, cells);
  free(cells);
  return st;
}

mc_status sc_fix_field(mc_model *m, int body, const sc_mesh *mesh, mc_int n, const mc_int *nodes, int base,
                       sc_field field, void *ctx) {
  mc_int k, *ids = sc_ids(nodes, n, base);
  double *values = malloc(sizeof(double) * 2 * (size_t)(n > 0 ? n : 1));
  mc_status st;
  for (k = 0; k < n; ++k) field(mesh->xy[2 * nodes[k]], mesh->xy[2 * nodes[k] + 1], ctx, values + 2 * k, NULL);
  st = mc_fix(m, body, n, ids, MC_XY, values);
  free(ids);
  free(values);
  return st;
}

mc_status sc_fix_side(mc_model *m, int body, const sc_mesh *mesh, int side, int components, int base) {
  mc_int *ids = sc_ids(mesh->side_nodes[side], mesh->n_side_nodes[side], base);
  mc_status st = mc_fix(m, body, mesh->n_side_nodes[side], ids, components, NULL);
  free(ids);
  return st;
}

mc_status sc_traction_side(mc_model *m, int body, const sc_mesh *mesh, int side, double tx, double ty, int base) {
  mc_int k, n = mesh->n_side_edges[side];
  mc_int *ids = sc_ids(mesh->side_edges[side], 2 * n, base);
  double *t = malloc(sizeof(double) * 2 * (size_t)n);
  mc_status st;
  for (k = 0; k < n; ++k) t[2 * k] = tx, t[2 * k + 1] = ty;
  st = mc_add_traction(m, body, n, ids, t);
  free(ids);
  free(t);
  return st;
}

/* ---- quadrature --------------------------------------------------------- */

/* Quadrature point of a cell: physical point, weight * |J|, shape values and gradients. */
typedef struct {
  double x, y, w;
  double N[4], dNdx[4], dNdy[4];
} qpoint;

/* Dunavant 7-point rule, degree 5: barycentric (l1, l2, l3) and weights (sum 1). */
static const double tri7_l[7][3] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3},
    {0.059715871789770, 0.470142064105115, 0.470142064105115},
    {0.470142064105115, 0.059715871789770, 0.470142064105115},
    {0.470142064105115, 0.470142064105115, 0.059715871789770},
    {0.797426985353087, 0.101286507323456, 0.101286507323456},
    {0.101286507323456, 0.797426985353087, 0.101286507323456},
    {0.101286507323456, 0.101286507323456, 0.797426985353087}};
static const double tri7_w[7] = {0.225,
                                 0.132394152788506, 0.132394152788506, 0.132394152788506,
                                 0.125939180544827, 0.125939180544827, 0.125939180544827};

static const double gauss3_x[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
static const double gauss3_w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
static const double gauss4_x[4] = {-0.86113631159405257522, -0.33998104358485626480, 0.33998104358485626480,
                                   0.86113631159405257522};
static const double gauss4_w[4] = {0.34785484513745385737, 0.65214515486254614263, 0.65214515486254614263,
                                   0.34785484513745385737};

/* Fills q[] for cell c; returns the number of points. ng = 3 or 4 for Q1 (Gauss points per
   direction); P1 always uses the 7-point rule. */
static int cell_points(const sc_mesh *mesh, mc_int c, int ng, qpoint *q) {
  const mc_int *v = mesh->cells + (size_t)c * mesh->npc;
  int k, a, n = 0;
  if (mesh->npc == 3) {
    const double *p0 = mesh->xy + 2 * v[0], *p1 = mesh->xy + 2 * v[1], *p2 = mesh->xy + 2 * v[2];
    double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    /* gradients of barycentric coordinates */
    double gx[3], gy[3];
    gx[0] = (p1[1] - p2[1]) / det, gy[0] = (p2[0] - p1[0]) / det;
    gx[1] = (p2[1] - p0[1]) / det, gy[1] = (p0[0] - p2[0]) / det;
    gx[2] = (p0[1] - p1[1]) / det, gy[2] = (p1[0] - p0[0]) / det;
    for (k = 0; k < 7; ++k) {
      qpoint *p = &q[n++];
      p->x = p->y = 0;
      for (a = 0; a < 3; ++a) {
        p->N[a] = tri7_l[k][a];
        p->dNdx[a] = gx[a];
        p->dNdy[a] = gy[a];
        p->x += tri7_l[k][a] * mesh->xy[2 * v[a]];
        p->y += tri7_l[k][a] * mesh->xy[2 * v[a] + 1];
      }
      p->N[3] = p->dNdx[3] = p->dNdy[3] = 0;
      p->w = tri7_w[k] * 0.5 * det;
    }
  } else {
    static const double xs[4] = {-1, 1, 1, -1}, es[4] = {-1, -1, 1, 1};
    const double *gx = ng == 4 ? gauss4_x : gauss3_x, *gw = ng == 4 ? gauss4_w : gauss3_w;
    int i, j;
    for (j = 0; j < ng; ++j)
      for (i = 0; i < ng; ++i) {
        qpoint *p = &q[n++];
        double xi = gx[i], eta = gx[j], dNdxi[4], dNdeta[4], J[4] = {0, 0, 0, 0}, det;
        p->x = p->y = 0;
        for (a = 0; a < 4; ++a) {
          const double *P = mesh->xy + 2 * v[a];
          p->N[a] = 0.25 * (1 + xs[a] * xi) * (1 + es[a] * eta);
          dNdxi[a] = 0.25 * xs[a] * (1 + es[a] * eta);
          dNdeta[a] = 0.25 * es[a] * (1 + xs[a] * xi);
          p->x += p->N[a] * P[0];
          p->y += p->N[a] * P[1];
          J[0] += dNdxi[a] * P[0];  /* dx/dxi */
          J[1] += dNdeta[a] * P[0]; /* dx/deta */
          J[2] += dNdxi[a] * P[1];  /* dy/dxi */
          J[3] += dNdeta[a] * P[1]; /* dy/deta */
        }
        det = J[0] * J[3] - J[1] * J[2];
        for (a = 0; a < 4; ++a) {
          p->dNdx[a] = (J[3] * dNdxi[a] - J[2] * dNdeta[a]) / det;
          p->dNdy[a] = (-J[1] * dNdxi[a] + J[0] * dNdeta[a]) / det;
        }
        p->w = gw[i] * gw[j] * det;
      }
  }
  return n;
}

void sc_consistent_load(const sc_mesh *mesh, sc_field f, void *ctx, double thickness, double *F) {
  mc_int c;
  qpoint q[16];
  memset(F, 0, sizeof(double) * 2 * (size_t)mesh->n_nodes);
  for (c = 0; c < mesh->n_cells; ++c) {
    const mc_int *v = mesh->cells + (size_t)c * mesh->npc;
    int k, a, n = cell_points(mesh, c, 3, q);
    for (k = 0; k < n; ++k) {
      double val[2];
      f(q[k].x, q[k].y, ctx, val, NULL);
      for (a = 0; a < mesh->npc; ++a) {
        F[2 * v[a]] += thickness * q[k].w * q[k].N[a] * val[0];
        F[2 * v[a] + 1] += thickness * q[k].w * q[k].N[a] * val[1];
      }
    }
  }
}

mc_status sc_add_nodal_forces(mc_model *m, int body, const sc_mesh *mesh, const double *F, int base) {
  mc_int k, *ids = malloc(sizeof(mc_int) * (size_t)mesh->n_nodes);
  mc_status st;
  for (k = 0; k < mesh->n_nodes; ++k) ids[k] = k + base;
  st = mc_add_nodal_force(m, body, mesh->n_nodes, ids, F);
  free(ids);
  return st;
}

void sc_errors(const sc_mesh *mesh, const double *u, sc_field exact, void *ctx, double *l2, double *h1) {
  mc_int c;
  qpoint q[16];
  double e0 = 0, e1 = 0;
  for (c = 0; c < mesh->n_cells; ++c) {
    const mc_int *v = mesh->cells + (size_t)c * mesh->npc;
    int k, a, n = cell_points(mesh, c, 4, q);
    for (k = 0; k < n; ++k) {
      double val[2], grad[4], uh[2] = {0, 0}, gh[4] = {0, 0, 0, 0};
      int d;
      exact(q[k].x, q[k].y, ctx, val, grad);
      for (a = 0; a < mesh->npc; ++a) {
        double ux = u[2 * v[a]], uy = u[2 * v[a] + 1];
        uh[0] += q[k].N[a] * ux;
        uh[1] += q[k].N[a] * uy;
        gh[0] += q[k].dNdx[a] * ux;
        gh[1] += q[k].dNdy[a] * ux;
        gh[2] += q[k].dNdx[a] * uy;
        gh[3] += q[k].dNdy[a] * uy;
      }
      for (d = 0; d < 2; ++d) e0 += q[k].w * (val[d] - uh[d]) * (val[d] - uh[d]);
      for (d = 0; d < 4; ++d) e1 += q[k].w * (grad[d] - gh[d]) * (grad[d] - gh[d]);
    }
  }
  if (l2) *l2 = sqrt(e0);
  if (h1) *h1 = sqrt(e1);
}

void sc_isotropic_law(double young, double poisson, int plane, double D[9], double zz[2]) {
  double E = young, nu = poisson;
  if (plane == MC_PLANE_STRESS) {
    double f = E / (1 - nu * nu);
    D[0] = f, D[1] = f * nu, D[2] = 0;
    D[3] = f * nu, D[4] = f, D[5] = 0;
    D[6] = 0, D[7] = 0, D[8] = f * (1 - nu) / 2;
    if (zz) zz[0] = zz[1] = 0;
  } else {
    double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    D[0] = lambda + 2 * mu, D[1] = lambda, D[2] = 0;
    D[3] = lambda, D[4] = lambda + 2 * mu, D[5] = 0;
    D[6] = 0, D[7] = 0, D[8] = mu;
    if (zz) zz[0] = zz[1] = lambda;
  }
}


mc_model *sc_axisymmetric_shrink_fit(const sc_mesh *shaft, const sc_mesh *hub, double young, double nu, double delta) {
  mc_model *m = NULL;
  mc_int k, n = shaft->n_side_nodes[SC_RIGHT];
  double *offset = malloc(sizeof(double) * (size_t)n);
  mc_status st = mc_create(&m);
  for (k = 0; k < n; ++k) offset[k] = -delta;
  if (st == MC_OK) st = mc_set_plane(m, MC_AXISYMMETRIC, 1);
  if (st == MC_OK) st = sc_set_mesh(m, 1, shaft, 0);
  if (st == MC_OK) st = sc_set_mesh(m, 2, hub, 0);
  if (st == MC_OK) st = mc_set_material(m, 1, young, nu);
  if (st == MC_OK) st = mc_set_material(m, 2, young, nu);
  if (st == MC_OK) st = sc_fix_side(m, 1, shaft, SC_BOTTOM, MC_Y, 0);
  if (st == MC_OK) st = sc_fix_side(m, 2, hub, SC_BOTTOM, MC_Y, 0);
  if (st == MC_OK) st = mc_set_contact(m, 1, shaft->n_side_edges[SC_RIGHT], shaft->side_edges[SC_RIGHT]);
  if (st == MC_OK) st = mc_set_contact(m, 2, hub->n_side_edges[SC_LEFT], hub->side_edges[SC_LEFT]);
  if (st == MC_OK) st = mc_set_gap_offset(m, n, shaft->side_nodes[SC_RIGHT], offset);
  free(offset);
  if (st != MC_OK) {
    fprintf(stderr, "sc_axisymmetric_shrink_fit: %s\n", mc_errmsg(m));
    mc_destroy(m);
    return NULL;
  }
  return m;
}

/* ---- full rings (scenes.h) ---- */

mc_int sc_ring_node(const sc_polar_ring *g, int i, int j) { return (mc_int)(j * g->nt + (i % g->nt)); }

int sc_polar_ring_build(sc_polar_ring *g, int nt, int nr, int npc, double r0, double r1) {
  if (nt % 4 != 0 || nt <= 0 || nr <= 0 || (npc != 3 && npc != 4)) return 1;
  g->nt = nt, g->nr = nr, g->npc = npc, g->r0 = r0, g->r1 = r1;
  g->n_nodes = nt * (nr + 1);
  g->n_cells = npc == 4 ? nt * nr : 2 * nt * nr;
  g->xy = malloc(sizeof(double) * 2 * (size_t)g->n_nodes);
  g->cells = malloc(sizeof(mc_int) * (size_t)npc * (size_t)g->n_cells);
  static const double axis_cos[4] = {1, 0, -1, 0}, axis_sin[4] = {0, 1, 0, -1};
  for (int j = 0; j <= nr; ++j)
    for (int i = 0; i < nt; ++i) {
      const double r = j == nr ? r1 : r0 + j * (r1 - r0) / nr, t = 2 * M_PI * i / nt;
      const int on_axis = i % (nt / 4) == 0; /* exactly on an axis: the symmetric supports need it */
      g->xy[2 * sc_ring_node(g, i, j)] = r * (on_axis ? axis_cos[i / (nt / 4)] : cos(t));
      g->xy[2 * sc_ring_node(g, i, j) + 1] = r * (on_axis ? axis_sin[i / (nt / 4)] : sin(t));
    }
  /* (i, j) -> (i, j+1) -> (i+1, j+1) -> (i+1, j) runs counter-clockwise: outwards, then around */
  mc_int *c = g->cells;
  for (int j = 0; j < nr; ++j)
    for (int i = 0; i < nt; ++i) {
      const mc_int a = sc_ring_node(g, i, j), b = sc_ring_node(g, i, j + 1), d = sc_ring_node(g, i + 1, j + 1),
                   e = sc_ring_node(g, i + 1, j);
      if (npc == 4) {
        c[0] = a, c[1] = b, c[2] = d, c[3] = e, c += 4;
      } else {
        c[0] = a, c[1] = b, c[2] = d, c[3] = a, c[4] = d, c[5] = e, c += 6;
      }
    }
  return 0;
}

void sc_polar_ring_free(sc_polar_ring *g) { free(g->xy), free(g->cells); }

/* The circle j as a closed loop of nt edges, oriented as its cells (the body on the left):
   counter-clockwise for the outer circle, clockwise for the inner one. */
mc_int *sc_ring_circle_edges(const sc_polar_ring *g, int j) {
  mc_int *e = malloc(sizeof(mc_int) * 2 * (size_t)g->nt);
  for (int i = 0; i < g->nt; ++i) {
    const mc_int a = sc_ring_node(g, i, j), b = sc_ring_node(g, i + 1, j);
    e[2 * i] = j == 0 ? b : a, e[2 * i + 1] = j == 0 ? a : b;
  }
  return e;
}
