/*
 * mortarcontact.h - unilateral contact, frictionless or with Tresca or Coulomb
 * friction, between linear-elastic 2D bodies meshed independently (two or more,
 * several contact pairs), by the mortar finite element method of Ben Belgacem,
 * Hild and Laborde (M3AS 9(2), 1999).
 *
 * The C ABI of this header is stable within a major version: see docs/abi.md.
 *
 * Conventions that hold for every entry point
 * -------------------------------------------
 * - Status: every call that can fail returns an mc_status; MC_OK is 0. After a
 *   failure mc_errmsg(model) names the argument and, where there is one, the
 *   offending index. A failed call leaves the model as it was before the call:
 *   the model stays usable.
 * - Threading: a model is used by one thread at a time; distinct models are
 *   fully independent (the library keeps no global mutable state), so two
 *   threads may solve two models at once. mc_solve may run body 2's work (and
 *   half of the sparse interface path's solves) on one thread of its own,
 *   joined before it returns (MC_OPTION_THREADS), and so
 *   may the call that computes the error estimate on demand (results on
 *   demand, MC_OPTION_EAGER_RESULTS); no other call starts threads.
 * - Ownership: every input array is copied before the call returns. Outputs go
 *   into caller-allocated arrays whose required size each comment states; the
 *   library never writes beyond that size.
 * - Ids: node, cell and edge ids are 0-based by default, 1-based after
 *   mc_set_index_base(m, 1); this applies to ids passed in and returned. The
 *   body number is always 1 or 2 (the paper's Omega^1 and Omega^2).
 * - Units: any consistent system. Forces per unit length of edge (tractions)
 *   and per unit area (body forces) are per unit thickness times the thickness
 *   set by mc_set_plane, as in a 2D model of a slab.
 * - Axisymmetric models (mc_set_plane(m, MC_AXISYMMETRIC, ...)): the mesh is the
 *   meridian of a 3D body of revolution under a load of revolution; x is the radius
 *   r >= 0, y the axis z. Every integral carries 2 pi r (stiffness, tractions,
 *   pressures, body forces, and the mortar integrals of contact). Tractions,
 *   pressures and the contact pressure are per unit area of the true (3D) surface,
 *   body forces per unit volume; nodal forces, reactions and contact forces are
 *   totals over the full turn (the ring of the node), not per radian. The strains
 *   are (rr, zz, rz) and the hoop strain u_r / r. Nodes on the axis (|x| at most
 *   1e-12 times the mesh's extent) get u_r = 0 automatically (a prescribed u_r
 *   there is overridden by 0; the support's force is reported by mc_get_reaction);
 *   a node with x < 0 is an MC_ERROR_MESH naming it. The only rigid motion is the
 *   translation along the axis: a body held axially by contact alone works as in a
 *   plane model. An edge on the axis is no surface of the 3D body: a load on it adds
 *   nothing, and as a contact edge it adds nothing to its nodes' tributary area.
 * - The library never aborts and no C++ exception crosses this interface.
 */
#ifndef MORTARCONTACT_H
#define MORTARCONTACT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define MC_API
#elif defined(__GNUC__)
#define MC_API __attribute__((visibility("default")))
#else
#define MC_API
#endif

#define MC_VERSION_MAJOR 0
#define MC_VERSION_MINOR 1
#define MC_VERSION_PATCH 0
#define MC_VERSION_NUMBER (MC_VERSION_MAJOR * 10000 + MC_VERSION_MINOR * 100 + MC_VERSION_PATCH)
#define MC_VERSION_STRING "0.1.0"

typedef struct mc_model mc_model; /* opaque; one per scene, no global state */
typedef int32_t mc_int;           /* node, cell and edge ids, counts */

/* Status codes. Values are frozen; new codes are only ever appended. */
typedef enum mc_status {
  MC_OK = 0,
  MC_ERROR_ARGUMENT = 1,       /* a NULL pointer, a bad body, an id or value out of range */
  MC_ERROR_MESH = 2,           /* degenerate, inverted or duplicated cells; edges not on the boundary */
  MC_ERROR_MATERIAL = 3,       /* E <= 0, nu outside (-1, 1/2), elasticity matrix not SPD */
  MC_ERROR_STATE = 4,          /* call out of order (no mesh yet, results before a solve) */
  MC_ERROR_CONTACT = 5,        /* contact surfaces that do not face each other, bad contact edges */
  MC_ERROR_SINGULAR = 6,       /* rigid motion not prevented by supports or by contact */
  MC_ERROR_NOT_CONVERGED = 7,  /* the active-set iteration did not reach complementarity */
  MC_ERROR_MEMORY = 8,         /* allocation failed */
  MC_ERROR_INTERNAL = 9        /* a bug: please report with the message */
} mc_status;

/* Kinds of 2D model (mc_set_plane). MC_AXISYMMETRIC: a 3D body of revolution under a load of
   revolution, whose meridian half-plane is the mesh: x is the radius r >= 0, y the axis z. */
enum { MC_PLANE_STRAIN = 0, MC_PLANE_STRESS = 1, MC_AXISYMMETRIC = 2 };
enum { MC_X = 1, MC_Y = 2, MC_XY = 3 }; /* component masks for mc_fix */

