/*
 * fuzz_api.c - a libFuzzer target that drives the whole C API from a byte stream.
 *
 * The input is read as a little program: one opcode byte (taken modulo OP_COUNT), then that
 * operation's operands, until the bytes run out (a read past the end gives 0). Sizes are
 * bounded (grid meshes up to 8 x 6 cells, host bodies on lattices up to 17 x 13 nodes, raw
 * arrays up to 16 entries, 64 load steps, 128 operations and 6 solves per input), so one input runs in
 * milliseconds.
 *
 * Nothing here asserts on a status: bad input is the point. What is checked after every call:
 *   - the status is one of the mc_status values;
 *   - mc_errmsg(m) is a NUL-terminated string, "" after MC_OK and non-empty after a failure;
 *   - every output array is exactly as large as the header says (heap blocks of that size,
 *     so AddressSanitizer reports a write beyond it);
 * and, by the sanitizers, no crash, no leak, no undefined behaviour, no C++ exception across
 * the C ABI (it would abort). A violated check calls abort().
 *
 * Encoding of operands (see read_real, read_id, read_count below):
 *   real : byte b < 16: a special value (0, 1, -1, 0.3, 0.5, NaN, +-inf, 1e300, ...);
 *          16 <= b < 240: (b - 128) / 8; b >= 240: the next 8 bytes as a little-endian double.
 *   id   : byte b < 240: b - 4 (so -4 .. 235); b >= 240: a special (INT_MIN, INT_MAX, ...) or
 *          the next 4 bytes as a little-endian int32.
 *   count: byte b: b % (max + 1), except 255, which gives -1.
 *   body : byte b: 1 + (b & 1), except b >= 250: 250 -> 0, 251 -> 3, 252 -> -1, 253 -> 4,
 *          254 -> 5, 255 -> 6. Bytes below 250 and 250..252 mean what they meant before
 *          assemblies (issue 32); 253..255 gave -1, and give 4, 5, 6 now: bodies that do not
 *          exist on a model of two bodies (every older input runs as before), bodies 4 and 5
 *          once OP_BODY_COUNT has made them (a model holds up to 5 here, 6 is always bad).
 *   body': (the assembly opcodes OP_ADD_PAIR, OP_PAIR_SURFACE) byte b < 240: 1 + b % 5 (any
 *          body a model may have here); b >= 240: a bad body (0, -1, 6, INT_MAX, INT_MIN, 1000).
 *   pair : byte b < 240: 1 + b % 3; b >= 240: 0, -1, 4, INT_MAX, INT_MIN or 1000 (pairs are
 *          numbered 1, 2, ... whatever the index base).
 *   law  : (OP_FRICTION) byte b < 240: b % 5 - 1 (-1 bad, MC_FRICTION_NONE, _TRESCA, _COULOMB,
 *          3 bad); b >= 240: 0, -1, 6, INT_MAX, INT_MIN or 1000.
 * Every read of the stream is its own statement or declarator (never two reads in one
 * expression: gcc and clang evaluate function arguments in different orders).
 * The seed corpus (tests/fuzz/corpus/) is written by tests/fuzz/make_corpus.py, which
 * documents the operations' operand order once more; keep the two in step. The campaigns'
 * findings kept there (finding_*) are raw inputs: when friction appended OP_FRICTION and
 * OP_RESET_HISTORY (OP_COUNT 35 -> 37) and two options (b % 14 -> b % 16), their opcode bytes
 * were rewritten as the operation numbers they meant and their option bytes as b % 14, so they
 * replay the same calls as before (compared with FUZZ_API_TRACE=1).
 *
 * Built two ways: with -fsanitize=fuzzer (CMake option MC_BUILD_FUZZ, clang only) it is the
 * fuzz target; with replay_main.c it is a plain program that runs the files named on its
 * command line (the ctest fuzz_corpus_replay, also under ASan/UBSan and valgrind).
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mortarcontact.h"


/* Counters for the replay driver (how far the corpus reaches); not used by the library. */
long fuzz_api_solves_ok = 0, fuzz_api_contact_solves_ok = 0, fuzz_api_host_solves_ok = 0;
long fuzz_api_pair_solves_ok = 0; /* solves with contact positions on two pairs or more */
long fuzz_api_friction_solves_ok = 0; /* solves with a sticking or slipping friction row */

enum {
  MAX_OPS = 128,
  MAX_SOLVES = 6,
  MAX_RAW = 16,
  MAX_NX = 8,
  MAX_NY = 6,
  MAX_SIDE = MAX_NX > MAX_NY ? MAX_NX : MAX_NY,
  MAX_LATTICE = (2 * MAX_NX + 1) * (2 * MAX_NY + 1), /* nodes of a host body's lattice */
  MAX_ELEMENTS = 4,                                  /* elements of OP_ELEMENTS_RAW */
  MAX_BODIES = 5,                                    /* bodies the harness tracks (OP_BODY_COUNT) */
  MAX_PAIR = 3                                       /* pairs queried: 0 (bad) .. MAX_PAIR */
};

typedef struct {
  const uint8_t *p;
  size_t n;
} stream;

static uint8_t read_u8(stream *s) {
  if (s->n == 0) return 0;
  s->n--;
  return *s->p++;
}

static uint64_t read_bytes(stream *s, int count) {
  uint64_t v = 0;
  int k;
  for (k = 0; k < count; ++k) v |= (uint64_t)read_u8(s) << (8 * k);
  return v;
}

static double read_real(stream *s) {
  static const double special[16] = {0.0, 1.0, -1.0, 0.3, 0.5, 0.4999999, -0.9999999, 1e-300,
                                     1e300, DBL_MAX, 0.0 /* NaN */, 0.0 /* inf */, 0.0 /* -inf */, 1e-8, 100.0, -0.5};
  uint8_t b = read_u8(s);
  if (b < 16) {
    if (b == 10) return NAN;
    if (b == 11) return INFINITY;
    if (b == 12) return -INFINITY;
    return special[b];
  }
  if (b < 240) return (b - 128) / 8.0;
  {
    uint64_t bits = read_bytes(s, 8);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
  }
}

static mc_int read_id(stream *s) {
  uint8_t b = read_u8(s);
  if (b < 240) return (mc_int)b - 4;
  switch (b) {
    case 240: return INT32_MIN;
    case 241: return INT32_MAX;
    case 242: return INT32_MIN + 1;
    case 243: return INT32_MAX - 1;
    case 244: return -1000000;
    case 245: return 1000000;
    default: return (mc_int)(int32_t)(uint32_t)read_bytes(s, 4);
  }
}

/* id + base without int overflow (INT32_MAX stays INT32_MAX: the extremes are tested as such) */
static mc_int plus_base(mc_int id, int base) {
  int64_t v = (int64_t)id + base;
  return v > INT32_MAX || v < INT32_MIN ? id : (mc_int)v;
}

static mc_int read_count(stream *s, int max) {
  uint8_t b = read_u8(s);
  if (b == 255) return -1;
  return (mc_int)(b % (max + 1));
}

static int read_body(stream *s) {
  static const int high[6] = {0, 3, -1, 4, 5, 6}; /* bytes 250 .. 255 */
  uint8_t b = read_u8(s);
  if (b >= 250) return high[b - 250];
  return 1 + (b & 1);
}

static const int bad_numbers[6] = {0, -1, 6, INT32_MAX, INT32_MIN, 1000};

/* A body of the assembly opcodes: 1 .. 5 or a bad one. */
static int read_any_body(stream *s) {
  uint8_t b = read_u8(s);
  if (b >= 240) return bad_numbers[(b - 240) % 6];
  return 1 + b % 5;
}

/* A pair number: 1 .. 3 or a bad one (4 is bad until a fourth pair is made). */
static int read_pair(stream *s) {
  uint8_t b = read_u8(s);
  if (b >= 240) return b % 6 == 2 ? 4 : bad_numbers[(b - 240) % 6];
  return 1 + b % 3;
}

/* ---- the contract checks ------------------------------------------------------------- */

static void fuzz_fail(const char *what, const char *call) {
  fprintf(stderr, "fuzz_api: %s after %s\n", what, call);
  abort();
}

static void check_message(const char *msg, const char *call) {
  size_t len;
  if (!msg) fuzz_fail("mc_errmsg returned NULL", call);
  len = strlen(msg); /* reads up to the NUL: ASan reports if the string is not valid memory */
  if (len > 4096) fuzz_fail("mc_errmsg is implausibly long", call);
}

