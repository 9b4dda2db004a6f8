/* host_assembly.c - an independent assembler of element matrices and loads; see host_assembly.h. */
#include "host_assembly.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

void ha_law_plane_strain(double young, double nu, double D[9]) {
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  memset(D, 0, 9 * sizeof(double));
  D[0] = D[4] = lambda + 2 * mu;
  D[1] = D[3] = lambda;
  D[8] = mu;
}

void ha_law_axisymmetric(double young, double nu, double D[16]) {
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  static const int normal[3] = {0, 1, 3}; /* rr, zz, tt; rz is index 2 */
  memset(D, 0, 16 * sizeof(double));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D[4 * normal[i] + normal[j]] = lambda + (i == j ? 2 * mu : 0);
  D[4 * 2 + 2] = mu;
}

void ha_law_orthotropic(double s11, double s22, double s12, double s33, double D[9]) {
  const double det = s11 * s22 - s12 * s12;
  memset(D, 0, 9 * sizeof(double));
  D[0] = s22 / det, D[4] = s11 / det, D[1] = D[3] = -s12 / det;
  D[8] = 1 / s33;
}

/* ---- shape functions ------------------------------------------------------------------------ */

/* Reference positions of the quadrilaterals' nodes (Q9's 9; Q8 and Q1 use the first 8 and 4). */
static const double kQuadXi[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0};
static const double kQuadEta[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};

/* The 1D quadratic Lagrange basis on the nodes -1, 0, 1: value and derivative of the one at s0. */
static void lagrange2(double s0, double s, double *l, double *dl) {
  if (s0 < 0) *l = 0.5 * s * (s - 1), *dl = s - 0.5;
  else if (s0 > 0) *l = 0.5 * s * (s + 1), *dl = s + 0.5;
  else *l = 1 - s * s, *dl = -2 * s;
}

void ha_shape(int npc, double xi, double eta, double *N, double *dxi, double *deta) {
  if (npc == 3 || npc == 6) {
    /* barycentric l0 = 1 - xi - eta, l1 = xi, l2 = eta; d/dxi = (-1, 1, 0), d/deta = (-1, 0, 1) */
    const double l[3] = {1 - xi - eta, xi, eta}, lx[3] = {-1, 1, 0}, le[3] = {-1, 0, 1};
    if (npc == 3) {
      for (int a = 0; a < 3; ++a) N[a] = l[a], dxi[a] = lx[a], deta[a] = le[a];
      return;
    }
    for (int a = 0; a < 3; ++a) { /* corners: l (2 l - 1) */
      N[a] = l[a] * (2 * l[a] - 1);
      dxi[a] = (4 * l[a] - 1) * lx[a], deta[a] = (4 * l[a] - 1) * le[a];
    }
    for (int k = 0; k < 3; ++k) { /* middle of edge k-(k+1): 4 l_k l_{k+1} */
      const int p = k, q = (k + 1) % 3;
      N[3 + k] = 4 * l[p] * l[q];
      dxi[3 + k] = 4 * (lx[p] * l[q] + l[p] * lx[q]);
      deta[3 + k] = 4 * (le[p] * l[q] + l[p] * le[q]);
    }
    return;
  }
  if (npc == 4) {
    for (int a = 0; a < 4; ++a) {
      const double xa = kQuadXi[a], ea = kQuadEta[a];
      N[a] = 0.25 * (1 + xa * xi) * (1 + ea * eta);
      dxi[a] = 0.25 * xa * (1 + ea * eta);
      deta[a] = 0.25 * ea * (1 + xa * xi);
    }
    return;
  }
  if (npc == 8) {
    for (int a = 0; a < 4; ++a) { /* corners: (1 + xi xa)(1 + eta ea)(xi xa + eta ea - 1) / 4 */
      const double xa = kQuadXi[a], ea = kQuadEta[a];
      N[a] = 0.25 * (1 + xa * xi) * (1 + ea * eta) * (xa * xi + ea * eta - 1);
      dxi[a] = 0.25 * xa * (1 + ea * eta) * (2 * xa * xi + ea * eta);
      deta[a] = 0.25 * ea * (1 + xa * xi) * (xa * xi + 2 * ea * eta);
    }
    for (int a = 4; a < 8; ++a) {
      const double xa = kQuadXi[a], ea = kQuadEta[a];
      if (xa == 0) { /* on eta = ea: (1 - xi^2)(1 + eta ea) / 2 */
        N[a] = 0.5 * (1 - xi * xi) * (1 + ea * eta);
        dxi[a] = -xi * (1 + ea * eta);
        deta[a] = 0.5 * (1 - xi * xi) * ea;
      } else { /* on xi = xa: (1 + xi xa)(1 - eta^2) / 2 */
        N[a] = 0.5 * (1 + xa * xi) * (1 - eta * eta);
        dxi[a] = 0.5 * xa * (1 - eta * eta);
        deta[a] = -eta * (1 + xa * xi);
      }
    }
    return;
  }
  for (int a = 0; a < 9; ++a) { /* Q9: products of the 1D quadratic bases */
    double lx, dlx, le, dle;
    lagrange2(kQuadXi[a], xi, &lx, &dlx);
    lagrange2(kQuadEta[a], eta, &le, &dle);
    N[a] = lx * le, dxi[a] = dlx * le, deta[a] = lx * dle;
  }
}