/* Options (mc_set_option_int / mc_set_option_real). Values are frozen. */
enum {
  MC_OPTION_METHOD = 1,         /* int: MC_METHOD_*; default MC_METHOD_MORTAR */
  MC_OPTION_TOLERANCE = 2,      /* real: relative complementarity/equilibrium tolerance; default 1e-10 */
  MC_OPTION_MAX_ITERATIONS = 3, /* int: active-set iterations before MC_ERROR_NOT_CONVERGED; default 200,
                                   or an eighth of the contact rows where that is more */
  MC_OPTION_ORDERING = 4,       /* int: MC_ORDERING_*; fill-reducing ordering; default MC_ORDERING_AUTO */
  MC_OPTION_Q1_INTEGRATION = 6, /* int: MC_Q1_*; default MC_Q1_FULL */
  MC_OPTION_CONTACT_NORMAL = 7, /* int: MC_NORMAL_*; default MC_NORMAL_NONMORTAR */
  MC_OPTION_CONTACT_SURFACE = 8, /* int: MC_SURFACE_*; the geometry of gaps and normals; default MC_SURFACE_SMOOTH */
  MC_OPTION_FEATURE_ANGLE = 9,   /* real, degrees in (0, 180): a contact chain is split into separately
                                    smoothed faces where adjacent edges turn by more than this; default 40 */
  MC_OPTION_THREADS = 10,       /* int: threads for the two bodies' work; default 0 (see below) */
  MC_OPTION_INTERFACE_SOLVER = 11, /* int: MC_INTERFACE_*; how the contact problem is solved; default
                                     MC_INTERFACE_AUTO (see below) */
  MC_OPTION_ERROR_ESTIMATE = 12, /* int: 1 (default) a solve's error is estimated (MC_INFO_ERROR_ESTIMATE,
                                    mc_get_error_indicator; when first asked for, see
                                    MC_OPTION_EAGER_RESULTS); 0: never (the info reads 0, the
                                    indicators are refused) */
  MC_OPTION_MULTIPLIER = 13,     /* int: MC_MULTIPLIER_*; the contact multipliers of a body 1 with
                                    quadratic cells (MC_METHOD_MORTAR); default MC_MULTIPLIER_LINEAR */
  MC_OPTION_LOAD_STEPS = 14,     /* int >= 1: a model with friction goes from the last converged state
                                    to the loads and prescribed values of this solve in n equal
                                    increments; default 1. No effect without friction. */
  MC_OPTION_FRICTION_CT = 15,    /* real >= 0: the tangential complementarity parameter c_t of the
                                    stick/slip update (it changes the iterates, never the converged
                                    answer); 0 (default) chooses one scaled by the interface operator */
  MC_OPTION_EAGER_RESULTS = 16   /* int: 0 (default) the stresses, nodal stresses and error estimate
                                    are computed by the first call that asks for them after a solve
                                    (see "Results on demand" below); 1: every mc_solve computes them */
};

/* Results on demand (MC_OPTION_EAGER_RESULTS = 0, the default). mc_solve computes the
   displacements, reactions, contact results and the infos; the cells' stresses, the nodal
   stresses and the error estimate are computed by the first call after it that needs them:
   mc_get_stress and mc_get_nodal_stress (that body's, both at once), mc_get_error_indicator and
   mc_get_info_real(MC_INFO_ERROR_ESTIMATE) (both bodies' estimate at once), mc_write_vtu (every
   written body's stresses). Later calls read what was computed, until the next mc_solve or any
   change of the model (which needs a new solve anyway). The numbers are those of
   MC_OPTION_EAGER_RESULTS = 1 bit for bit; only when they are computed differs: a re-solve
   after a load change then pays its triangular solves, not results nobody reads. Such a call
   takes a const model and leaves it const to the caller (what it computes is kept inside); as
   every call, it must not run on one model from two threads at once (distinct models stay
   independent). The error estimate may run the two bodies' share on two threads as mc_solve
   does (MC_OPTION_THREADS), joined before the call returns. An error while computing (stresses
   beyond double range: MC_ERROR_ARGUMENT, as mc_solve reports it with eager results; out of
   memory) is that call's status and message; nothing is kept, the model and its other results
   stay usable, and the next call tries again. The log callback gets the phase messages of what
   such a call computes ("stresses: body B, ..., T s", "error estimate: E ..., T s"), after
   "solve: done". Time: MC_INFO_TIME_TOTAL is mc_solve's own; MC_INFO_TIME_RESULTS adds up what
   computing these results has cost since the solve, in mc_solve (eager) or in the calls that
   asked for them. */

/* Values of MC_OPTION_MULTIPLIER: the space of the contact pressure when body 1 has quadratic
   cells (T6, Q8, Q9). Bodies of linear cells always use the paper's space (theory §2b). */
enum {
  MC_MULTIPLIER_LINEAR = 0,   /* continuous piecewise linear on the edges' corners (one value per
                                 edge): the cone is exact, the pressure as coarse as the corners */
  MC_MULTIPLIER_QUADRATIC = 1 /* continuous piecewise quadratic, a value at every trace node
                                 (corners and mid-edge nodes): nonnegative at the nodes */
};

/* Values of MC_OPTION_INTERFACE_SOLVER, and of MC_INFO_INTERFACE_SOLVER (which one ran).
   Both paths give the same answer to round-off (docs/theory.md, "Two interface solvers").
   MC_INTERFACE_AUTO (default): the library analyses both (symbolically: no numeric work),
     estimates their time and memory, and runs the cheaper; the log says which and why.
   MC_INTERFACE_CONDENSED: each body factorized alone with its contact unknowns last, the
     problem condensed onto the q contact rows (S = B K^+ B^T, dense q x q) and solved there.
     A re-solve with new loads is then nearly free, but time grows like q^3 and memory like q^2:
     the choice for contact zones small beside the bodies (Hertz, punches, fits of few nodes).
   MC_INTERFACE_SPARSE: the two bodies and the active rows solved together, sparse: each
     active-set iteration factorizes K + rho B_A^T B_A (one symbolic analysis for all of them)
     and solves the exact saddle-point problem on that active set by conjugate gradients on the
     multipliers, preconditioned by that factor (no penalty error remains). Cost: a few
     factorizations of the two bodies whatever q is; the choice for long interfaces (strips,
     liners, layered bodies). A re-solve whose active set does not change reuses the factor. */
enum { MC_INTERFACE_AUTO = 0, MC_INTERFACE_CONDENSED = 1, MC_INTERFACE_SPARSE = 2 };