/* FUZZ_API_TRACE=1 prints every operation (its opcode and where its bytes start) and every
   call with its status (for writing seeds, and for comparing two builds' replays). */
static int tracing(void) {
  static int trace = -1;
  if (trace < 0) trace = getenv("FUZZ_API_TRACE") != NULL;
  return trace;
}

static mc_status checked(mc_model *m, mc_status st, const char *call) {
  const char *msg = mc_errmsg(m);
  if (tracing()) fprintf(stderr, "%-60.60s %-22s %s\n", call, mc_status_string(st), msg ? msg : "(null)");
  if ((int)st < (int)MC_OK || (int)st > (int)MC_ERROR_INTERNAL) fuzz_fail("status out of range", call);
  check_message(msg, call);
  if (strcmp(mc_status_string(st), "unknown status") == 0) fuzz_fail("no name for a status", call);
  if (m) {
    if (st == MC_OK && msg[0] != '\0') fuzz_fail("message after MC_OK", call);
    if (st != MC_OK && msg[0] == '\0') fuzz_fail("empty message after a failure", call);
  }
  return st;
}

#define CALL(expr) checked(m, (expr), #expr)

/* ---- what the harness knows about the model ------------------------------------------ */

typedef struct {
  int meshed; /* a mesh or a host body: n_nodes (and n_cells, 0 for a host body) are known */
  int host;   /* a host body: n_equations is known */
  mc_int n_nodes, n_cells, n_equations;
  /* side edges of the last grid mesh or host lattice (0-based, counter-clockwise: the body on
     their left), if it came from OP_GRID_MESH or OP_HOST_BODY, with their middles on a
     quadratic grid or a lattice of order 2 */
  int grid, has_mid;
  mc_int n_side[4];
  mc_int side[4][2 * MAX_SIDE];
  mc_int side_mid[4][MAX_SIDE];
  /* a host body's lattice (OP_HOST_BODY): node j * nI + i, its equations 0-based (-1: none) */
  int nI, nJ;
  double xy[2 * MAX_LATTICE];
  mc_int eq[2 * MAX_LATTICE];
} body_state;

typedef struct {
  mc_model *m;
  int base;
  body_state body[MAX_BODIES]; /* bodies 1 .. MAX_BODIES (OP_BODY_COUNT) */
  int solves;
  long log_lines;
} harness;

static void log_callback(void *user_data, mc_log_level level, const char *message) {
  harness *h = (harness *)user_data;
  if (level != MC_LOG_PHASE && level != MC_LOG_ITERATION) fuzz_fail("bad log level", "log callback");
  check_message(message, "log callback");
  h->log_lines++;
}

static void reset_model(harness *h) {
  mc_destroy(h->m);
  h->m = NULL;
  memset(h->body, 0, sizeof h->body);
  h->base = 0;
  if (mc_create(&h->m) != MC_OK || !h->m) fuzz_fail("mc_create failed", "mc_create");
}

static body_state *tracked(harness *h, int body) {
  return body >= 1 && body <= MAX_BODIES ? &h->body[body - 1] : NULL;
}

/* ---- queries with exactly sized buffers ---------------------------------------------- */

static void *exact(size_t count, size_t size) {
  void *p = malloc(count ? count * size : 1);
  if (!p) abort();
  return p;
}

static void query_all(harness *h) {
  mc_model *m = h->m;
  int body, info;
  for (info = 0; info <= 33; ++info) { /* 0 and 33 (past MC_INFO_TIME_RESULTS = 32): bad infos */
    int64_t iv;
    double rv;
    CALL(mc_get_info_int(m, info, &iv));
    CALL(mc_get_info_real(m, info, &rv));
  }
  for (body = 0; body <= MAX_BODIES + 1; ++body) { /* 0 and MAX_BODIES + 1: bad bodies */
    const body_state *b = tracked(h, body);
    size_t nodes = b && b->meshed ? (size_t)b->n_nodes : 0, cells = b && b->meshed ? (size_t)b->n_cells : 0;
    double *u = exact(2 * nodes, sizeof(double)), *sigma = exact(4 * cells, sizeof(double));
    double *sigma_n = exact(4 * nodes, sizeof(double)), *r = exact(2 * nodes, sizeof(double));
    double *eta = exact(cells, sizeof(double));
    mc_status su = CALL(mc_get_displacement(m, body, u));
    CALL(mc_get_stress(m, body, sigma));
    CALL(mc_get_nodal_stress(m, body, sigma_n));
    if (CALL(mc_get_error_indicator(m, body, eta)) == MC_OK && !(b && b->meshed && !b->host))
      fuzz_fail("error indicators of a body without cells", "mc_get_error_indicator");
    CALL(mc_get_reaction(m, body, r));
    if (su == MC_OK && !(b && b->meshed)) fuzz_fail("displacements of a body without a mesh", "mc_get_displacement");
    free(u), free(sigma), free(sigma_n), free(r), free(eta);
    {
      /* equation vectors: n_equations of a host body, 2 per node of a mesh body */
      size_t n_eq = b && b->meshed ? (b->host ? (size_t)b->n_equations : 2 * (size_t)b->n_nodes) : 0;
      double *ue = exact(n_eq, sizeof(double)), *re = exact(n_eq, sizeof(double));
      if (CALL(mc_get_equation_solution(m, body, ue)) == MC_OK && !(b && b->meshed))
        fuzz_fail("equation solution of a body without a mesh", "mc_get_equation_solution");
      CALL(mc_get_contact_load(m, body, re));
      free(ue), free(re);
    }
  }
  {
    mc_int n = -1;
    if (CALL(mc_get_contact_count(m, &n)) == MC_OK) {
      size_t c;
      mc_int *nodes;
      double *p, *f, *g, *g0, *nrm;
      if (n < 0) fuzz_fail("negative contact count", "mc_get_contact_count");
      c = (size_t)n;
      nodes = exact(c, sizeof(mc_int));
      p = exact(c, sizeof(double)), f = exact(c, sizeof(double)), g = exact(c, sizeof(double));
      g0 = exact(c, sizeof(double)), nrm = exact(2 * c, sizeof(double));
      CALL(mc_get_contact_nodes(m, nodes));
      CALL(mc_get_contact_pressure(m, p));
      CALL(mc_get_contact_force(m, f));
      CALL(mc_get_contact_gap(m, g));
      CALL(mc_get_contact_initial_gap(m, g0));
      CALL(mc_get_contact_normal(m, nrm));
      free(nodes), free(p), free(f), free(g), free(g0), free(nrm);
    }
  }
  {
    /* every pair 0 (bad) .. MAX_PAIR and every field 0 .. 10 (0 and 10 bad; 6 .. 9 friction's:
       shear, slip, accumulated slip, state), buffers of exactly the count the library gave (none
       where it refused the count) */
    int pair, field;
    for (pair = 0; pair <= MAX_PAIR; ++pair) {
      mc_int n = -1;
      size_t c = 0;
      mc_int *nodes;
      if (CALL(mc_get_pair_contact_count(m, pair, &n)) == MC_OK) {
        if (n < 0) fuzz_fail("negative pair contact count", "mc_get_pair_contact_count");
        c = (size_t)n;
      }
      nodes = exact(c, sizeof(mc_int));
      CALL(mc_get_pair_contact_nodes(m, pair, nodes));
      free(nodes);
      for (field = 0; field <= 10; ++field) {
        double *out = exact(field == MC_CONTACT_NORMAL ? 2 * c : c, sizeof(double));
        CALL(mc_get_pair_contact(m, pair, field, out));
        free(out);
      }
    }
  }
}

