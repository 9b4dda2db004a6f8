/*
 * tutorial_push_out.c - the program of docs/tutorial_friction.md: a shaft pressed into a hub
 * (a shrink fit) and then pushed out of it, with Coulomb friction, axisymmetric.
 *
 *   tutorial_push_out [out.pvd]
 *
 * Pushes the shaft's end down step by step and prints the push force against the slip state of
 * the bore; once every position slips the force is mu times the normal force, which the fit
 * sets to about the Lame pressure times the bore's area. Exits non-zero unless the full-slip
 * force is mu N to 1e-8 and within 3 % of mu p_Lame 2 pi b L.
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
  /* ---- step 1: the meshes ---- */
  /* A steel hub b <= r <= c on a solid shaft r <= b, both of length L, radial interference
     delta; the meshes do not match along the bore. */
  const double b = 20, c = 40, L = 20, delta = 0.02; /* mm */
  const double young = 210000, nu = 0.3, mu = 0.2;   /* MPa */
  const int nr = 16, nz_shaft = 40, nz_hub = 52;
  rectangle shaft = rectangle_mesh(0, b, L, nr, nz_shaft);
  rectangle hub = rectangle_mesh(b, c - b, L, nr, nz_hub);

  /* ---- step 2: the model ---- */
  mc_model *m;
  if (mc_create(&m) != MC_OK) return 1;
  CHECK(mc_set_plane(m, MC_AXISYMMETRIC, 0.0));
  CHECK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_BBAR));
  CHECK(mc_set_mesh(m, 1, shaft.n_nodes, shaft.xy, shaft.n_cells, 4, shaft.cells));
  CHECK(mc_set_mesh(m, 2, hub.n_nodes, hub.xy, hub.n_cells, 4, hub.cells));
  CHECK(mc_set_material(m, 1, young, nu));
  CHECK(mc_set_material(m, 2, young, nu));
  /* The hub sits on its bottom face (u_z = 0 there); the shaft's top face is where the press
     pushes: its axial displacement is prescribed, 0 for the fit. */
  CHECK(mc_fix(m, 2, nr + 1, hub.bottom, MC_Y, NULL));
  mc_int *top = malloc(sizeof(mc_int) * (nr + 1));
  for (int i = 0; i <= nr; ++i) top[i] = nz_shaft * (nr + 1) + i;
  CHECK(mc_fix(m, 1, nr + 1, top, MC_Y, NULL));

  /* ---- step 3: contact with interference and friction ---- */
  CHECK(mc_set_contact(m, 1, nz_shaft, shaft.right_edges));
  CHECK(mc_set_contact(m, 2, nz_hub, hub.left_edges));
  double *offset = malloc(sizeof(double) * (nz_shaft + 1));
  for (int j = 0; j <= nz_shaft; ++j) offset[j] = -delta;
  CHECK(mc_set_gap_offset(m, nz_shaft + 1, shaft.right, offset));
  free(offset);
  /* Coulomb friction on pair 1 (the shaft on the bore): |shear| <= mu p. Each solve is now a
     step from the last converged state. */
  CHECK(mc_set_friction(m, 1, MC_FRICTION_COULOMB, mu));

  /* ---- step 4: the fit ---- */
  CHECK(mc_solve(m));
  mc_int n;
  CHECK(mc_get_contact_count(m, &n));
  double *force = malloc(sizeof(double) * n), *state = malloc(sizeof(double) * n);
  double normal = 0;
  CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_FORCE, force));
  for (mc_int j = 0; j < n; ++j) normal += force[j];
  /* Lame, plane stress, equal materials: p = E delta (c^2 - b^2) / (2 b c^2), on 2 pi b L. */
  const double pi = 3.14159265358979323846;
  const double lame = young * delta * (c * c - b * b) / (2 * b * c * c), area = 2 * pi * b * L;
  printf("fit: normal force %.1f N, Lame p A = %.1f N (%+.2f %%)\n", normal, lame * area,
         100 * (normal / (lame * area) - 1));

  /* ---- step 5: push the shaft out, step by step ---- */
  double *r = malloc(sizeof(double) * 2 * shaft.n_nodes), push = 0;
  printf("  push (mm)   force (N)   force / (mu N)   stick  slip\n");
  for (int k = 1; k <= 8; ++k) {
    const double w = 0.001 * k;
    double *down = malloc(sizeof(double) * 2 * (nr + 1));
    for (int i = 0; i <= nr; ++i) down[2 * i] = 0, down[2 * i + 1] = -w;
    CHECK(mc_fix(m, 1, nr + 1, top, MC_Y, down));
    free(down);
    CHECK(mc_solve(m)); /* a step from the last state: the friction's history carries */
    CHECK(mc_get_reaction(m, 1, r));
    push = 0;
    for (int i = 0; i <= nr; ++i) push -= r[2 * top[i] + 1];
    CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_FORCE, force));
    CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, state));
    normal = 0;
    int stick = 0, slip = 0;
    for (mc_int j = 0; j < n; ++j) {
      normal += force[j];
      stick += state[j] == MC_STATE_STICK, slip += state[j] == MC_STATE_SLIP;
    }
    printf("  %9.3f  %10.1f   %14.4f   %5d  %4d\n", w, push, push / (mu * normal), stick, slip);
  }

  /* ---- step 6: the push-out force against mu N and mu p A ---- */
  printf("push-out force %.1f N: mu N = %.1f N (%+.1e), mu p_Lame A = %.1f N (%+.2f %%)\n", push, mu * normal,
         push / (mu * normal) - 1, mu * lame * area, 100 * (push / (mu * lame * area) - 1));
  if (argc > 1) {
    CHECK(mc_write_vtu(m, argv[1]));
    printf("wrote %s\n", argv[1]);
  }
  const int ok = fabs(push / (mu * normal) - 1) < 1e-8 && fabs(push / (mu * lame * area) - 1) < 0.03;
  free(top), free(force), free(state), free(r);
  rectangle_free(&shaft), rectangle_free(&hub);
  mc_destroy(m);
  return ok ? 0 : 1;
}