/* MC_OPTION_THREADS: how many threads mc_solve runs the two bodies' work on.
   0 (default) automatic: two when the process may run on two or more cores (its affinity mask)
     and the smaller body has at least 30000 unknowns (2 x its nodes), one otherwise: below that
     size two threads were measured to gain too little, or to lose on a re-solve
     (docs/benchmarks.md, "Threads").
   1 serial: the library starts no thread (today's behaviour).
   n >= 2 at most n: two when both bodies have a mesh (a third would have nothing to do).
   Threads the library starts: with two, mc_solve starts one std::thread at a time (named
   "mc-body2") for body 2's share of a phase while the calling thread does body 1's, and joins
   it before that phase ends. The phases: first, everything a body needs before the interface
   problem (assembly with the rigid modes, ordering, factorization, the body's block of the
   interface operator, its load solve); then the recovery (displacements, reactions, and the
   stresses with MC_OPTION_EAGER_RESULTS). A re-solve runs two: the load solves, and the
   recovery. A solve whose recovered gaps are above round-off (MC_INFO_GAP_RESIDUAL > 1e-13) is
   refined: each refinement step (at most 3) adds two phases (the residuals' forward solves, the
   corrections' backward solves), and the recovery runs once more. The error estimate is one
   more phase, in mc_solve (eager) or in the call that first asks for it. On the sparse
   interface path (MC_INTERFACE_SPARSE) with a slender matrix of 60000 unknowns or more (two long
   strips: a separator of at most 100 unknowns), ordered in two
   halves, the same thread (same name, one at a time) also does half of each solve and of each
   factorization with that matrix's simplicial factor, and body 2's share of each refinement
   residual: the same arithmetic as serially, so the results stay those of MC_OPTION_THREADS = 1
   bit for bit. No thread outlives
   the call that started it, no other call starts one, and if none can be started the work runs
   serially. The
   log callback is still called only from the calling thread, with the messages in the serial
   order; an error on body 2's thread is returned as usual (body 1's first, as serially).
   BLAS: while both bodies run, each one's BLAS calls use its share of the cores. With
   OpenBLAS's pthread build (Debian's default) the thread count is process-wide and threaded
   calls take turns on one lock, so an mc_solve that uses two threads lowers the count to 1 from
   its start to its end and puts the previous count back before returning (unless it was changed
   meanwhile, e.g. by another model's solve: that value then stands); a host thread calling
   BLAS during such a solve also gets one thread. With the OpenMP build each body thread sets
   only its own OpenMP thread count to half the cores (the calling thread's is put back). CHOLMOD's OpenMP team
   stays at one thread as always. Results: bit for bit those of the serial solve when OpenBLAS
   runs one thread per call anyway (OPENBLAS_NUM_THREADS=1; tested); otherwise they differ by
   round-off only, since OpenBLAS's sums depend on its thread count (tested to 1e-11 relative).
   Changing this option keeps the factorizations and the results. With two threads the time
   infos other than MC_INFO_TIME_TOTAL add both bodies' times, and may sum to more than it. */

/* Values of MC_OPTION_METHOD: how the non-penetration condition is discretized. */
enum {
  MC_METHOD_MORTAR = 0,          /* the paper's cone K_h: nodal values of u1.n + pi_h^1(u2.n) (3.2) */
  MC_METHOD_DUAL_MORTAR = 1,     /* same, with Wohlmuth's biorthogonal multiplier basis (diagonal D); a
                                    body 1 of quadratic cells: the dual basis of its quadratic trace,
                                    a value at every contact node */
  MC_METHOD_NODE_TO_SEGMENT = 2  /* pointwise: each body-1 node against the body-2 point it projects to */
};

/* Values of MC_OPTION_CONTACT_NORMAL: the direction n_j of the constraint at body-1 node j,
   along which body 2 is projected and the gap measured. Both agree on flat contact; on
   curved contact they differ by O((a/R)^2) (0.75 % in p0 on the Hertz scene, see docs). */
enum {
  MC_NORMAL_NONMORTAR = 0, /* body 1's nodal normal: mean of its adjacent edge normals */
  MC_NORMAL_MORTAR = 1     /* minus body 2's normal at the closest point of its surface */
};

/* Values of MC_OPTION_CONTACT_SURFACE: the geometry the contact constraint is measured on.
   The mesh itself never moves; only gaps and constraint normals use the chosen surface. */
enum {
  MC_SURFACE_SMOOTH = 0, /* a C1 curve through each surface's nodes (cubic Hermite, nodal normals
                            exact on circles); split at corners sharper than MC_OPTION_FEATURE_ANGLE */
  MC_SURFACE_FACETED = 1 /* the straight mesh edges, nodal normals the mean of the edge normals (0.1) */
};

/* Storage of a host body's stiffness entries (mc_add_stiffness). */
enum {
  MC_MATRIX_FULL = 1,    /* both triangles given (summed duplicates must be symmetric to round-off) */
  MC_MATRIX_TRIANGLE = 2 /* one triangle, either, each off-diagonal pair once */
};

/* Values of MC_OPTION_ORDERING. */
enum { MC_ORDERING_AUTO = 0, MC_ORDERING_AMD = 1, MC_ORDERING_METIS = 2 };

/* Values of MC_OPTION_Q1_INTEGRATION (quadrilaterals only). */
enum {
  MC_Q1_FULL = 0, /* 2x2 Gauss */
  MC_Q1_BBAR = 1  /* B-bar: volumetric strain averaged per cell, locking-free for nu -> 1/2 */
};

