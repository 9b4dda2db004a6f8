/*
 * westergaard_scene.h - Westergaard's periodic wavy contact as a long interface with many
 * separate contact patches (K. L. Johnson, Contact Mechanics, 1985, section 13.2), shared by
 * bench/westergaard.c and tests/test_westergaard.c (C99).
 *
 * The closed form. A surface of profile Delta (1 - cos(2 pi x / L)) pressed on a flat one under
 * the mean pressure pm, both bodies linear elastic half-planes (plane strain), frictionless:
 *   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   p* = pi E* Delta / L (full contact from pm = p*).
 * For pm < p*, around every crest x = kL a zone |x - kL| < a with sin^2(pi a / L) = pm / p*,
 *   p(x) = 2 pm cos(pi x / L) sqrt(sin^2(pi a / L) - sin^2(pi x / L)) / sin^2(pi a / L),
 * peak p0 = p(0) = 2 sqrt(pm p*). (Checked before use: its mean over a wavelength is pm, and the
 * surface displacement of its Fourier series closes the gap exactly inside |x| < a and leaves it
 * open outside.)
 *
 * The scene. Two flat rectangles N L long, body 1 = [0, NL] x [0, D] on top of body 2 =
 * [0, NL] x [-D, 0] (D = depth L), non-matching structured meshes (P1 or Q1): body 1 has n cells
 * per wavelength along x, body 2 round(ratio2 n N) cells over the whole length (ratio2 = 0.83:
 * the two meshes line up at x = 0 and NL only, not at every crest). In depth the rows are graded
 * from the interface: y = D t^g for t uniform in [0, 1] with ny = ceil((D/h)^(1/g)) rows, so the
 * first row is at most the interface spacing h and the last about g D / ny (the periodic stresses
 * decay like exp(-2 pi y / L): at D = L they are 2e-3 of the interface's).
 * The waviness goes in as the initial gap (default): mc_set_gap_offset on every body-1 contact
 * node, g0(x) = Delta (1 - cos(2 pi x / L)), crests touching at x = 0, L, 2L, ..., both surfaces
 * flat. With the mortar method the constraint rows are nodal (the cone K_h: nodal values of
 * u1.n + pi_h(u2).n against g0_j), so this is the sampled gap exactly, and the normals are the
 * exact vertical ones. Or (wavy_mesh = 1) body 2's top is meshed wavy, y = -Delta (1 - cos(...)),
 * the shift fading linearly to 0 at its bottom, and the library measures the gap on its smooth
 * surface: the same problem up to O(Delta / L) geometry.
 * Supports: u_x = 0 on the left and right sides of both bodies (rollers; the sides are mirror
 * lines through crests, so the strip is exactly the periodic problem, ends included), u_y = 0 on
 * body 2's bottom; the pressure pm on body 1's top; body 1 held vertically by contact alone.
 * Materials: body 1 E = 1, nu = 0.3; body 2 E = 2, nu = 0.2 (dissimilar, so that E* is tested);
 * L = 1, Delta = 1e-3 L (linear theory).
 * The "plain" model: the same meshes and loads, no contact, body 1 held by u_y = 0 on its bottom.
 *
 * Choices, measured (bench/westergaard, condensed path, crest-node pressure against p0; N = 2
 * or 4, n = 40 unless said):
 * - depth: Q1 uniform rows, D = 0.75, 1, 1.5 L: -0.236, -0.113, -0.105 %; so D = L moves p0 by
 *   about 0.01 % (0.5 L: -1.4 %).
 * - element and grading (D = L): Q1 g = 1, 1.25, 1.5: -0.11, +0.01, +0.25 % (graded rows of tall
 *   cells stiffen); P1 the same: +0.55, +0.90, +1.57 %. Default Q1, g = 1.25: 284199 unknowns at
 *   N = 100, n = 40 (g = 1: 5.5 x 10^5; g = 1.5: 1.8 x 10^5).
 * - gap offsets against a wavy body-2 mesh (N = 4, g = 1.25), n = 20, 40, 80, 160: +0.41 / +0.34,
 *   +0.065 / +0.044, +0.072 / +0.059, +0.014 / +0.002 %; same active counts but at n = 80
 *   (117 / 121: edge nodes with tiny forces). Equivalent to a fraction of the error; the offsets
 *   are kept: no geometry in the gap, exact vertical normals.
 */
#ifndef MC_WESTERGAARD_SCENE_H
#define MC_WESTERGAARD_SCENE_H

#include "mortarcontact.h"
#include "scenes.h"

typedef struct wg_params {
  int wavelengths;   /* N */
  int cells;         /* n: body-1 cells per wavelength along the interface */
  double ratio2;     /* body-2 cells along x per body-1 cell */
  int npc;           /* 3 (P1) or 4 (Q1) */
  double depth;      /* of each body, in wavelengths */
  double grading;    /* exponent g of the depth grading (1: uniform rows of height h) */
  double load;       /* pm / p* */
  int wavy_mesh;     /* 0: waviness as gap offsets on body 1; 1: body 2's top meshed wavy */
} wg_params;

/* N = 100, n = 40, ratio2 = 0.83, Q1, depth 1, grading 1.25, pm/p* = 0.3, gap offsets. */
wg_params wg_default_params(void);

typedef struct wg_scene {
  wg_params prm;
  sc_mesh mesh[2];
  double length, amplitude;      /* L, Delta */
  double young[2], poisson[2];
  double e_star, p_star, pm;     /* E*, p*, the mean pressure */
  double a_exact, p0_exact;      /* Westergaard's half-width and peak */
} wg_scene;

/* Builds the meshes. Returns 0, or nonzero on bad parameters. */
int wg_scene_build(wg_scene *s, const wg_params *prm);
void wg_scene_free(wg_scene *s);

/* The model: contact = 1 the contact scene (interface_solver: MC_INTERFACE_*), 0 the plain one.
   NULL on failure (the library's message printed on stderr). */
mc_model *wg_model(const wg_scene *s, int contact, int interface_solver);

typedef struct wg_result {
  long dofs, contact_nodes, active_nodes, iterations, interface_solver;
  int crests;              /* interior crests measured (x = kL, 0 < k < N; both ends if N = 1) */
  int patches;             /* runs of active body-1 nodes along the interface */
  double p0_mean, p0_min, p0_max; /* crest-node pressures over those crests */
  double a_mean;           /* half-width: last active node + h/2, both sides, averaged */
  double a_last_min, a_last_max; /* distance crest - last active node, over crests and sides */
  double profile_error;    /* max |p - p(x)| / p0 at nodes within 0.8 a of a measured crest */
  double gap_residual;     /* MC_INFO_GAP_RESIDUAL */
  double h;                /* body-1 spacing along x */
} wg_result;

/* Reads a solved contact model's answer into *r. Returns 0, nonzero on a library error.
   pressure (may be NULL): gets the contact pressures (MC_INFO_CONTACT_NODES of them, caller
   allocates mc_get_contact_count's count). */
int wg_measure(mc_model *m, const wg_scene *s, wg_result *r, double *pressure);

#endif /* MC_WESTERGAARD_SCENE_H */