/* ---- quadrature ------------------------------------------------------------------------------ */

static const double kGauss2 = 0.57735026918962576451; /* 1 / sqrt(3) */
static const double kGauss3 = 0.77459666924148337704; /* sqrt(3 / 5) */

int ha_rule(int npc, int axisymmetric, double *p, double *w) {
  int n = 0;
  if (npc == 3 && !axisymmetric) {
    p[0] = p[1] = 1.0 / 3, w[0] = 0.5;
    return 1;
  }
  if (npc == 3 || (npc == 6 && !axisymmetric)) { /* barycentric (2/3, 1/6, 1/6) and its permutations */
    const double bary[3][3] = {{2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {1.0 / 6, 1.0 / 6, 2.0 / 3}};
    for (int k = 0; k < 3; ++k) p[2 * k] = bary[k][1], p[2 * k + 1] = bary[k][2], w[k] = 0.5 / 3;
    return 3;
  }
  if (npc == 6) { /* axisymmetric: Dunavant, degree 4: (1 - 2a, a, a) and permutations, two orbits */
    const double a[2] = {0.445948490915965, 0.091576213509771}, wa[2] = {0.223381589678011, 0.109951743655322};
    for (int o = 0; o < 2; ++o) {
      const double l[3][3] = {{1 - 2 * a[o], a[o], a[o]}, {a[o], 1 - 2 * a[o], a[o]}, {a[o], a[o], 1 - 2 * a[o]}};
      for (int k = 0; k < 3; ++k, ++n) p[2 * n] = l[k][1], p[2 * n + 1] = l[k][2], w[n] = 0.5 * wa[o];
    }
    return n;
  }
  if (npc == 4) {
    const double g[2] = {-kGauss2, kGauss2};
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i, ++n) p[2 * n] = g[i], p[2 * n + 1] = g[j], w[n] = 1;
    return n;
  }
  const double g[3] = {-kGauss3, 0, kGauss3}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i, ++n) p[2 * n] = g[i], p[2 * n + 1] = g[j], w[n] = gw[i] * gw[j];
  return n;
}

/* ---- element stiffness ------------------------------------------------------------------------ */

/* Adds weight * B^T D B at reference point (xi, eta) to ke; returns 1 on a non-positive
   Jacobian (or r <= 0 for axisymmetric). */