/* Every entry point with NULL for the model or for an output. */
static void null_calls(harness *h) {
  mc_model *m = NULL;
  mc_int id = 0, edge[2] = {0, 1};
  double v[2] = {0, 0};
  int64_t iv;
  double rv;
  check_message(mc_errmsg(NULL), "mc_errmsg(NULL)");
  check_message(mc_status_string((mc_status)1234), "mc_status_string");
  check_message(mc_version_string(), "mc_version_string");
  if (mc_create(NULL) != MC_ERROR_ARGUMENT) fuzz_fail("mc_create(NULL) accepted", "mc_create");
  mc_destroy(NULL);
  CALL(mc_set_index_base(m, 0));
  CALL(mc_set_plane(m, 0, 1));
  CALL(mc_set_mesh(m, 1, 3, v, 1, 3, edge));
  CALL(mc_set_material(m, 1, 1, 0.3));
  CALL(mc_set_cell_elasticity(m, 1, v));
  CALL(mc_fix(m, 1, 1, &id, MC_XY, NULL));
  CALL(mc_add_traction(m, 1, 1, edge, v));
  CALL(mc_add_pressure(m, 1, 1, edge, v));
  CALL(mc_add_nodal_force(m, 1, 1, &id, v));
  CALL(mc_set_body_force(m, 1, 0, 0));
  CALL(mc_clear_loads(m, 1));
  CALL(mc_set_contact(m, 1, 1, edge));
  CALL(mc_set_option_int(m, MC_OPTION_METHOD, 0));
  CALL(mc_set_option_real(m, MC_OPTION_TOLERANCE, 1e-8));
  CALL(mc_solve(m));
  CALL(mc_get_info_int(m, MC_INFO_DOFS, &iv));
  CALL(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &rv));
  CALL(mc_get_displacement(m, 1, v));
  CALL(mc_get_stress(m, 1, v));
  CALL(mc_get_nodal_stress(m, 1, v));
  CALL(mc_get_error_indicator(m, 1, v));
  CALL(mc_get_reaction(m, 1, v));
  CALL(mc_get_contact_count(m, &id));
  CALL(mc_get_contact_nodes(m, &id));
  CALL(mc_get_contact_pressure(m, v));
  CALL(mc_get_contact_force(m, v));
  CALL(mc_get_contact_gap(m, v));
  CALL(mc_get_contact_initial_gap(m, v));
  CALL(mc_get_contact_normal(m, v));
  CALL(mc_set_gap_offset(m, 1, &id, v));
  {
    int pair = 0;
    CALL(mc_set_body_count(m, 3));
    CALL(mc_add_contact_pair(m, 1, 2, &pair));
    CALL(mc_set_pair_surface(m, 1, 1, 1, edge));
    CALL(mc_set_pair_surface_curved(m, 1, 1, 1, edge));
    CALL(mc_set_pair_gap_offset(m, 1, 1, &id, v));
    CALL(mc_get_pair_contact_count(m, 1, &id));
    CALL(mc_get_pair_contact_nodes(m, 1, &id));
    CALL(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, v));
    CALL(mc_set_friction(m, 1, MC_FRICTION_COULOMB, 0.3));
    CALL(mc_reset_history(m));
  }
  CALL(mc_set_log_callback(m, NULL, NULL));
  CALL(mc_write_vtu(m, "/dev/null"));
  {
    mc_int eq2[2] = {0, 1}, ptr[2] = {0, 2}, edge3[3] = {0, 1, 2};
    double k4[4] = {1, 0, 0, 1};
    CALL(mc_set_host_body(m, 1, 1, v, eq2, 2));
    CALL(mc_add_stiffness(m, 1, 2, eq2, eq2, v, MC_MATRIX_FULL));
    CALL(mc_add_element_matrices(m, 1, 1, ptr, eq2, k4));
    CALL(mc_set_load_vector(m, 1, 2, v));
    CALL(mc_get_equation_solution(m, 1, v));
    CALL(mc_get_contact_load(m, 1, v));
    CALL(mc_set_contact_curved(m, 1, 1, edge3));
  }
  /* NULL outputs on a real model */
  m = h->m;
  CALL(mc_get_info_int(m, MC_INFO_DOFS, NULL));
  CALL(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, NULL));
  CALL(mc_get_displacement(m, 1, NULL));
  CALL(mc_get_stress(m, 2, NULL));
  CALL(mc_get_nodal_stress(m, 2, NULL));
  {
    CALL(mc_get_error_indicator(m, 1, NULL));
    CALL(mc_get_error_indicator(m, 2, NULL));
  }
  CALL(mc_get_reaction(m, 1, NULL));
  CALL(mc_get_contact_count(m, NULL));
  CALL(mc_get_contact_nodes(m, NULL));
  CALL(mc_get_contact_pressure(m, NULL));
  CALL(mc_get_contact_force(m, NULL));
  CALL(mc_get_contact_gap(m, NULL));
  CALL(mc_get_contact_initial_gap(m, NULL));
  CALL(mc_get_contact_normal(m, NULL));
  CALL(mc_write_vtu(m, NULL));
  CALL(mc_get_equation_solution(m, 1, NULL));
  CALL(mc_get_contact_load(m, 2, NULL));
  CALL(mc_get_pair_contact_count(m, 1, NULL));
  CALL(mc_get_pair_contact_nodes(m, 1, NULL));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_NORMAL, NULL));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, NULL));
  CALL(mc_set_pair_surface(m, 1, 1, 1, NULL));
  CALL(mc_set_pair_gap_offset(m, 1, 1, NULL, NULL));
}

/* ---- operations ---------------------------------------------------------------------- */

enum {
  OP_NEW_MODEL,      /* -                                                           */
  OP_INDEX_BASE,     /* byte: base = byte % 4 - 1                                   */
  OP_PLANE,          /* byte: plane = byte % 3 - (byte >= 128); real: thickness     */
  OP_GRID_MESH,      /* body, byte kind (b % 7: npc 3, 4, 4, 6, 4, 8, 9), byte nx, byte ny, real x0, y0, lx, ly,
                        byte distortion, real bow, byte corrupt [, corruption operands] */
  OP_RAW_MESH,       /* body, count n_nodes, 2n reals, count n_cells, byte npc (2..5), ids, byte nulls */
  OP_MATERIAL,       /* body, real young, real poisson                              */
  OP_CELL_LAW,       /* body, real young, real poisson, byte cell, byte entry, real value, byte null */
  OP_FIX_SIDE,       /* body, byte side, byte mask (b % 5), byte has_values, [real vx, vy] */
  OP_FIX_RAW,        /* body, count n, n ids, byte mask, byte has_values, [2n reals] */
  OP_TRACTION_SIDE,  /* body, byte side, real tx, real ty                           */
  OP_PRESSURE_SIDE,  /* body, byte side, real p                                     */
  OP_EDGE_LOAD_RAW,  /* body, byte kind (0 traction, 1 pressure), count n, 2n ids, reals, byte nulls */
  OP_NODAL_FORCE,    /* body, count n, n ids, 2n reals                              */
  OP_BODY_FORCE,     /* body, real fx, real fy                                      */
  OP_CLEAR_LOADS,    /* body                                                        */
  OP_CONTACT_SIDE,   /* body, byte side, byte first, byte count (0: all)            */
  OP_CONTACT_RAW,    /* body, count n, 2n ids                                       */
  OP_OPTION_INT,     /* byte option (b % 16), byte kind: < 200: b % 6 - 1; else 8 raw bytes */
  OP_OPTION_REAL,    /* byte option (b % 16), real value                            */
  OP_SOLVE,          /* - (then queries every result)                               */
  OP_QUERY,          /* - (queries every result)                                    */
  OP_GAP_OFFSET,     /* count n, n ids, n reals (needs mc_set_gap_offset)           */
  OP_LOG,            /* byte on                                                     */
  OP_WRITE_VTU,      /* byte which path                                             */
  OP_NULLS,          /* - (every entry point with NULL model / NULL outputs)        */
  /* host bodies (issue 22), appended so that the older seeds keep their meaning: */
  OP_HOST_BODY,      /* body, byte order (b % 2 + 1), byte nx, byte ny, real x0, y0, lx, ly, byte restrain
                        (b % 6), byte shuffle, byte corrupt (b % 8) [, corruption operands] */
  OP_HOST_STIFFNESS, /* body, byte mode (b % 3: coordinates full, one triangle, element matrices),
                        real young, real poisson, byte corrupt (b % 7) [, corruption operands] */
  OP_STIFFNESS_RAW,  /* body, count n, n ids rows, n ids cols, n reals, byte storage (b % 4), byte nulls */
  OP_ELEMENTS_RAW,   /* body, count n_elements (<= 4), per element: count k (<= 4), k ids, k*k reals;
                        byte corrupt (b % 4) [, id] */
  OP_LOAD_VECTOR,    /* body, byte kind (b % 4), real fx, real fy [, kind 1: count n, n reals] */
  OP_CONTACT_CURVED, /* body, byte side, byte first, byte count (0: all), byte mode (b % 3)
                        [, mode 2: count n, 3n ids] */
  /* assemblies (issue 32), appended likewise: */
  OP_BODY_COUNT,      /* byte: n = b % 6 (0 and 1 bad; a model here holds at most 5 bodies) */
  OP_ADD_PAIR,        /* body' nonmortar, body' mortar                              */
  OP_PAIR_SURFACE,    /* pair, body', byte side, byte first, byte count (0: all), byte mode (b % 4:
                         0 straight, 1 curved with the side's middles, 2 curved with an end and the
                         middle swapped, 3 straight from the stream: count n, 2n ids) */
  OP_PAIR_GAP_OFFSET, /* pair, count n, n ids, n reals                             */
  /* friction (issue 33), appended likewise: */
  OP_FRICTION,        /* pair, law, real value (mc_set_friction)                     */
  OP_RESET_HISTORY,   /* - (mc_reset_history)                                         */
  OP_COUNT
};

