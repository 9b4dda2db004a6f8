/*
 * tutorial_shrink_fit.c - the program of docs/tutorial_axisymmetric.md: a hub shrunk on a
 * solid shaft, a 3D scene solved on its 2D meridian with MC_AXISYMMETRIC.
 *
 *   tutorial_shrink_fit [out.pvd]
 *
 * Prints the contact pressure along the bore against the plane-stress Lame value (the exact
 * answer for equal lengths and free ends) and exits non-zero unless every node is within 1 %
 * and the shaft's stress is the uniform -p it must be.
 */
#include <math.h>
#include <mortarcontact.h>
#include <stdio.h>
#include <stdlib.h>

/* A structured Q1 mesh of the rectangle [x0, x0 + lx] x [0, ly] with nx x ny cells, and the
   node ids of its bottom (y = 0) and of its left and right sides, bottom to top. */
typedef struct rectangle {
  int n_nodes, n_cells;
  double *xy;
  mc_int *cells, *bottom, *left, *right;
  mc_int *left_edges, *right_edges; /* 2 ids per edge */
} rectangle;

static rectangle rectangle_mesh(double x0, double lx, double ly, int nx, int ny) {
  rectangle m;
  m.n_nodes = (nx + 1) * (ny + 1), m.n_cells = nx * ny;
  m.xy = malloc(sizeof(double) * 2 * m.n_nodes);
  m.cells = malloc(sizeof(mc_int) * 4 * m.n_cells);
  m.bottom = malloc(sizeof(mc_int) * (nx + 1));
  m.left = malloc(sizeof(mc_int) * (ny + 1)), m.right = malloc(sizeof(mc_int) * (ny + 1));
  m.left_edges = malloc(sizeof(mc_int) * 2 * ny), m.right_edges = malloc(sizeof(mc_int) * 2 * ny);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.xy[2 * (j * (nx + 1) + i)] = x0 + lx * i / nx;
      m.xy[2 * (j * (nx + 1) + i) + 1] = ly * j / ny;
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) { /* counter-clockwise */
      mc_int *c = &m.cells[4 * (j * nx + i)], a = j * (nx + 1) + i;
      c[0] = a, c[1] = a + 1, c[2] = a + nx + 2, c[3] = a + nx + 1;
    }
  for (int i = 0; i <= nx; ++i) m.bottom[i] = i;
  for (int j = 0; j <= ny; ++j) m.left[j] = j * (nx + 1), m.right[j] = j * (nx + 1) + nx;
  for (int j = 0; j < ny; ++j) {
    m.left_edges[2 * j] = m.left[j], m.left_edges[2 * j + 1] = m.left[j + 1];
    m.right_edges[2 * j] = m.right[j], m.right_edges[2 * j + 1] = m.right[j + 1];
  }
  return m;
}

static void rectangle_free(rectangle *m) {
  free(m->xy), free(m->cells), free(m->bottom), free(m->left), free(m->right);
  free(m->left_edges), free(m->right_edges);
}

#define CHECK(call)                                                          \
  do {                                                                       \
    if ((call) != MC_OK) {                                                   \
      fprintf(stderr, "%s failed: %s\n", #call, mc_errmsg(m));               \
      return 1;                                                              \
    }                                                                        \
  } while (0)

int main(int argc, char **argv) {
  /* The scene: a steel hub b <= r <= c shrunk on a solid shaft r <= b, both of length 2 L,
     radial interference delta. By symmetry only the half z >= 0 is modelled. */
  const double b = 20, c = 40, L = 20, delta = 0.02; /* mm */
  const double young = 210000, nu = 0.3;             /* MPa */
  const int nr = 32, nz_shaft = 48, nz_hub = 68;     /* non-matching along the bore */
  rectangle shaft = rectangle_mesh(0, b, L, nr, nz_shaft);
  rectangle hub = rectangle_mesh(b, c - b, L, nr, nz_hub);

  mc_model *m;
  if (mc_create(&m) != MC_OK) return 1;
  /* The meridian: x is the radius, y the axis. The thickness is ignored. */
  CHECK(mc_set_plane(m, MC_AXISYMMETRIC, 0.0));
  CHECK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_BBAR));
  CHECK(mc_set_mesh(m, 1, shaft.n_nodes, shaft.xy, shaft.n_cells, 4, shaft.cells));
  CHECK(mc_set_mesh(m, 2, hub.n_nodes, hub.xy, hub.n_cells, 4, hub.cells));
  CHECK(mc_set_material(m, 1, young, nu));
  CHECK(mc_set_material(m, 2, young, nu));
  /* Supports: the symmetry plane z = 0 on rollers (u_z = 0). The shaft's nodes on the axis
     get u_r = 0 from the library; nothing else holds the bodies radially: the hoop
     stiffness does. */
  CHECK(mc_fix(m, 1, nr + 1, shaft.bottom, MC_Y, NULL));
  CHECK(mc_fix(m, 2, nr + 1, hub.bottom, MC_Y, NULL));
  /* Contact: the shaft's mantle (body 1) against the bore (body 2); the meshes touch, and the
     interference is an offset of -delta on the initial gap of the shaft's nodes. */
  CHECK(mc_set_contact(m, 1, nz_shaft, shaft.right_edges));
  CHECK(mc_set_contact(m, 2, nz_hub, hub.left_edges));
  double *offset = malloc(sizeof(double) * (nz_shaft + 1));
  for (int j = 0; j <= nz_shaft; ++j) offset[j] = -delta;
  CHECK(mc_set_gap_offset(m, nz_shaft + 1, shaft.right, offset));
  free(offset);
  CHECK(mc_solve(m));

  /* Lame, plane stress, equal materials: p = E delta (c^2 - b^2) / (2 b c^2). */
  const double lame = young * delta * (c * c - b * b) / (2 * b * c * c);
  mc_int n;
  CHECK(mc_get_contact_count(m, &n));
  mc_int *nodes = malloc(sizeof(mc_int) * n);
  double *pressure = malloc(sizeof(double) * n), worst = 0;
  CHECK(mc_get_contact_nodes(m, nodes));
  CHECK(mc_get_contact_pressure(m, pressure));
  printf("contact pressure along the bore (Lame: %.4f MPa)\n", lame);
  for (mc_int j = 0; j < n; ++j) {
    worst = fmax(worst, fabs(pressure[j] / lame - 1));
    if (j % 8 == 0 || j == n - 1)
      printf("  z = %6.3f mm   p = %.4f MPa   %+.3f %%\n", shaft.xy[2 * nodes[j] + 1], pressure[j],
             100 * (pressure[j] / lame - 1));
  }
  printf("largest deviation from Lame along the bore: %.3f %%\n", worst * 100);

  /* The shaft is in uniform plane stress: sigma_rr = sigma_theta_theta = -p, sigma_zz = 0. */
  double *sigma = malloc(sizeof(double) * 4 * shaft.n_cells), hoop = 0;
  CHECK(mc_get_stress(m, 1, sigma));
  for (int k = 0; k < shaft.n_cells; ++k) hoop += sigma[4 * k + 3] / shaft.n_cells;
  printf("shaft: mean hoop stress %.4f MPa (-p = %.4f)\n", hoop, -lame);

  if (argc > 1) {
    CHECK(mc_write_vtu(m, argv[1]));
    printf("wrote %s\n", argv[1]);
  }
  int ok = worst < 0.01 && fabs(hoop / -lame - 1) < 0.01;
  free(nodes), free(pressure), free(sigma);
  rectangle_free(&shaft), rectangle_free(&hub);
  mc_destroy(m);
  return ok ? 0 : 1;
}