static int add_point(int npc, const double *xy, int axisymmetric, double thickness, const double *D, double xi,
                     double eta, double weight, double *ke) {
  double N[9], dxi[9], deta[9], J[4] = {0, 0, 0, 0}, r = 0;
  ha_shape(npc, xi, eta, N, dxi, deta);
  for (int a = 0; a < npc; ++a) {
    J[0] += dxi[a] * xy[2 * a], J[1] += deta[a] * xy[2 * a];         /* dx/dxi, dx/deta */
    J[2] += dxi[a] * xy[2 * a + 1], J[3] += deta[a] * xy[2 * a + 1]; /* dy/dxi, dy/deta */
    r += N[a] * xy[2 * a];
  }
  const double det = J[0] * J[3] - J[1] * J[2];
  if (!(det > 0) || (axisymmetric && !(r > 0))) return 1;
  const int nd = 2 * npc, ns = axisymmetric ? 4 : 3;
  double B[4][18];
  memset(B, 0, sizeof B);
  for (int a = 0; a < npc; ++a) {
    const double dx = (J[3] * dxi[a] - J[2] * deta[a]) / det, dy = (-J[1] * dxi[a] + J[0] * deta[a]) / det;
    B[0][2 * a] = dx;
    B[1][2 * a + 1] = dy;
    B[2][2 * a] = dy, B[2][2 * a + 1] = dx;
    if (axisymmetric) B[3][2 * a] = N[a] / r;
  }
  const double scale = weight * det * (axisymmetric ? 2 * M_PI * r : thickness);
  double DB[4][18];
  for (int i = 0; i < ns; ++i)
    for (int k = 0; k < nd; ++k) {
      double s = 0;
      for (int j = 0; j < ns; ++j) s += D[ns * i + j] * B[j][k];
      DB[i][k] = s;
    }
  for (int p = 0; p < nd; ++p)
    for (int q = p; q < nd; ++q) {
      double s = 0;
      for (int i = 0; i < ns; ++i) s += B[i][p] * DB[i][q];
      ke[nd * p + q] += scale * s;
    }
  return 0;
}

static void mirror(int nd, double *ke) {
  for (int p = 0; p < nd; ++p)
    for (int q = 0; q < p; ++q) ke[nd * p + q] = ke[nd * q + p];
}

int ha_element_stiffness(int npc, const double *xy, int axisymmetric, double thickness, const double *D, double *ke) {
  double pts[18], w[9];
  const int nd = 2 * npc, n = ha_rule(npc, axisymmetric, pts, w);
  memset(ke, 0, sizeof(double) * (size_t)(nd * nd));
  for (int k = 0; k < n; ++k)
    if (add_point(npc, xy, axisymmetric, thickness, D, pts[2 * k], pts[2 * k + 1], w[k], ke)) return 1;
  mirror(nd, ke);
  return 0;
}

int ha_layered_stiffness(int npc, const double *xy, double thickness, int n_layers, const double *eta_bounds,
                         const double *D, double *ke) {
  double pts[18], w[9];
  const int nd = 2 * npc, n = ha_rule(npc, 0, pts, w);
  if (npc != 4 && npc != 8 && npc != 9) return 1;
  memset(ke, 0, sizeof(double) * (size_t)(nd * nd));
  for (int l = 0; l < n_layers; ++l) {
    const double e0 = eta_bounds[l], e1 = eta_bounds[l + 1], mid = 0.5 * (e0 + e1), half = 0.5 * (e1 - e0);
    for (int k = 0; k < n; ++k)
      if (add_point(npc, xy, 0, thickness, D + 9 * l, pts[2 * k], mid + half * pts[2 * k + 1], w[k] * half, ke)) return 1;
  }
  mirror(nd, ke);
  return 0;
}

/* ---- loads --------------------------------------------------------------------------------------- */