/* A structured grid of any cell kind: the lattice of corners (order 1) or of corners and
   mid-edge points (order 2, (2 nx + 1) x (2 ny + 1) points, a Q8 grid without the squares'
   centres), bowed and distorted as one, sides as corner pairs. */
static void op_grid_mesh(harness *h, stream *s) {
  static const int kinds[7] = {3, 4, 4, 6, 4, 8, 9};
  mc_model *m = h->m;
  int body = read_body(s), npc = kinds[read_u8(s) % 7], nx = 1 + read_u8(s) % MAX_NX, ny = 1 + read_u8(s) % MAX_NY;
  double x0 = read_real(s), y0 = read_real(s), lx = read_real(s), ly = read_real(s);
  double distortion = (read_u8(s) % 32) / 128.0, bow = read_real(s);
  int corrupt = read_u8(s) % 4; /* 0 none, 1 one coordinate, 2 one cell id, 3 swap two ids of a cell */
  const int o = npc > 4 ? 2 : 1, quad = npc == 4 || npc == 8 || npc == 9, nI = o * nx + 1, nJ = o * ny + 1;
  mc_int n_cells = quad ? nx * ny : 2 * nx * ny, n_nodes = 0;
  double xy[2 * (2 * MAX_NX + 1) * (2 * MAX_NY + 1)];
  mc_int cells[12 * MAX_NX * MAX_NY], id[(2 * MAX_NX + 1) * (2 * MAX_NY + 1)]; /* T6: 2 x 6 per square */
  int i, j, k;
  unsigned state = 12345u;
  if (lx == 0) lx = 1;
  if (ly == 0) ly = 1;
  k = 0;
  for (j = 0; j < ny; ++j)
    for (i = 0; i < nx; ++i) {
      const int I = o * i, J = o * j;
      const mc_int a = J * nI + I, b = a + o, c = b + o * nI, d = a + o * nI;
      if (quad) {
        cells[k++] = a, cells[k++] = b, cells[k++] = c, cells[k++] = d;
        if (o == 2) {
          cells[k++] = a + 1, cells[k++] = b + nI, cells[k++] = d + 1, cells[k++] = a + nI;
          if (npc == 9) cells[k++] = a + nI + 1;
        }
      } else {
        cells[k++] = a, cells[k++] = b, cells[k++] = c;
        if (o == 2) cells[k++] = a + 1, cells[k++] = b + nI, cells[k++] = a + nI + 1;
        cells[k++] = a, cells[k++] = c, cells[k++] = d;
        if (o == 2) cells[k++] = a + nI + 1, cells[k++] = d + 1, cells[k++] = a + nI;
      }
    }
  for (k = 0; k < nI * nJ; ++k) id[k] = -1;
  for (k = 0; k < npc * n_cells; ++k) id[cells[k]] = 0;
  for (k = 0; k < nI * nJ; ++k)
    if (id[k] == 0) id[k] = n_nodes++;
  for (j = 0; j < nJ; ++j)
    for (i = 0; i < nI; ++i) {
      const int n = id[j * nI + i];
      if (n < 0) continue;
      double t = 2.0 * i / (nI - 1) - 1;
      xy[2 * n] = x0 + lx * i / (nI - 1);
      xy[2 * n + 1] = y0 + ly * j / (nJ - 1) + bow * t * t * (1.0 - (double)j / (nJ - 1));
      if (i > 0 && j > 0 && i < nI - 1 && j < nJ - 1 && distortion > 0) {
        state = state * 1103515245u + 12345u;
        xy[2 * n] += distortion * lx / nx * (((state >> 8) & 0xffff) / 65536.0 - 0.5);
        state = state * 1103515245u + 12345u;
        xy[2 * n + 1] += distortion * ly / ny * (((state >> 8) & 0xffff) / 65536.0 - 0.5);
      }
    }
  for (k = 0; k < npc * n_cells; ++k) cells[k] = id[cells[k]] + h->base;
  if (corrupt == 1) { /* the position first, then the value: one order whatever the compiler */
    const int where = read_u8(s) % (2 * n_nodes);
    xy[where] = read_real(s);
  } else if (corrupt == 2) {
    int where = read_u8(s) % (npc * n_cells);
    cells[where] = plus_base(read_id(s), h->base);
  } else if (corrupt == 3) {
    int c = read_u8(s) % n_cells, a = read_u8(s) % npc, b = read_u8(s) % npc;
    mc_int tmp = cells[npc * c + a];
    cells[npc * c + a] = cells[npc * c + b], cells[npc * c + b] = tmp;
  }
  if (CALL(mc_set_mesh(m, body, n_nodes, xy, n_cells, npc, cells)) == MC_OK) {
    body_state *b = tracked(h, body);
#define C(I, J) id[(J) * nI + (I)]
    memset(b, 0, sizeof *b);
    b->meshed = 1, b->n_nodes = n_nodes, b->n_cells = n_cells, b->grid = 1;
    for (i = 0; i < nx; ++i) { /* bottom, left to right; top, right to left (corner pairs) */
      b->side[0][2 * i] = C(o * i, 0), b->side[0][2 * i + 1] = C(o * (i + 1), 0);
      b->side[2][2 * i] = C(o * (nx - i), nJ - 1), b->side[2][2 * i + 1] = C(o * (nx - i - 1), nJ - 1);
    }
    for (j = 0; j < ny; ++j) { /* right, bottom to top; left, top to bottom */
      b->side[1][2 * j] = C(nI - 1, o * j), b->side[1][2 * j + 1] = C(nI - 1, o * (j + 1));
      b->side[3][2 * j] = C(0, o * (ny - j)), b->side[3][2 * j + 1] = C(0, o * (ny - j - 1));
    }
    if (o == 2) { /* the middles of the side edges, in the same order */
      b->has_mid = 1;
      for (i = 0; i < nx; ++i) b->side_mid[0][i] = C(2 * i + 1, 0), b->side_mid[2][i] = C(2 * (nx - i) - 1, nJ - 1);
      for (j = 0; j < ny; ++j) b->side_mid[1][j] = C(nI - 1, 2 * j + 1), b->side_mid[3][j] = C(0, 2 * (ny - j) - 1);
    }
#undef C
    b->n_side[0] = b->n_side[2] = nx;
    b->n_side[1] = b->n_side[3] = ny;
  }
}

static void op_raw_mesh(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s);
  mc_int n_nodes = read_count(s, MAX_RAW), n_cells, k;
  double xy[2 * MAX_RAW];
  mc_int cells[5 * MAX_RAW];
  int npc, nulls;
  for (k = 0; k < 2 * n_nodes; ++k) xy[k] = read_real(s);
  n_cells = read_count(s, MAX_RAW / 2);
  npc = 2 + read_u8(s) % 4;
  for (k = 0; k < npc * n_cells; ++k) cells[k] = plus_base(read_id(s), h->base);
  nulls = read_u8(s) % 8;
  if (CALL(mc_set_mesh(m, body, n_nodes, nulls == 1 ? NULL : xy, n_cells, npc, nulls == 2 ? NULL : cells)) == MC_OK) {
    body_state *b = tracked(h, body);
    memset(b, 0, sizeof *b);
    b->meshed = 1, b->n_nodes = n_nodes, b->n_cells = n_cells;
  }
}