/* Infos (mc_get_info_int / mc_get_info_real): what the last mc_solve did. */
enum {
  MC_INFO_DOFS = 1,                /* int: unknowns after eliminating supports, both bodies */
  MC_INFO_FACTOR_NNZ = 2,          /* int: nonzeros of the Cholesky factors */
  MC_INFO_ITERATIONS = 3,          /* int: active-set iterations of the last solve */
  MC_INFO_ACTIVE_NODES = 4,        /* int: body-1 contact nodes with a positive force */
  MC_INFO_CONTACT_NODES = 5,       /* int: constraint rows: body-1 positions that see body 2, plus the
                                      ends of Gamma_c inside partly covered edges */
  MC_INFO_FACTORIZATIONS = 6,      /* int: numeric factorizations done by the last solve (0 on reuse) */
  MC_INFO_INTERFACE_SOLVER = 7,    /* int: the contact solve that ran: MC_INTERFACE_CONDENSED or
                                      MC_INTERFACE_SPARSE; 0 without contact */
  MC_INFO_STICK_NODES = 8,         /* int: constraint rows of pairs with friction that stick */
  MC_INFO_SLIP_NODES = 9,          /* int: constraint rows of pairs with friction that slip */
  MC_INFO_TIME_ASSEMBLY = 20,      /* real, seconds */
  MC_INFO_TIME_ANALYSIS = 21,      /* real, seconds: ordering and symbolic factorization */
  MC_INFO_TIME_FACTORIZATION = 22, /* real, seconds: numeric factorization */
  MC_INFO_TIME_SOLVE = 23,         /* real, seconds: triangular solves */
  MC_INFO_TIME_CONTACT = 24,       /* real, seconds: geometry, mortar operators, interface operator, QP */
  MC_INFO_TIME_TOTAL = 25,         /* real, seconds: the whole mc_solve (results computed later on
                                      demand are not in it: MC_INFO_TIME_RESULTS) */
  MC_INFO_STRAIN_ENERGY = 26,      /* real: 1/2 u^T K u over both bodies */
  MC_INFO_COMPLEMENTARITY = 27,    /* real: largest relative violation of lambda>=0, gap>=0, lambda*gap=0 */
  MC_INFO_EQUILIBRIUM = 28,        /* real: ||K u + B^T lambda - f|| / ||f - K u_prescribed, B^T lambda||
                                      on the free unknowns (u without its rigid-mode part) */
  MC_INFO_GAP_RESIDUAL = 29,       /* real: the gaps of the returned displacements: largest |gap| of a row
                                      with lambda > 0, or penetration of one with lambda = 0, as a length
                                      (the row's weighted gap over its weights), relative to the largest
                                      displacement or initial gap; 0 without contact. Above 1e-13 the
                                      solve refines its answer (up to 3 steps of iterative refinement
                                      on the full problem's residuals) and reports the value after;
                                      MC_INFO_COMPLEMENTARITY, the condensed problem's, cannot show
                                      what the condensation lost (docs/robustness.md) */
  MC_INFO_ERROR_ESTIMATE = 30,     /* real: the estimated relative error of the solution in the energy norm
                                      of both bodies, eta / sqrt(||u_h||^2 + eta^2) with ||u_h||^2 =
                                      u^T K u (twice MC_INFO_STRAIN_ENERGY): Zienkiewicz-Zhu recovery in
                                      each cell plus, on body 1's contact edges, the misfit between the
                                      recovered normal stress and the contact pressure and the
                                      complementarity of pressure and gap (docs/theory.md, "Error
                                      estimate"); 0 when MC_OPTION_ERROR_ESTIMATE is 0. Host bodies
                                      (no cells) add nothing to it. Computed by the first call that
                                      reads it (or by mc_solve, MC_OPTION_EAGER_RESULTS). */
  MC_INFO_FRICTION_COMPLEMENTARITY = 31, /* real: largest relative violation of the friction conditions
                                      of the last solve's last step: |lambda_t| <= bound, slip 0 where
                                      sticking, lambda_t = bound with the slip's sign where slipping;
                                      0 without friction */
  MC_INFO_TIME_RESULTS = 32        /* real, seconds: computing the last solve's stresses, nodal stresses and
                                      error estimate so far: inside mc_solve with MC_OPTION_EAGER_RESULTS
                                      (then part of MC_INFO_TIME_TOTAL), otherwise in the calls that asked
                                      for them (not part of it); 0 if none was asked for yet */
};

/* ---- lifecycle, errors, version ---------------------------------------- */

/* Creates an empty model in *model. Returns MC_ERROR_ARGUMENT if model is NULL. */
MC_API mc_status mc_create(mc_model **model);
/* Frees the model and everything it owns. NULL is fine. */
MC_API void mc_destroy(mc_model *model);
/* The message of the last failed call on this model, "" if the last call succeeded.
   Valid until the next call on the model. A NULL model gives a static message. */
MC_API const char *mc_errmsg(const mc_model *model);
/* A static English name of a status code ("MC_OK", ...); unknown codes give "unknown status". */
MC_API const char *mc_status_string(mc_status status);
/* The library's version as "MAJOR.MINOR.PATCH" (static storage). */
MC_API const char *mc_version_string(void);
/* The library's version as MAJOR*10000+MINOR*100+PATCH; equals MC_VERSION_NUMBER of a matching header. */
MC_API int mc_version_number(void);

/* ---- the scene ----------------------------------------------------------- */

/* 0 (default) or 1: the base of all node, cell and edge ids, in and out. */
MC_API mc_status mc_set_index_base(mc_model *m, int base);
/* MC_PLANE_STRAIN (default), MC_PLANE_STRESS or MC_AXISYMMETRIC, and the thickness (> 0,
   default 1) that multiplies the stiffness, tractions, pressures and body forces. Nodal forces,
   reactions and contact forces are totals (already per the whole thickness). MC_AXISYMMETRIC
   ignores the thickness (any value is accepted and the last plane model's is kept) and
   weights every integral by 2 pi r instead (see "Axisymmetric models" above); it is an
   MC_ERROR_MESH, naming the node, if a body's mesh has a node with x < 0 (the model is then
   unchanged). Switching between the kinds is allowed at any time; the next solve rebuilds. */
MC_API mc_status mc_set_plane(mc_model *m, int plane, double thickness);
/* The mesh of a body (1 or 2). xy: 2 per node. cells: nodes_per_cell ids each, corners
   counter-clockwise, in Gmsh's and VTK's node order:
     3 = P1 triangle, 4 = Q1 quadrilateral (corners only);
     6 = T6 triangle: corners 0 1 2, then the mid-edge nodes of edges 0-1, 1-2, 2-0;
     8 = Q8 serendipity quadrilateral: corners 0 1 2 3, then mid-edge nodes of 0-1, 1-2, 2-3, 3-0;
     9 = Q9 Lagrange quadrilateral: as Q8, then the centre node.
   Quadratic cells are isoparametric: a mid-edge node off its edge's chord makes the edge a
   curve (a parabola through the three nodes), which loads and contact follow. Two cells sharing
   an edge must share its mid-edge node; the Jacobian must be positive everywhere inside a cell
   (checked on a lattice of points, corners and edges included), else MC_ERROR_MESH naming the
   cell and node. Edges are always named by their two corner nodes (mc_add_traction,
   mc_add_pressure, mc_set_contact): the library finds the mid-edge node from the cell, so a
   host's boundary lists are the same for linear and quadratic meshes. Quadrature (docs/api.md):
   P1 1 point (axisymmetric 3), Q1 2x2, T6 3 points (axisymmetric 6), Q8 and Q9 3x3 Gauss;
   exact for the stiffness of straight-sided T6 and of parallelogram Q8/Q9 cells. Every node must be used by a cell.
   Setting a mesh again clears that body's materials, supports, loads and contact surface.
   In an axisymmetric model a node with x < 0 is an MC_ERROR_MESH naming it. */