void ha_edge_load(int n, const double *xy, const double t[2], int axisymmetric, double thickness, double *f) {
  const double g[3] = {-kGauss3, 0, kGauss3}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  memset(f, 0, sizeof(double) * 2 * (size_t)n);
  for (int k = 0; k < 3; ++k) {
    const double s = g[k];
    double N[3], dN[3];
    if (n == 2) {
      N[0] = 0.5 * (1 - s), N[1] = 0.5 * (1 + s), dN[0] = -0.5, dN[1] = 0.5;
    } else { /* ends at s = -1, 1, the middle at 0 */
      N[0] = 0.5 * s * (s - 1), N[1] = 0.5 * s * (s + 1), N[2] = 1 - s * s;
      dN[0] = s - 0.5, dN[1] = s + 0.5, dN[2] = -2 * s;
    }
    double x = 0, dx = 0, dy = 0;
    for (int a = 0; a < n; ++a) x += N[a] * xy[2 * a], dx += dN[a] * xy[2 * a], dy += dN[a] * xy[2 * a + 1];
    const double weight = gw[k] * sqrt(dx * dx + dy * dy) * (axisymmetric ? 2 * M_PI * x : thickness);
    for (int a = 0; a < n; ++a) f[2 * a] += weight * N[a] * t[0], f[2 * a + 1] += weight * N[a] * t[1];
  }
}

mc_int ha_edge_middle(int npc, mc_int n_cells, const mc_int *cells, mc_int a, mc_int b) {
  const int corners = npc == 6 ? 3 : 4;
  for (mc_int c = 0; c < n_cells; ++c) {
    const mc_int *v = cells + (size_t)c * (size_t)npc;
    for (int k = 0; k < corners; ++k) {
      const mc_int p = v[k], q = v[(k + 1) % corners];
      if ((p == a && q == b) || (p == b && q == a)) return v[corners + k];
    }
  }
  return -1;
}

int ha_mesh_element_matrices(int npc, mc_int n_cells, const mc_int *cells, const double *xy, const mc_int *equations,
                             const double D[9], mc_int **eltptr, mc_int **eltvar, double **a) {
  const int nv = 2 * npc;
  *eltptr = malloc(sizeof(mc_int) * ((size_t)n_cells + 1));
  *eltvar = malloc(sizeof(mc_int) * (size_t)nv * (size_t)n_cells);
  *a = malloc(sizeof(double) * (size_t)nv * nv * (size_t)n_cells);
  int failed = 0;
  double cell_xy[18];
  for (mc_int c = 0; c < n_cells; ++c) {
    (*eltptr)[c] = c * nv;
    for (int k = 0; k < npc; ++k) {
      const mc_int v = cells[npc * c + k];
      cell_xy[2 * k] = xy[2 * v], cell_xy[2 * k + 1] = xy[2 * v + 1];
      (*eltvar)[nv * c + 2 * k] = equations[2 * v], (*eltvar)[nv * c + 2 * k + 1] = equations[2 * v + 1];
    }
    if (ha_element_stiffness(npc, cell_xy, 0, 1.0, D, *a + (size_t)nv * nv * c) && !failed) failed = 1 + (int)c;
  }
  (*eltptr)[n_cells] = nv * n_cells;
  return failed;
}

/* ---- coordinate matrices ------------------------------------------------------------------------- */

void ha_coo_add(ha_coo *a, mc_int row, mc_int col, double value) {
  if (a->n == a->cap) {
    a->cap = a->cap ? 2 * a->cap : 1024;
    a->row = realloc(a->row, a->cap * sizeof(mc_int));
    a->col = realloc(a->col, a->cap * sizeof(mc_int));
    a->val = realloc(a->val, a->cap * sizeof(double));
  }
  a->row[a->n] = row, a->col[a->n] = col, a->val[a->n] = value;
  ++a->n;
}

void ha_coo_free(ha_coo *a) {
  free(a->row), free(a->col), free(a->val);
  memset(a, 0, sizeof *a);
}

void ha_coo_multiply(const ha_coo *a, const double *x, double *y, mc_int n) {
  memset(y, 0, sizeof(double) * (size_t)n);
  for (size_t k = 0; k < a->n; ++k) {
    const mc_int i = a->row[k], j = a->col[k];
    if (i < 0 || i >= n || j < 0 || j >= n) continue;
    y[i] += a->val[k] * x[j];
  }
}