/* The in-plane isotropic plane-strain law of (young, poisson), row-major Voigt. */
static void isotropic(double young, double poisson, double d[9]) {
  double f = young / ((1 + poisson) * (1 - 2 * poisson));
  memset(d, 0, 9 * sizeof(double));
  d[0] = d[4] = f * (1 - poisson);
  d[1] = d[3] = f * poisson;
  d[8] = f * (1 - 2 * poisson) / 2;
}

static void op_cell_law(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s);
  double young = read_real(s), poisson = read_real(s);
  int cell = read_u8(s), entry = read_u8(s) % 10;
  double value = read_real(s);
  int null = read_u8(s) % 8 == 1;
  const body_state *b = tracked(h, body);
  size_t cells = b && b->meshed && b->n_cells > 0 ? (size_t)b->n_cells : 1, c;
  double *d = exact(9 * cells, sizeof(double));
  for (c = 0; c < cells; ++c) isotropic(young, poisson, d + 9 * c);
  if (entry < 9) d[9 * ((size_t)cell % cells) + (size_t)entry] = value;
  CALL(mc_set_cell_elasticity(m, body, null ? NULL : d));
  free(d);
}

static const mc_int *side_edges(harness *h, int body, int side, mc_int *n) {
  const body_state *b = tracked(h, body);
  static const mc_int none[2] = {0, 1};
  if (!b || !b->grid) {
    *n = 1;
    return none;
  }
  *n = b->n_side[side];
  return b->side[side];
}

/* ids of a side (0-based in the harness) with the index base added */
static void with_base(const harness *h, const mc_int *ids, mc_int n, mc_int *out) {
  mc_int k;
  for (k = 0; k < n; ++k) out[k] = ids[k] + h->base;
}

static void op_fix_side(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), side = read_u8(s) % 4, mask = read_u8(s) % 5, has_values = read_u8(s) & 1;
  double vx = has_values ? read_real(s) : 0, vy = has_values ? read_real(s) : 0;
  mc_int n, k, nodes[MAX_NX + 1], ne;
  const mc_int *edges = side_edges(h, body, side, &ne);
  double values[2 * (MAX_NX + 1)];
  n = ne + 1;
  for (k = 0; k < ne; ++k) nodes[k] = edges[2 * k] + h->base;
  nodes[ne] = edges[2 * ne - 1] + h->base;
  for (k = 0; k < n; ++k) values[2 * k] = vx, values[2 * k + 1] = vy;
  CALL(mc_fix(m, body, n, nodes, mask, has_values ? values : NULL));
}

static void op_fix_raw(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s);
  mc_int n = read_count(s, MAX_RAW), k, nodes[MAX_RAW];
  double values[2 * MAX_RAW];
  int mask, has_values;
  for (k = 0; k < n; ++k) nodes[k] = plus_base(read_id(s), h->base);
  mask = read_u8(s) % 5;
  has_values = read_u8(s) & 1;
  if (has_values)
    for (k = 0; k < 2 * n; ++k) values[k] = read_real(s);
  CALL(mc_fix(m, body, n, n > 0 ? nodes : NULL, mask, has_values ? values : NULL));
}

static void op_side_load(harness *h, stream *s, int pressure) {
  mc_model *m = h->m;
  int body = read_body(s), side = read_u8(s) % 4;
  double tx = read_real(s), ty = pressure ? 0 : read_real(s);
  mc_int ne, k, edges[2 * MAX_NX];
  const mc_int *e = side_edges(h, body, side, &ne);
  double t[2 * MAX_NX];
  with_base(h, e, 2 * ne, edges);
  for (k = 0; k < ne; ++k) {
    if (pressure) t[k] = tx;
    else t[2 * k] = tx, t[2 * k + 1] = ty;
  }
  if (pressure) CALL(mc_add_pressure(m, body, ne, edges, t));
  else CALL(mc_add_traction(m, body, ne, edges, t));
}

static void op_edge_load_raw(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), pressure = read_u8(s) & 1, nulls;
  mc_int n = read_count(s, MAX_RAW), k, edges[2 * MAX_RAW];
  double t[2 * MAX_RAW];
  for (k = 0; k < 2 * n; ++k) edges[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < (pressure ? 1 : 2) * n; ++k) t[k] = read_real(s);
  nulls = read_u8(s) % 8;
  if (pressure) CALL(mc_add_pressure(m, body, n, nulls == 1 ? NULL : edges, nulls == 2 ? NULL : t));
  else CALL(mc_add_traction(m, body, n, nulls == 1 ? NULL : edges, nulls == 2 ? NULL : t));
}

static void op_nodal_force(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s);
  mc_int n = read_count(s, MAX_RAW), k, nodes[MAX_RAW];
  double f[2 * MAX_RAW];
  for (k = 0; k < n; ++k) nodes[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < 2 * n; ++k) f[k] = read_real(s);
  CALL(mc_add_nodal_force(m, body, n, nodes, f));
}

static void op_contact_side(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), side = read_u8(s) % 4, first = read_u8(s), count = read_u8(s);
  mc_int ne, edges[2 * MAX_NX];
  const mc_int *e = side_edges(h, body, side, &ne);
  first %= ne;
  count = count == 0 ? ne - first : 1 + count % (ne - first);
  with_base(h, e + 2 * first, 2 * count, edges);
  CALL(mc_set_contact(m, body, count, edges));
}

static void op_contact_raw(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s);
  mc_int n = read_count(s, MAX_RAW), k, edges[2 * MAX_RAW];
  for (k = 0; k < 2 * n; ++k) edges[k] = plus_base(read_id(s), h->base);
  CALL(mc_set_contact(m, body, n, n > 0 ? edges : NULL));
}

static void op_option_int(harness *h, stream *s) {
  mc_model *m = h->m;
  int option = read_u8(s) % 16; /* 1 .. 15: every option (MC_OPTION_FRICTION_CT = 15) and a bad one (5); 0: MC_OPTION_EAGER_RESULTS (16) */
  if (option == 0) option = MC_OPTION_EAGER_RESULTS;
  uint8_t kind = read_u8(s);
  /* -1 .. 4: every value of the enum options (MC_INTERFACE_AUTO .. _SPARSE = 0 .. 2) and bad ones */
  int64_t value = kind < 200 ? (int64_t)(kind % 6) - 1 : (int64_t)read_bytes(s, 8);
  /* Load steps are a size like the meshes': the library accepts up to 10^6, and a tiny model
     with friction then runs 10^6 solves (112 s under ASan: the timeout CI's campaign found on
     2026-11-27). A valid count above 64 is taken modulo 64; the bad ones (< 1, > 10^6) stay. */
  if (option == MC_OPTION_LOAD_STEPS && value > 64 && value <= 1000000) value = 1 + value % 64;
  CALL(mc_set_option_int(m, option, value));
}

static void op_gap_offset(harness *h, stream *s) {
  mc_model *m = h->m;
  mc_int n = read_count(s, MAX_RAW), k, nodes[MAX_RAW];
  double offset[MAX_RAW];
  for (k = 0; k < n; ++k) nodes[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < n; ++k) offset[k] = read_real(s);
  CALL(mc_set_gap_offset(m, n, n > 0 ? nodes : NULL, n > 0 ? offset : NULL));
}

static void op_write_vtu(harness *h, stream *s) {
  mc_model *m = h->m;
  /* never a .pvd here: it would write files next to the path */
  static const char *paths[3] = {"/dev/null", "/nonexistent-mortarcontact-dir/out.vtu", ""};
  int which = read_u8(s) % 3;
  CALL(mc_write_vtu(m, paths[which]));
}

/* ---- host bodies --------------------------------------------------------------------- */

static unsigned lcg(unsigned *state) {
  *state = *state * 1103515245u + 12345u;
  return (*state >> 8) & 0xffffff;
}

/* A host body on a lattice of (order nx + 1) x (order ny + 1) nodes (order 2: the corners and
   middles of a quadratic grid), its freedoms numbered node by node or shuffled, a side
   restrained (no equation) or none (a floating body), optionally corrupted. */