MC_API mc_status mc_set_mesh(mc_model *m, int body, mc_int n_nodes, const double *xy,
                             mc_int n_cells, int nodes_per_cell, const mc_int *cells);
/* Isotropic material of the whole body: Young's modulus > 0, Poisson's ratio in (-1, 1/2). */
MC_API mc_status mc_set_material(mc_model *m, int body, double young, double poisson);
/* The paper's A(x) per cell: 9 per cell, a row-major symmetric positive definite 3x3 matrix in
   Voigt notation (xx, yy, engineering xy) giving the in-plane stress from the in-plane strain.
   Overrides mc_set_material for this body (mc_set_plane's thickness still applies; the
   plane-strain/plane-stress choice does not, as the matrix already is the in-plane law;
   mc_get_stress then reports sigma_zz = 0). An axisymmetric model also needs the hoop terms,
   which this 3x3 law lacks: mc_solve then fails with MC_ERROR_MATERIAL. */
MC_API mc_status mc_set_cell_elasticity(mc_model *m, int body, const double *d);
/* Prescribes displacements: for each of the n nodes, the components in the mask (MC_X, MC_Y,
   MC_XY) take the given values. values: 2 per node (x, y); components not in the mask are
   ignored; NULL means zero. A later call on the same node and component overrides. */
MC_API mc_status mc_fix(mc_model *m, int body, mc_int n, const mc_int *nodes, int components,
                        const double *values);
/* Adds a traction on boundary edges. edges: 2 node ids each, an edge of a cell on the boundary;
   traction: 2 per edge, force per unit length (times the thickness; axisymmetric: per unit
   area of the surface the edge sweeps), global axes, uniform along the edge. */
MC_API mc_status mc_add_traction(mc_model *m, int body, mc_int n_edges, const mc_int *edges,
                                 const double *traction);
/* Adds a normal pressure on boundary edges: 1 per edge, > 0 pushes into the body. */
MC_API mc_status mc_add_pressure(mc_model *m, int body, mc_int n_edges, const mc_int *edges,
                                 const double *pressure);
/* Adds point forces: force has 2 per node, total forces (not multiplied by the thickness;
   axisymmetric: the total over the node's ring, i.e. 2 pi r times a line load). */
MC_API mc_status mc_add_nodal_force(mc_model *m, int body, mc_int n, const mc_int *nodes,
                                    const double *force);
/* Sets (replaces) a uniform body force per unit area (per unit volume times thickness 1;
   axisymmetric: per unit volume, fx radial, fy axial). */
MC_API mc_status mc_set_body_force(mc_model *m, int body, double fx, double fy);
/* Removes every load (tractions, pressures, nodal and body forces) of a body; supports stay.
   Use it with the add_ calls to step loads: the next solve reuses the factorization. */
MC_API mc_status mc_clear_loads(mc_model *m, int body);

/* Candidate contact surface of a body: boundary edges, 2 node ids each. Body 1 is the
   non-mortar side (the paper's Omega^1: its trace carries the constraint and the
   multipliers); body 2 is the mortar side. Both bodies need one for a contact solve.
   A host body (mc_set_host_body) has no cells: its edges run with the body on their left, and
   each node needs an equation in x or y.
   The surface may be open chains or closed loops; consecutive edges that turn by more than
   175 degrees (a chain folding back on itself) are an MC_ERROR_CONTACT naming the node.
   Gamma_c is the part of body 1's surface whose normal lines meet body 2's surface: it may end
   inside a body-1 edge that body 2 covers partly (the constraint there then acts on both of
   that edge's nodes), and a closed loop covered all round has no end. A body-1 node whose
   normal line misses body 2 "sees no mortar surface": its gap is reported as +infinity, and
   its force is zero unless Gamma_c ends inside one of its edges. */
MC_API mc_status mc_set_contact(mc_model *m, int body, mc_int n_edges, const mc_int *edges);
/* Adds offset[k] (a length, may be negative) to the initial gap g0 of body-1 node nodes[k]:
   a clearance (> 0) or an interference (< 0) that the meshes do not show, e.g. a coating or a
   shrink fit. Replaces earlier offsets of those nodes; nodes not on body 1's contact surface
   are an MC_ERROR_ARGUMENT; before mc_set_contact of body 1, MC_ERROR_STATE. Like loads,
   changing offsets keeps the factorizations and the interface operator for the next solve. */
MC_API mc_status mc_set_gap_offset(mc_model *m, mc_int n, const mc_int *nodes, const double *offset);

/* ---- assemblies: bodies 1..N and contact pairs (docs/api.md, "Assemblies") -------------
   A model holds 2 bodies unless told otherwise; every call that takes a body accepts 1..N, and
   mesh bodies and host bodies mix freely. Contact acts between the two bodies of a pair: the
   non-mortar body carries the constraint and the multipliers on its side (as body 1 does in a
   two-body model), the mortar body is the surface it is measured against. A body may be
   non-mortar in one pair and mortar in another (the middle body of a stack). Pairs are numbered
   1, 2, ... in the order they are made, whatever the index base (like bodies).
   The two-body calls (mc_set_contact, mc_set_contact_curved, mc_set_gap_offset and the
   mc_get_contact_* getters) act on pair 1: mc_set_contact on a model without pairs makes pair 1
   as (non-mortar 1, mortar 2), so existing programs read the same results; on a model whose
   pair 1 joins other bodies they are MC_ERROR_STATE.
   A non-mortar position belongs to one pair: two pairs with the same non-mortar and mortar
   bodies are one surface (their edges joined, one multiplier per position: splitting a surface
   into pairs changes no answer); two pairs whose non-mortar surfaces on the same body share a
   node with different mortar bodies are refused (MC_ERROR_CONTACT naming the node and both
   pairs) unless the surface turns there by more than MC_OPTION_FEATURE_ANGLE (a corner: one
   position per face, each with its own normal and constraint, as inside one surface). */