static void op_host_body(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), o = 1 + read_u8(s) % 2, nx = 1 + read_u8(s) % MAX_NX, ny = 1 + read_u8(s) % MAX_NY;
  double x0 = read_real(s), y0 = read_real(s), lx = read_real(s), ly = read_real(s);
  int restrain = read_u8(s) % 6, shuffle = read_u8(s), corrupt = read_u8(s) % 8;
  const int nI = o * nx + 1, nJ = o * ny + 1, n = nI * nJ;
  double xy[2 * MAX_LATTICE];
  mc_int eq[2 * MAX_LATTICE], call_eq[2 * MAX_LATTICE], n_eq = 0, n_equations;
  int i, j, k;
  unsigned state = 777u + (unsigned)shuffle;
  if (lx == 0) lx = 1;
  if (ly == 0) ly = 1;
  for (j = 0; j < nJ; ++j)
    for (i = 0; i < nI; ++i) {
      const int node = j * nI + i;
      /* 0 none, 1 the bottom clamped, 2 rollers (left x, bottom y), 3 bottom y, 4 every x,
         5 x of the first node (a body contact holds in y) */
      const int no_x = (restrain == 1 && j == 0) || (restrain == 2 && i == 0) || restrain == 4 || (restrain == 5 && node == 0);
      const int no_y = ((restrain == 1 || restrain == 2 || restrain == 3) && j == 0);
      xy[2 * node] = x0 + lx * i / (nI - 1), xy[2 * node + 1] = y0 + ly * j / (nJ - 1);
      eq[2 * node] = no_x ? -1 : n_eq++;
      eq[2 * node + 1] = no_y ? -1 : n_eq++;
    }
  if (shuffle) { /* a permutation of the equation numbers */
    mc_int perm[2 * MAX_LATTICE];
    for (k = 0; k < n_eq; ++k) perm[k] = k;
    for (k = n_eq - 1; k > 0; --k) {
      int r = (int)(lcg(&state) % (unsigned)(k + 1));
      mc_int t = perm[k];
      perm[k] = perm[r], perm[r] = t;
    }
    for (k = 0; k < 2 * n; ++k)
      if (eq[k] >= 0) eq[k] = perm[eq[k]];
  }
  n_equations = n_eq;
  for (k = 0; k < 2 * n; ++k) call_eq[k] = eq[k] >= 0 ? eq[k] + h->base : h->base - 1;
  /* 1 two freedoms share an equation, 2 an equation number read, 3 n_equations read,
     4 NULL xy, 5 NULL equations, 6 a coordinate read, 7 one more equation than the nodes name */
  if (corrupt == 1 && n_eq > 1) call_eq[read_u8(s) % (2 * n)] = h->base;
  else if (corrupt == 2) { /* the position first, then the value (see op_grid_mesh) */
    const int where = read_u8(s) % (2 * n);
    call_eq[where] = plus_base(read_id(s), h->base);
  }
  else if (corrupt == 3) { /* bounded: the harness sizes equation vectors from it */
    n_equations = read_id(s);
    if (n_equations > n_eq + 1000) n_equations = n_eq + 1000;
  }
  else if (corrupt == 6) {
    const int where = read_u8(s) % (2 * n);
    xy[where] = read_real(s);
  }
  else if (corrupt == 7) n_equations++;
  if (CALL(mc_set_host_body(m, body, n, corrupt == 4 ? NULL : xy, corrupt == 5 ? NULL : call_eq, n_equations)) == MC_OK) {
    body_state *b = tracked(h, body);
    memset(b, 0, sizeof *b);
    b->meshed = 1, b->host = 1, b->n_nodes = n, b->n_cells = 0, b->n_equations = n_equations, b->grid = 1;
    b->nI = nI, b->nJ = nJ;
    memcpy(b->xy, xy, 2 * (size_t)n * sizeof(double));
    for (k = 0; k < 2 * n; ++k) b->eq[k] = call_eq[k] < h->base ? -1 : call_eq[k] - h->base;
#define C(I, J) ((J) * nI + (I))
    for (i = 0; i < nx; ++i) {
      b->side[0][2 * i] = C(o * i, 0), b->side[0][2 * i + 1] = C(o * (i + 1), 0);
      b->side[2][2 * i] = C(o * (nx - i), nJ - 1), b->side[2][2 * i + 1] = C(o * (nx - i - 1), nJ - 1);
      if (o == 2) b->side_mid[0][i] = C(2 * i + 1, 0), b->side_mid[2][i] = C(2 * (nx - i) - 1, nJ - 1);
    }
    for (j = 0; j < ny; ++j) {
      b->side[1][2 * j] = C(nI - 1, o * j), b->side[1][2 * j + 1] = C(nI - 1, o * (j + 1));
      b->side[3][2 * j] = C(0, o * (ny - j)), b->side[3][2 * j + 1] = C(0, o * (ny - j - 1));
      if (o == 2) b->side_mid[1][j] = C(nI - 1, 2 * j + 1), b->side_mid[3][j] = C(0, 2 * (ny - j) - 1);
    }
#undef C
    b->has_mid = o == 2;
    b->n_side[0] = b->n_side[2] = nx;
    b->n_side[1] = b->n_side[3] = ny;
  }
}

/* The plane-strain stiffness (row-major 6 x 6) of the P1 triangle a, b, c of a lattice. */
static void p1_stiffness(const double *xy, const int tri[3], double young, double poisson, double k[36]) {
  double x[3], y[3], bm[3][6], d[9], area, inv2a;
  int i, r, c, p, q;
  for (i = 0; i < 3; ++i) x[i] = xy[2 * tri[i]], y[i] = xy[2 * tri[i] + 1];
  area = 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]));
  inv2a = area != 0 ? 1 / (2 * area) : 0;
  memset(bm, 0, sizeof bm);
  for (i = 0; i < 3; ++i) {
    double b = (y[(i + 1) % 3] - y[(i + 2) % 3]) * inv2a, cc = (x[(i + 2) % 3] - x[(i + 1) % 3]) * inv2a;
    bm[0][2 * i] = b, bm[1][2 * i + 1] = cc, bm[2][2 * i] = cc, bm[2][2 * i + 1] = b;
  }
  isotropic(young, poisson, d);
  for (r = 0; r < 6; ++r)
    for (c = 0; c < 6; ++c) {
      double sum = 0;
      for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) sum += bm[p][r] * d[3 * p + q] * bm[q][c];
      k[6 * r + c] = area * sum;
    }
}

/* The stiffness of a host body's lattice (P1 triangles on it) given as coordinate entries, both
   triangles or the lower one, or as element matrices; optionally corrupted. Needs a body that
   OP_HOST_BODY made; on another body, one diagonal entry (refused). */
static void op_host_stiffness(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), mode = read_u8(s) % 3;
  double young = read_real(s), poisson = read_real(s);
  int corrupt = read_u8(s) % 7; /* 1 a value read, 2 an equation read, 3 an asymmetric entry,
                                   4 a negative count, 5 a NULL array, 6 an infinite value */
  const body_state *b = tracked(h, body);
  const int nI = b && b->host ? b->nI : 2, nJ = b && b->host ? b->nJ : 2;
  const size_t n_elements = 2 * (size_t)(nI - 1) * (size_t)(nJ - 1);
  mc_int *rows = exact(36 * n_elements, sizeof(mc_int)), *cols = exact(36 * n_elements, sizeof(mc_int));
  mc_int *eltptr = exact(n_elements + 1, sizeof(mc_int)), *eltvar = exact(6 * n_elements, sizeof(mc_int));
  double *values = exact(36 * n_elements, sizeof(double)), *a_elt = exact(36 * n_elements, sizeof(double));
  static const double unit[2 * 4] = {0, 0, 1, 0, 1, 1, 0, 1};
  const double *xy = b && b->host ? b->xy : unit;
  size_t e = 0, n = 0, at;
  int i, j, t, r, c;
  for (j = 0; j + 1 < nJ; ++j)
    for (i = 0; i + 1 < nI; ++i)
      for (t = 0; t < 2; ++t, ++e) {
        const int a = j * nI + i, tri[3] = {a, t ? a + nI + 1 : a + 1, t ? a + nI : a + nI + 1};
        double k[36];
        mc_int dof[6];
        p1_stiffness(xy, tri, young, poisson, k);
        for (r = 0; r < 6; ++r) {
          mc_int q = b && b->host ? b->eq[2 * tri[r / 2] + r % 2] : (mc_int)(2 * tri[r / 2] + r % 2);
          dof[r] = q >= 0 ? q + h->base : h->base - 1;
        }
        eltptr[e] = (mc_int)(6 * e) + h->base;
        for (c = 0; c < 6; ++c) {
          eltvar[6 * e + (size_t)c] = dof[c];
          for (r = 0; r < 6; ++r) {
            a_elt[36 * e + 6 * (size_t)c + (size_t)r] = k[6 * r + c];
            if (mode == 1 && (dof[r] < h->base || dof[c] < h->base || dof[r] < dof[c])) continue;
            rows[n] = dof[r], cols[n] = dof[c], values[n] = k[6 * r + c], n++;
          }
        }
      }
  eltptr[n_elements] = (mc_int)(6 * n_elements) + h->base;
  at = read_u8(s);
  if (mode < 2) {
    mc_int count = (mc_int)n;
    if (n > 0) at %= n;
    if (corrupt == 1 && n > 0) values[at] = read_real(s);
    else if (corrupt == 2 && n > 0) rows[at] = plus_base(read_id(s), h->base);
    else if (corrupt == 3 && n > 0) values[at] += 1;
    else if (corrupt == 4) count = -1;
    else if (corrupt == 6 && n > 0) values[at] = INFINITY;
    CALL(mc_add_stiffness(m, body, count, corrupt == 5 ? NULL : rows, cols, values,
                          mode == 0 ? MC_MATRIX_FULL : MC_MATRIX_TRIANGLE));
  } else {
    mc_int count = (mc_int)n_elements;
    if (corrupt == 1) a_elt[at % (36 * n_elements)] = read_real(s);
    else if (corrupt == 2) eltvar[at % (6 * n_elements)] = plus_base(read_id(s), h->base);
    else if (corrupt == 3) a_elt[at % (36 * n_elements)] += 1;
    else if (corrupt == 4) count = -1;
    else if (corrupt == 6) a_elt[at % (36 * n_elements)] = NAN;
    CALL(mc_add_element_matrices(m, body, count, eltptr, corrupt == 5 ? NULL : eltvar, a_elt));
  }
  free(rows), free(cols), free(values), free(eltptr), free(eltvar), free(a_elt);
}

static void op_stiffness_raw(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), storage, nulls;
  mc_int n = read_count(s, MAX_RAW), k, rows[MAX_RAW], cols[MAX_RAW];
  double values[MAX_RAW];
  for (k = 0; k < n; ++k) rows[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < n; ++k) cols[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < n; ++k) values[k] = read_real(s);
  storage = read_u8(s) % 4; /* 0 and 3: not a storage */
  nulls = read_u8(s) % 8;
  CALL(mc_add_stiffness(m, body, n, nulls == 1 || n <= 0 ? NULL : rows, nulls == 2 || n <= 0 ? NULL : cols,
                        nulls == 3 || n <= 0 ? NULL : values, storage));
}

/* Element matrices from the stream. The arrays are exactly as long as eltptr says; a corrupted
   eltptr only ever asks for less (a first entry below the base, a decreasing entry), which the
   library must refuse without reading past the arrays. */
static void op_elements_raw(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), corrupt;
  mc_int n_elements = read_count(s, MAX_ELEMENTS), e, k, eltptr[MAX_ELEMENTS + 1], n_var = 0;
  mc_int eltvar[MAX_ELEMENTS * 4];
  double a_elt[MAX_ELEMENTS * 16];
  size_t n_values = 0;
  mc_int *var;
  double *a;
  eltptr[0] = h->base;
  for (e = 0; e < (n_elements > 0 ? n_elements : 0); ++e) {
    mc_int size = read_count(s, 4);
    if (size < 0) size = 0;
    for (k = 0; k < size; ++k) eltvar[n_var + k] = plus_base(read_id(s), h->base);
    for (k = 0; k < size * size; ++k) a_elt[n_values + (size_t)k] = read_real(s);
    n_var += size, n_values += (size_t)(size * size);
    eltptr[e + 1] = n_var + h->base;
  }
  corrupt = read_u8(s) % 4; /* 1 eltptr[0] below the base, 2 a decreasing entry, 3 NULL arrays */
  if (corrupt == 1) eltptr[0] = h->base - 1 - read_u8(s) % 3;
  else if (corrupt == 2 && n_elements >= 2 && eltptr[1] > eltptr[0]) eltptr[1] = eltptr[0] - 1;
  /* exactly sized heap copies: ASan sees a read past them */
  var = exact((size_t)n_var, sizeof(mc_int)), a = exact(n_values, sizeof(double));
  memcpy(var, eltvar, (size_t)n_var * sizeof(mc_int)), memcpy(a, a_elt, n_values * sizeof(double));
  CALL(mc_add_element_matrices(m, body, n_elements, corrupt == 3 ? NULL : eltptr, corrupt == 3 ? NULL : var, a));
  free(var), free(a);
}

static void op_load_vector(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), kind = read_u8(s) % 4; /* 0 the body's size, 1 raw, 2 NULL, 3 one too many */
  double fx = read_real(s), fy = read_real(s), raw[MAX_RAW];
  const body_state *b = tracked(h, body);
  mc_int n = b && b->meshed ? (b->host ? b->n_equations : 2 * b->n_nodes) : 1, k;
  double *f;
  if (kind == 1) {
    n = read_count(s, MAX_RAW);
    for (k = 0; k < n; ++k) raw[k] = read_real(s);
  }
  if (kind == 3) n++;
  f = exact(n > 0 ? (size_t)n : 0, sizeof(double));
  for (k = 0; k < n; ++k) f[k] = kind == 1 ? raw[k] : 0;
  if (kind != 1 && b && b->host) /* fx, fy on each node's x and y equations */
    for (k = 0; k < 2 * b->n_nodes; ++k)
      if (b->eq[k] >= 0 && b->eq[k] < n) f[b->eq[k]] += k % 2 ? fy : fx;
  CALL(mc_set_load_vector(m, body, n, kind == 2 ? NULL : f));
  free(f);
}

/* Quadratic contact edges (end, end, middle) along a side: the side's own middles where the body
   has them (a quadratic grid, a lattice of order 2), else the next corner (refused); mode 1 swaps
   an end and the middle; mode 2 reads the edges. */
static void op_contact_curved(harness *h, stream *s) {
  mc_model *m = h->m;
  int body = read_body(s), side = read_u8(s) % 4, first = read_u8(s), count = read_u8(s), mode = read_u8(s) % 3;
  mc_int edges[3 * MAX_RAW > 3 * MAX_SIDE ? 3 * MAX_RAW : 3 * MAX_SIDE], n, k;
  if (mode == 2) {
    n = read_count(s, MAX_RAW);
    for (k = 0; k < 3 * n; ++k) edges[k] = plus_base(read_id(s), h->base);
  } else {
    const body_state *b = tracked(h, body);
    mc_int ne;
    const mc_int *e = side_edges(h, body, side, &ne);
    first %= ne;
    n = count == 0 ? ne - first : 1 + count % (ne - first);
    for (k = 0; k < n; ++k) {
      const mc_int a = e[2 * (first + k)], c = e[2 * (first + k) + 1];
      const mc_int mid = b && b->grid && b->has_mid ? b->side_mid[side][first + k] : e[2 * ((first + k + 1) % ne) + 1];
      edges[3 * k] = (mode == 1 ? mid : a) + h->base, edges[3 * k + 1] = c + h->base;
      edges[3 * k + 2] = (mode == 1 ? a : mid) + h->base;
    }
  }
  CALL(mc_set_contact_curved(m, body, n, n > 0 ? edges : NULL));
}

/* ---- assemblies ---------------------------------------------------------------------- */

static void op_body_count(harness *h, stream *s) {
  mc_model *m = h->m;
  int n = read_u8(s) % 6, b;
  if (CALL(mc_set_body_count(m, n)) == MC_OK)
    for (b = n; b < MAX_BODIES; ++b) memset(&h->body[b], 0, sizeof h->body[b]); /* dropped bodies */
}

static void op_add_pair(harness *h, stream *s) {
  mc_model *m = h->m;
  int nonmortar = read_any_body(s);
  int mortar = read_any_body(s);
  int pair = -12345;
  if (CALL(mc_add_contact_pair(m, nonmortar, mortar, &pair)) == MC_OK && pair < 1)
    fuzz_fail("a pair numbered below 1", "mc_add_contact_pair");
}