/* The number of bodies, n >= 2 (default 2). Growing keeps the bodies there are; shrinking drops
   the last ones, and is MC_ERROR_STATE while a contact pair uses a dropped body. */
MC_API mc_status mc_set_body_count(mc_model *m, int n);
/* Makes a contact pair between two different bodies and returns its number in *pair. */
MC_API mc_status mc_add_contact_pair(mc_model *m, int nonmortar_body, int mortar_body, int *pair);
/* One side of a pair: body is the pair's non-mortar or mortar body; boundary edges, 2 node ids
   each (as mc_set_contact), or 3 with their middles (as mc_set_contact_curved). Replaces that
   side's earlier edges. */
MC_API mc_status mc_set_pair_surface(mc_model *m, int pair, int body, mc_int n_edges, const mc_int *edges);
MC_API mc_status mc_set_pair_surface_curved(mc_model *m, int pair, int body, mc_int n_edges, const mc_int *edges);
/* Initial-gap offsets of the pair's non-mortar nodes (as mc_set_gap_offset does for pair 1). */
MC_API mc_status mc_set_pair_gap_offset(mc_model *m, int pair, mc_int n, const mc_int *nodes, const double *offset);
/* After a solve: the number of the pair's contact positions (its non-mortar surface's nodes, a
   corner once per face, quadratic middles included: as mc_get_contact_count for pair 1). */
MC_API mc_status mc_get_pair_contact_count(const mc_model *m, int pair, mc_int *n);
/* Their node ids on the non-mortar body (index base applies). */
MC_API mc_status mc_get_pair_contact_nodes(const mc_model *m, int pair, mc_int *nodes);
/* Fields of mc_get_pair_contact: one value per position (MC_CONTACT_NORMAL: two, x and y), as the
   mc_get_contact_* getter of the same name. */
typedef enum mc_contact_field {
  MC_CONTACT_PRESSURE = 1,    /* contact pressure (>= 0), as mc_get_contact_pressure */
  MC_CONTACT_FORCE = 2,       /* nodal contact force, as mc_get_contact_force */
  MC_CONTACT_GAP = 3,         /* gap after the solve (+infinity where the mortar side is not seen) */
  MC_CONTACT_INITIAL_GAP = 4, /* initial gap, offsets included */
  MC_CONTACT_NORMAL = 5,      /* unit outward normal of the non-mortar body, 2 per position */
  MC_CONTACT_SHEAR = 6,       /* tangential traction on the non-mortar side along t = (-n_y, n_x):
                                 the friction the mortar body exerts, opposite to the slip */
  MC_CONTACT_SLIP = 7,        /* tangential slip of the last solve, (u1 - u2) . t from the last
                                 converged state (all load steps of the solve) */
  MC_CONTACT_SLIP_TOTAL = 8,  /* accumulated |slip| since the unloaded state (mc_reset_history) */
  MC_CONTACT_STATE = 9        /* MC_STATE_OPEN, _STICK or _SLIP as a double; frictionless contact slips */
} mc_contact_field;
/* Values of MC_CONTACT_STATE. */
enum { MC_STATE_OPEN = 0, MC_STATE_STICK = 1, MC_STATE_SLIP = 2 };
MC_API mc_status mc_get_pair_contact(const mc_model *m, int pair, int field, double *out);

/* ---- friction (docs/api.md, "Friction") --------------------------------------------------
   Per contact pair: MC_FRICTION_NONE (default), MC_FRICTION_TRESCA (value: the slip bound, a
   shear traction >= 0) or MC_FRICTION_COULOMB (value: the friction coefficient mu >= 0). The
   stick/slip/open states are found exactly (a primal-dual active-set iteration; the converged
   step satisfies the discrete conditions to round-off, MC_INFO_FRICTION_COMPLEMENTARITY).
   Friction remembers: each mc_solve of a model with friction is a step from the last converged
   state (the first: the unloaded state), in MC_OPTION_LOAD_STEPS increments; mc_reset_history
   returns to the unloaded state. A change of the model's structure (meshes, supports' set,
   contact surfaces, method) also does. Both interface solvers (MC_OPTION_INTERFACE_SOLVER) take
   friction, with the same answers. */
enum { MC_FRICTION_NONE = 0, MC_FRICTION_TRESCA = 1, MC_FRICTION_COULOMB = 2 };
MC_API mc_status mc_set_friction(mc_model *m, int pair, int law, double value);
/* Forgets the converged state: the next solve starts from the unloaded state (u = 0, loads 0,
   accumulated slip 0). */
MC_API mc_status mc_reset_history(mc_model *m);

/* ---- host bodies: a legacy program's own matrices (docs/tutorial_legacy.md) ---------------

   A host body has no cells: the host hands over what its own element library and assembly
   built, in its own equation numbering (Smith and Griffiths' nf/g steering, MUMPS's input):
   the stiffness, the load vector, and the nodes and edges of the contact surface. The solver
   treats it like a mesh body (every method, both interface paths, floating bodies, threads,
   re-solves); the results come back in the host's numbering. Every equation number counts from
   the index base (mc_set_index_base) like every id; a number below the base means "no equation"
   (a restrained or absent freedom) and is skipped wherever it appears.
   What a host body refuses, with a message that says why (MC_ERROR_STATE): materials and cell
   laws (its stiffness is the host's), mc_fix (its supports are its restrained freedoms: give them
   no equation), tractions, pressures and body forces (use mc_set_load_vector), and the results
   that need cells: mc_get_stress, mc_get_nodal_stress, mc_get_reaction. mc_add_nodal_force adds
   to the load of the node's equations; mc_get_displacement gives 2 per node (0 where a freedom
   has no equation); mc_write_vtu writes mesh bodies only. */