/* One side of a pair along a side of the body's last grid or lattice (as OP_CONTACT_SIDE and
   OP_CONTACT_CURVED do), or read from the stream. */
static void op_pair_surface(harness *h, stream *s) {
  mc_model *m = h->m;
  int pair = read_pair(s);
  int body = read_any_body(s);
  int side = read_u8(s) % 4;
  int first = read_u8(s);
  int count = read_u8(s);
  int mode = read_u8(s) % 4;
  mc_int edges[3 * MAX_RAW > 3 * MAX_SIDE ? 3 * MAX_RAW : 3 * MAX_SIDE], n, k;
  if (mode == 3) {
    n = read_count(s, MAX_RAW);
    for (k = 0; k < 2 * n; ++k) edges[k] = plus_base(read_id(s), h->base);
    CALL(mc_set_pair_surface(m, pair, body, n, n > 0 ? edges : NULL));
    return;
  }
  {
    const body_state *b = tracked(h, body);
    mc_int ne;
    const mc_int *e = side_edges(h, body, side, &ne);
    first %= ne;
    n = count == 0 ? ne - first : 1 + count % (ne - first);
    if (mode == 0) {
      with_base(h, e + 2 * first, 2 * n, edges);
      CALL(mc_set_pair_surface(m, pair, body, n, edges));
      return;
    }
    for (k = 0; k < n; ++k) {
      const mc_int a = e[2 * (first + k)], c = e[2 * (first + k) + 1];
      const mc_int mid = b && b->grid && b->has_mid ? b->side_mid[side][first + k] : e[2 * ((first + k + 1) % ne) + 1];
      edges[3 * k] = (mode == 2 ? mid : a) + h->base, edges[3 * k + 1] = c + h->base;
      edges[3 * k + 2] = (mode == 2 ? a : mid) + h->base;
    }
    CALL(mc_set_pair_surface_curved(m, pair, body, n, edges));
  }
}

static void op_pair_gap_offset(harness *h, stream *s) {
  mc_model *m = h->m;
  int pair = read_pair(s);
  mc_int n = read_count(s, MAX_RAW), k, nodes[MAX_RAW];
  double offset[MAX_RAW];
  for (k = 0; k < n; ++k) nodes[k] = plus_base(read_id(s), h->base);
  for (k = 0; k < n; ++k) offset[k] = read_real(s);
  CALL(mc_set_pair_gap_offset(m, pair, n, n > 0 ? nodes : NULL, n > 0 ? offset : NULL));
}

/* A friction law: -1 .. 3 (MC_FRICTION_NONE .. _COULOMB = 0 .. 2 and bad ones) or a bad number. */
static int read_law(stream *s) {
  uint8_t b = read_u8(s);
  if (b >= 240) return bad_numbers[(b - 240) % 6];
  return b % 5 - 1;
}

static void op_friction(harness *h, stream *s) {
  mc_model *m = h->m;
  int pair = read_pair(s);
  int law = read_law(s);
  double value = read_real(s);
  CALL(mc_set_friction(m, pair, law, value));
}

static void run(harness *h, stream *s, size_t size) {
  int ops = 0;
  while (s->n > 0 && ops++ < MAX_OPS) {
    mc_model *m = h->m;
    uint8_t op = read_u8(s) % OP_COUNT;
    if (tracing()) fprintf(stderr, "-- op %d at byte %zu\n", (int)op, size - s->n - 1);
    switch (op) {
      case OP_NEW_MODEL: reset_model(h); break;
      case OP_INDEX_BASE: {
        int base = read_u8(s) % 4 - 1;
        if (CALL(mc_set_index_base(m, base)) == MC_OK) h->base = base;
        break;
      }
      case OP_PLANE: {
        uint8_t b = read_u8(s);
        CALL(mc_set_plane(m, b % 3 - (b >= 128), read_real(s)));
        break;
      }
      case OP_GRID_MESH: op_grid_mesh(h, s); break;
      case OP_RAW_MESH: op_raw_mesh(h, s); break;
      case OP_MATERIAL: {
        int body = read_body(s);
        double young = read_real(s), poisson = read_real(s);
        CALL(mc_set_material(m, body, young, poisson));
        break;
      }
      case OP_CELL_LAW: op_cell_law(h, s); break;
      case OP_FIX_SIDE: op_fix_side(h, s); break;
      case OP_FIX_RAW: op_fix_raw(h, s); break;
      case OP_TRACTION_SIDE: op_side_load(h, s, 0); break;
      case OP_PRESSURE_SIDE: op_side_load(h, s, 1); break;
      case OP_EDGE_LOAD_RAW: op_edge_load_raw(h, s); break;
      case OP_NODAL_FORCE: op_nodal_force(h, s); break;
      case OP_BODY_FORCE: {
        int body = read_body(s);
        double fx = read_real(s), fy = read_real(s);
        CALL(mc_set_body_force(m, body, fx, fy));
        break;
      }
      case OP_CLEAR_LOADS: CALL(mc_clear_loads(m, read_body(s))); break;
      case OP_CONTACT_SIDE: op_contact_side(h, s); break;
      case OP_CONTACT_RAW: op_contact_raw(h, s); break;
      case OP_OPTION_INT: op_option_int(h, s); break;
      case OP_OPTION_REAL: {
        int option = read_u8(s) % 16; /* 1 .. 15: every option (MC_OPTION_FRICTION_CT = 15) and a bad one (5); 0: MC_OPTION_EAGER_RESULTS (16) */
        if (option == 0) option = MC_OPTION_EAGER_RESULTS;
        CALL(mc_set_option_real(m, option, read_real(s)));
        break;
      }
      case OP_SOLVE:
        if (h->solves++ < MAX_SOLVES) {
          if (CALL(mc_solve(m)) == MC_OK) {
            mc_int n;
            int b, host = 0, pairs = 0;
            fuzz_api_solves_ok++;
            if (mc_get_contact_count(m, &n) == MC_OK) fuzz_api_contact_solves_ok++;
            for (b = 0; b < MAX_BODIES; ++b) host |= h->body[b].host;
            if (host) fuzz_api_host_solves_ok++;
            for (b = 1; b <= MAX_PAIR; ++b) pairs += mc_get_pair_contact_count(m, b, &n) == MC_OK && n > 0;
            if (pairs >= 2) fuzz_api_pair_solves_ok++;
            {
              int64_t stick = 0, slip = 0;
              if (mc_get_info_int(m, MC_INFO_STICK_NODES, &stick) == MC_OK &&
                  mc_get_info_int(m, MC_INFO_SLIP_NODES, &slip) == MC_OK && stick + slip > 0)
                fuzz_api_friction_solves_ok++;
            }
          }
          query_all(h);
        }
        break;
      case OP_QUERY: query_all(h); break;
      case OP_GAP_OFFSET: op_gap_offset(h, s); break;
      case OP_LOG:
      {
        int on = read_u8(s) & 1; /* operands are read even when the call is skipped */
        CALL(mc_set_log_callback(m, on ? log_callback : NULL, on ? (void *)h : NULL));
        break;
      }
      case OP_WRITE_VTU: op_write_vtu(h, s); break;
      case OP_NULLS: null_calls(h); break;
      case OP_HOST_BODY: op_host_body(h, s); break;
      case OP_HOST_STIFFNESS: op_host_stiffness(h, s); break;
      case OP_STIFFNESS_RAW: op_stiffness_raw(h, s); break;
      case OP_ELEMENTS_RAW: op_elements_raw(h, s); break;
      case OP_LOAD_VECTOR: op_load_vector(h, s); break;
      case OP_CONTACT_CURVED: op_contact_curved(h, s); break;
      case OP_BODY_COUNT: op_body_count(h, s); break;
      case OP_ADD_PAIR: op_add_pair(h, s); break;
      case OP_PAIR_SURFACE: op_pair_surface(h, s); break;
      case OP_PAIR_GAP_OFFSET: op_pair_gap_offset(h, s); break;
      case OP_FRICTION: op_friction(h, s); break;
      case OP_RESET_HISTORY: CALL(mc_reset_history(m)); break;
    }
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  harness h;
  stream s;
  memset(&h, 0, sizeof h);
  s.p = data, s.n = size;
  reset_model(&h);
  run(&h, &s, size);
  mc_destroy(h.m);
  return 0;
}