/* Makes body a host body, replacing what it was (as mc_set_mesh does). n_nodes >= 1 nodes at
   xy (2 per node): the nodes the contact surface uses, and, for a body that only contact holds,
   every node of the host's model, whose coordinates give the rigid modes (translations and the
   rotation; axisymmetric: the axial translation). equations: 2 per node (x then y), the host's
   equation number of that freedom, or a number below the base for none. n_equations >= 1: the
   size of the host's system. Each equation number is at most n_equations - 1 + base and belongs
   to one freedom (MC_ERROR_ARGUMENT naming both nodes otherwise). Equations no node names are
   fine (freedoms of nodes not given, rotations, internal modes), but a floating body needs all
   its freedoms on given nodes. */
MC_API mc_status mc_set_host_body(mc_model *m, int body, mc_int n_nodes, const double *xy, const mc_int *equations,
                                  mc_int n_equations);
/* Adds coordinate entries to a host body's stiffness: entry k is values[k] at (rows[k], cols[k]),
   equation numbers from the index base; duplicates are summed; an entry naming a number below
   the base is skipped. storage: MC_MATRIX_FULL (both triangles) or MC_MATRIX_TRIANGLE (one
   triangle, either, the same for every off-diagonal entry of the call; the other is its
   mirror). Repeated calls add. A non-finite value, a number above the system, or a TRIANGLE call
   with entries in both triangles is MC_ERROR_ARGUMENT naming k; a call that fails adds nothing.
   The call costs one pass over its arrays (no sort): whether the MC_MATRIX_FULL entries, summed
   over all calls, are symmetric (to 1e-12 of their largest) is checked by mc_solve when it
   assembles the matrix, an MC_ERROR_ARGUMENT naming the two equations of the first pair that is
   not (start again with mc_set_host_body). mc_solve also refuses (MC_ERROR_SINGULAR, naming the
   equation) a diagonal that is not positive, and a matrix singular beyond the rigid modes. */
MC_API mc_status mc_add_stiffness(mc_model *m, int body, mc_int n_entries, const mc_int *rows, const mc_int *cols,
                                  const double *values, int storage);
/* Adds element matrices to a host body's stiffness (MUMPS's elemental input, Smith and
   Griffiths' g and storkm): element e's equations are eltvar[eltptr[e] - base .. eltptr[e+1] -
   base) (eltptr has n_elements + 1 entries counted from the base: MUMPS's ELTPTR(1) = 1 with base
   1), its square matrix, full and column by column, follows the previous element's in a_elt.
   An equation below the base (restrained) skips its row and column. Each element matrix must be
   symmetric to 1e-12 of its largest entry. A call that fails adds nothing. */
MC_API mc_status mc_add_element_matrices(mc_model *m, int body, mc_int n_elements, const mc_int *eltptr,
                                         const mc_int *eltvar, const double *a_elt);
/* The load of a host body, n_equations values in equation order (replaces the previous one;
   mc_clear_loads zeroes it). */
MC_API mc_status mc_set_load_vector(mc_model *m, int body, mc_int n_equations, const double *f);
/* After a solve: the displacements in equation order (n_equations values) of a host body, or
   (2 per node) of a mesh body. */
MC_API mc_status mc_get_equation_solution(const mc_model *m, int body, double *u);
/* After a solve: the contact forces on the body as a load vector in its equation order
   (n_equations values for a host body, 2 per node for a mesh body): what a host adds to its
   residual or its reaction output; K u = f + r on the free equations. */
MC_API mc_status mc_get_contact_load(const mc_model *m, int body, double *r);
/* Candidate contact surface of quadratic edges, 3 node ids per edge: end, end, middle (the
   3-node line of Gmsh and VTK). For a host body the edges run with the body on their left (a
   boundary walked counter-clockwise); for a mesh body each must be a boundary edge of a cell with
   that middle node. Otherwise as mc_set_contact. */
MC_API mc_status mc_set_contact_curved(mc_model *m, int body, mc_int n_edges, const mc_int *edges);

/* ---- options and solving ------------------------------------------------ */

/* Sets an integer option (MC_OPTION_*). */
MC_API mc_status mc_set_option_int(mc_model *m, int option, int64_t value);
/* Sets a real option (MC_OPTION_*). */
MC_API mc_status mc_set_option_real(mc_model *m, int option, double value);
/* Solves the scene. Without contact surfaces: two independent elasticity problems, each
   needing supports that prevent rigid motion (else MC_ERROR_SINGULAR). With contact
   surfaces: the discrete variational inequality (3.5); a body may then be held by contact
   alone (Corollary 4.1). A solve after changing only loads, prescribed values or nothing
   reuses the factorizations and the interface operator. */
MC_API mc_status mc_solve(mc_model *m);

/* Progress messages of mc_solve: phases and active-set iterations. */
typedef enum mc_log_level {
  MC_LOG_PHASE = 1,     /* a phase started or ended: assembly, factorization, contact, ... */
  MC_LOG_ITERATION = 2  /* one active-set iteration: its number, active nodes, residuals */
} mc_log_level;
/* Called from the thread that calls mc_solve (and from a call that computes results on demand,
   for their messages: "Results on demand" above), with a NUL-terminated one-line message that is
   valid only during the call. The callback must not call back into the same model. Phase
   messages after "solve: start, ..." ("assembly: body 1, ...", "factorization: ...",
   "interface operator: ...", "active-set solve: ...", "recovery: ...", "solve: done, ...")
   end with the phase's time in seconds; iteration messages read "active-set iteration K: A active of Q, F to flip, residual
   R" (R: the relative complementarity violation, MC_INFO_COMPLEMENTARITY at the last one). The
   callback is a C function: it must return normally (a C++ callback catches its exceptions;
   one thrown into the shared library, which has its own unwinder, terminates the process). */
typedef void (*mc_log_fn)(void *user_data, mc_log_level level, const char *message);
/* Installs (fn != NULL) or removes (fn == NULL) the model's log callback. */
MC_API mc_status mc_set_log_callback(mc_model *m, mc_log_fn fn, void *user_data);

/* ---- results ------------------------------------------------------------ */

MC_API mc_status mc_get_info_int(const mc_model *m, int info, int64_t *value);
MC_API mc_status mc_get_info_real(const mc_model *m, int info, double *value);
/* Displacements of a body: 2 per node (n_nodes of that body). */
MC_API mc_status mc_get_displacement(const mc_model *m, int body, double *u);
/* Stresses of a body: 4 per cell: xx yy xy zz, averaged over the cell (exact for P1).
   Axisymmetric: rr zz rz and the hoop stress theta-theta in the fourth slot, averaged over the
   cell's volume of revolution (weight 2 pi r). */
MC_API mc_status mc_get_stress(const mc_model *m, int body, double *sigma);
/* Stresses of a body at its nodes: 4 per node (n_nodes of that body), the components of
   mc_get_stress. Each cell's stress is evaluated at each of its nodes (for P1 the cell's constant
   stress), and a node gets the mean over the cells that share it. Exact for a uniform stress
   state with every cell kind. On the axis of an axisymmetric model the hoop strain u_r / r is
   taken as its limit du_r/dr. */
MC_API mc_status mc_get_nodal_stress(const mc_model *m, int body, double *sigma);
/* The error indicators of a body's cells: n_cells values, relative like MC_INFO_ERROR_ESTIMATE,
   whose squares over both bodies add up to its square: refine where they are large.
   MC_ERROR_STATE before a solve, for a host body, or when MC_OPTION_ERROR_ESTIMATE is 0. */
MC_API mc_status mc_get_error_indicator(const mc_model *m, int body, double *eta);
/* Support reactions of a body: 2 per node; the force the supports exert on the body at
   prescribed components, 0 at the others. Reactions + applied loads + contact forces = 0. */
MC_API mc_status mc_get_reaction(const mc_model *m, int body, double *r);

/* Number of body-1 contact positions (the length of the arrays below): the nodes of body 1's
   contact surface, except that a corner node where the smooth surface is split
   (MC_OPTION_FEATURE_ANGLE) counts once per face, each with that face's normal and its own
   constraint. On a quadratic surface (T6, Q8, Q9 cells) the mid-edge nodes are positions too,
   each right after its edge's first corner. */
MC_API mc_status mc_get_contact_count(const mc_model *m, mc_int *n);
/* Their node ids (index base applies), in order along each face of the surface. */
MC_API mc_status mc_get_contact_nodes(const mc_model *m, mc_int *nodes);
/* Contact pressure at those positions, >= 0, force per unit area (per unit length of Gamma_c
   per unit thickness). Recovered by lumping: p_j = f_j / (t * integral of phi_j over Gamma_c),
   which is exact for uniform pressure. Axisymmetric: p_j = f_j / (integral of phi_j 2 pi r
   over Gamma_c), per unit area of the true surface; at a node on the axis that area is small
   (2 pi h^2 / 6 for an edge of length h) and the pressure correspondingly less accurate than
   elsewhere; a node whose contact edges all lie on the axis reports 0. With quadratic cells in
   body 1: the method's own pressure field, continuous and piecewise linear on the corner nodes
   (the multipliers, docs/theory.md section 2b), a middle getting the mean of its corners. */
MC_API mc_status mc_get_contact_pressure(const mc_model *m, double *p);
/* Normal contact forces f_j >= 0 on body 1 at those positions (total force, thickness
   included; axisymmetric: total over the node's ring), pushing body 1 along -n_j: the
   multiplier of the position's own constraint row, plus its share of a row at an end of
   Gamma_c inside one of its edges. With quadratic cells in body 1: the consistent nodal
   forces of the pressure field (1/6, 2/3, 1/6 of an edge's share for a uniform pressure); a
   corner's can be slightly negative where the pressure varies fast. */
MC_API mc_status mc_get_contact_force(const mc_model *m, double *f);
/* Discrete gap after the solve: g0_j - (u1_j - pi(u2)_j).n_j >= 0 (the row of the cone K_h);
   +infinity for positions that see no mortar surface. */
MC_API mc_status mc_get_contact_gap(const mc_model *m, double *g);
/* Initial gap g0_j along the normal (negative: interference); +infinity where no mortar surface. */
MC_API mc_status mc_get_contact_initial_gap(const mc_model *m, double *g0);
/* Unit outward normals n_j of body 1 at the contact nodes: 2 per node. */
MC_API mc_status mc_get_contact_normal(const mc_model *m, double *n);

/* ---- output ------------------------------------------------------------- */

/* Writes the solved scene for ParaView. A path ending in ".pvd" writes a collection and one
   VTK XML unstructured-grid file per body next to it ("<stem>_body1.vtu", "<stem>_body2.vtu");
   any other path gets one .vtu with both bodies (cell data "body" = 1 or 2). Point data:
   displacement and the nodal stress (mc_get_nodal_stress); cell data: stress (xx yy xy zz;
   axisymmetric: rr zz rz theta_theta), von Mises; on body 1's contact nodes (zero
   elsewhere, flag "contact" = 1): contact pressure, gap, initial gap and "active" (force > 0).
   Cells keep the mesh's node order (VTK's = Gmsh's = mc_set_mesh's), with VTK cell types 5
   (P1 triangle), 9 (Q1), 22 (T6, VTK_QUADRATIC_TRIANGLE), 23 (Q8, VTK_QUADRATIC_QUAD) and 28
   (Q9, VTK_BIQUADRATIC_QUAD); every node of a quadratic mesh, mid-edge and centre nodes
   included, is a point with its own values.
   MC_ERROR_STATE before a successful solve; MC_ERROR_ARGUMENT if the file cannot be written.
   Array names: point data "displacement" (3 components, z = 0), "nodal_stress" (4 components,
   as "stress"), "pressure", "gap", "initial_gap", "active", "contact", and the fields of
   friction "shear", "slip", "slip_total" and "state" (MC_CONTACT_SHEAR, ...; state an integer,
   MC_STATE_*); cell data "stress" (4
   components), "von_mises" (with sigma_zz), "body". A corner node, a contact position in two
   faces, gets its total force over its total tributary measure as pressure, and the smaller of
   its gaps. A body-1 contact-surface node that sees no mortar surface has
   "contact" = 0 and gap = initial_gap = -1 (a sentinel for the +infinity of the getters: VTK
   readers take no inf). ASCII, 17 significant digits (values read back exactly), independent
   of the C locale. Only bodies with a mesh are written. */
MC_API mc_status mc_write_vtu(const mc_model *m, const char *path);

#ifdef __cplusplus
}
#endif
#endif /* MORTARCONTACT_H */
