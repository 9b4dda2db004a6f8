// The scene a host registers (bodies 0..N-1, materials, supports, loads, contact pairs), the
// solve, and its results. ids are 0-based here; the C API layer handles the index base.
#pragma once
#include "mortarcontact.h"
#include <algorithm>
#include "bodies/assembly.hpp"
#include "contact/contact_geometry.hpp"
#include "linalg/dual_qp.hpp"
#include "linalg/friction_qp.hpp"
#include "bodies/host_body.hpp"
#include "bodies/mesh.hpp"
#include "contact/mortar_operators.hpp"
#include "support/progress_log.hpp"
#include "bodies/rigid_modes.hpp"
#include "linalg/envelope_bound.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/sparse_contact_solve.hpp"
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mc {

class Error;

// A node of an axisymmetric model lies on the axis when |x| <= axis_tolerance(mesh) (a
// relative 1e-12 of the mesh's extent: a mesh generator's round-off); one with x below
// -axis_tolerance is an error (first_node_left_of_axis finds it, -1 if none).
double axis_tolerance(const Mesh &mesh);
int first_node_left_of_axis(const Mesh &mesh);

struct EdgeLoad {
  int a, b;        // nodes, oriented as the cell (body on the left)
  double tx, ty;   // traction (per unit length), or pressure in tx with is_pressure
  bool is_pressure;
};

struct Body {
  bool has_mesh = false;  // a mesh body, or a host body (whose mesh holds nodes only)
  Mesh mesh;
  bool host = false;      // mc_set_host_body: the stiffness and load are the host's (host_body.hpp)
  HostBody host_data;
  bool has_material = false;
  double young = 0, poisson = 0;
  std::vector<double> cell_elasticity;  // 9 per cell when given
  // Per DOF: 2 per node (x, y) for a mesh body, one per host equation for a host body.
  std::vector<char> prescribed;         // per DOF
  std::vector<double> prescribed_value;
  std::vector<double> nodal_force;      // per DOF
  std::vector<EdgeLoad> edge_loads;
  double body_force[2] = {0, 0};
  // results (the stresses and the error estimate: Model::cell_stresses and the others, on demand)
  std::vector<double> u, reaction;      // per DOF
  std::vector<double> contact_load;     // per DOF: the contact forces on the body (K u = f + contact_load)
};

// A contact pair (mc_add_contact_pair; a two-body model's pair 1 is (0, 1)): the non-mortar
// body carries the constraint and its multipliers (the paper's Omega^1), the mortar body is the
// surface the gaps are measured against.
struct ContactPair {
  int nonmortar = 0, mortar = 1;
  bool has_side[2] = {false, false};   // [0] the non-mortar side, [1] the mortar side
  std::vector<SurfaceSegment> side[2];
  std::vector<double> gap_offset;      // per non-mortar node, added to g0; empty: none
  int friction_law = MC_FRICTION_NONE; // mc_set_friction
  double friction_value = 0;           // Tresca: the slip bound (a shear traction); Coulomb: mu
  bool complete() const { return has_side[0] && has_side[1]; }
  int body_of_side(int s) const { return s == 0 ? nonmortar : mortar; }
};

// What a solve keeps for the next one when only loads or prescribed values change.
struct BodySystem {
  SymmetricCsc stiffness;          // all 2n DOFs
  std::vector<PlaneLaw> laws;
  RigidModes rigid;
  std::vector<int> solve_index;    // DOF -> reduced index, -1 if prescribed or pinned
  std::vector<int> solve_dofs;
  SymmetricCsc reduced;            // K less supports and pins: the condensed path's matrix
  bool reduced_held = false;       // false once the sparse path has freed it (reduce_stiffness rebuilds it)
  SparseCholesky cholesky;
  std::vector<int> interface;      // DOFs (full numbering) in B, ordered last in the factor
  EnvelopeBound envelope;          // of `reduced`, for the automatic choice (set only there)
};

// The pairs of one non-mortar and one mortar body, as one surface on each side (contact_pairs.cpp:
// a surface split into several pairs gives the unsplit answer, one multiplier per position):
// its geometry and rows, whose positions and rows are numbered from first_position and
// first_row in the stacked ContactSystem.
struct ContactGroup {
  int nonmortar = 0, mortar = 1;
  std::vector<int> pairs;          // the model's pairs joined here, in order
  ContactGeometry geometry;
  ConstraintRows rows;             // the group's own rows (its positions 0-based): its results
  int first_position = 0, first_row = 0;
  std::vector<double> gap_offset;  // per non-mortar node, its pairs' offsets; empty: none
  int positions() const { return int(geometry.nodes.size()); }
};

struct ContactSystem {
  std::vector<ContactGroup> groups;
  // Every group's rows stacked (positions and auxiliary points renumbered across the groups):
  // what the interface solvers read. A row's non-mortar weights (start1, position1, weight1) are
  // kept; its mortar weights live in B.
  ConstraintRows rows;
  std::vector<int> row_group, aux_group, position_group;
  // Per model pair: its positions (a position of a joined group belongs to every pair whose
  // non-mortar edges hold its node).
  std::vector<std::vector<int>> pair_positions;
  // B per body as CSR over rows: (DOF, coefficient); a body no row touches has empty rows.
  std::vector<std::vector<int>> b_start, b_dof;
  std::vector<std::vector<double>> b_value;
  // B without the mortar weights of the rows with a mortar value (ConstraintRows::aux): the
  // sparse path builds its structure from it. Without friction it never completes it (a row's
  // mortar part is -n . w_a, and the mortar body's contact forces R^T mu: aux_values and
  // aux_multipliers below); friction and the condensed path complete it first (complete_b).
  bool b_partial = false;
  double b_completion_seconds = 0;  // what completing it took
  bool b_completed_alongside = false;  // on a thread of its own, while the sparse path's ordering ran
  // The last sparse solve's mortar values w (2 per aux point: x, y) and the multipliers mu of
  // their equations D w - R u2 = 0 (the same order), read where B is partial: a row's gap
  // g_r - B_r u has -n . w_a for B's mortar part, and the mortar body's contact forces -B^T lambda
  // are R^T mu (the KKT system's stationarity in w: D^T mu = n lambda, so R^T mu = (D^-1 R)^T n lambda).
  std::vector<double> aux_values, aux_multipliers;
  // The rows that touch each body (B_b's nonzero columns), increasing.
  std::vector<std::vector<int>> body_rows;
  // The q x q interface operator B K^+ B^T, stored by blocks of rows: block (I, J) only if a
  // body touches rows of both (block_sparse_operator.hpp; two bodies: one dense block).
  BlockSparseOperator s;
  // W_b = L_GG^-1 (P B_b^T)_G per body (rows: the factor's trailing interface unknowns; columns:
  // the rows touching b, body_rows[b]): S = sum W_b^T W_b, B K^-1 f = sum W_b^T (L^-1 P f)_G, and
  // the recovery needs only L^-1 P B^T lambda = [0; W_b lambda]: one forward and one backward
  // solve per body. With many bodies W_b never holds a column of a pair b is not in.
  std::vector<std::vector<double>> w;
  std::vector<int> w_rows;
  std::vector<char> last_active;
  // The sparse path (MC_INTERFACE_SPARSE; sparse_contact_path.cpp): its unknowns are each body's
  // unsupported unknowns from column_offset[b] (a floating body's pins included: its block is
  // its whole stiffness on them, `floating`), the mortar values w (2 per ConstraintRows::aux
  // point) from aux_offset; its rows the q contact rows, then two mortar equations per aux point.
  bool sparse = false;
  SparseContactStructure structure;
  SparseContactSolver solver;
  std::vector<int> column_offset;
  // A floating body's block (rigid.count > 0): K on every DOF not prescribed, the pins of its
  // rigid modes kept, so that the active rows hold its rigid motion directly (H_P is SPD once
  // they do). With the pins removed and the modes' amplitudes as unknowns instead, the
  // amplitudes' pivot was the difference of the rows' penalty stiffness and what the pinned
  // body's bending gives back, which on a long strip held over a tenth of its length cancels
  // to round-off (docs/robustness.md, "A load on a part of a long strip").
  struct FloatingBlock {
    std::vector<int> index, dofs;  // DOF -> column in the block (-1: prescribed); the block's DOFs
  };
  std::vector<FloatingBlock> floating;  // per body; empty for a held body
  int aux_offset = 0, modes = 0;
  std::vector<double> g;           // G = B R, q x modes, column-major (both paths' floating bodies)
  // Friction (friction.cpp): B's rows q + j (j = 0 .. tangent_of.size() - 1) are the tangential
  // rows of normal rows tangent_of[j]: the same weights along t = (-n_y, n_x), so that row q + j
  // of B u is the weighted tangential displacement (u1 - pi_h u2) . t there. Only the rows of
  // pairs with friction have one. Per tangential row its law (MC_FRICTION_*) and its bound: mu
  // (Coulomb), or the Tresca bound times the row's multiplier measure (a force, like lambda).
  std::vector<int> tangent_of;
  std::vector<int> friction_law;
  std::vector<double> friction_bound;
  std::vector<FrictionState> friction_state;  // the last converged states (a warm start)
  int tangent_row_offset = 0;  // the sparse structure's row of tangential row 0 (after the equations)
  int b_rows() const { return rows.size() + int(tangent_of.size()); }  // B's rows: normal, then tangential
  const ContactGroup &group_of_position(int pos) const { return groups[position_group[pos]]; }
};

struct Options {
  int method = MC_METHOD_MORTAR;
  double tolerance = 1e-10;
  int max_iterations = 0;  // MC_OPTION_MAX_ITERATIONS; 0: not set (iteration_limit)
  // The active-set (and stick/slip) iterations allowed on q contact rows: MC_OPTION_MAX_ITERATIONS
  // where set, else 200, or q / 8 where that is more: a lift-off that spreads a row or two per
  // iteration takes about q / 12 (docs/robustness.md, "A pulled part of a long strip": 215 at
  // 2501 rows), and a wandering iteration is cut short by its patience, not by this limit.
  int iteration_limit(int q) const { return max_iterations > 0 ? max_iterations : std::max(kIterationLimit, q / 8); }
  static constexpr int kIterationLimit = 200;
  int ordering = MC_ORDERING_AUTO;
  int q1_integration = MC_Q1_FULL;
  int contact_normal = MC_NORMAL_NONMORTAR;
  int contact_surface = MC_SURFACE_SMOOTH;
  double feature_angle = 40;  // degrees (docs/robustness.md: chosen by measurement)
  int threads = 0;  // MC_OPTION_THREADS: 0 automatic, 1 serial, n: at most n threads
  int interface_solver = MC_INTERFACE_AUTO;  // MC_OPTION_INTERFACE_SOLVER
  bool error_estimate = true;                // MC_OPTION_ERROR_ESTIMATE
  int multiplier = MC_MULTIPLIER_LINEAR;     // MC_OPTION_MULTIPLIER
  int load_steps = 1;                        // MC_OPTION_LOAD_STEPS
  double friction_ct = 0;                    // MC_OPTION_FRICTION_CT (0: scaled automatically)
  bool eager_results = false;                // MC_OPTION_EAGER_RESULTS
};

struct Infos {
  long dofs = 0, factor_nnz = 0, iterations = 0, active = 0, contact_rows = 0, factorizations = 0;
  double t_assembly = 0, t_analysis = 0, t_factor = 0, t_solve = 0, t_contact = 0, t_total = 0;
  double energy = 0, complementarity = 0, equilibrium = 0;
  double gap_residual = 0;  // MC_INFO_GAP_RESIDUAL: complementarity of the returned displacements' gaps
  int threads = 1;  // threads the last solve ran the bodies' work on (1 or 2)
  int interface_solver = 0;  // MC_INFO_INTERFACE_SOLVER: MC_INTERFACE_CONDENSED or _SPARSE; 0 without contact
  long stick = 0, slip = 0;   // MC_INFO_STICK_NODES, MC_INFO_SLIP_NODES (rows of pairs with friction)
  double friction_complementarity = 0;  // MC_INFO_FRICTION_COMPLEMENTARITY
};

// The converged state a frictional solve steps from (friction.cpp): per body the displacements
// u0, the loads f0 and the prescribed values of the last converged step, and per contact position
// the accumulated slip. Empty (valid = false): the unloaded state.
struct History {
  bool valid = false;
  std::vector<std::vector<double>> u, f, prescribed;
  std::vector<double> slip_total;
};

// What the solve's displacements give on demand (results/results_on_demand.cpp): the stresses
// of the cells and at the nodes, and the error estimate, each computed when a getter first asks
// for it (or by the solve itself with MC_OPTION_EAGER_RESULTS), at most once per solve, and
// forgotten by the next solve. The model holds it as a mutable cache: the getters stay const.
struct DerivedResults {
  std::vector<char> has_stresses;                          // per body
  std::vector<std::vector<double>> stress, nodal_stress;   // per body: 4 per cell, 4 per node
  std::vector<double> stress_seconds;                      // per body
  bool has_estimate = false;
  double error_estimate = 0, estimate_seconds = 0;         // MC_INFO_ERROR_ESTIMATE, its time
  std::vector<std::vector<double>> error_indicator;        // per body, per cell; empty: not estimated
  void reset(size_t bodies) {
    *this = DerivedResults{};
    has_stresses.assign(bodies, 0), stress.resize(bodies), nodal_stress.resize(bodies);
    stress_seconds.assign(bodies, 0.0), error_indicator.resize(bodies);
  }
};

// The smaller body's unknowns (2 x its nodes) from which MC_OPTION_THREADS = 0 (automatic)
// solves the two bodies at once on a machine with two or more cores. Chosen by measurement
// (docs/benchmarks.md, "Threads"): below about 15000 the re-solve, a few milliseconds, was
// slower on two threads (starting them costs more than they save), and up to 25000 the gain was
// within the noise of a shared machine; from 30000 on it was clear in every run.
constexpr long kParallelMinBodyDofs = 30000;

// The refinement of a contact solve (Model::refine_solution) runs when the gaps of the
// recovered displacements (MC_INFO_GAP_RESIDUAL) exceed this: at most 1.1e-14 in every contact
// scene of the test suite, 3e-11 and more on the long strips (docs/robustness.md). Each step
// costs a forward and a backward solve per body and a dense solve of the active block.
constexpr double kRefineAboveGapResidual = 1e-13;
constexpr int kMaxRefinementSteps = 3;

// One body's share of a phase that runs for both bodies at once: its own timings and counts
// (added to the model's infos in body order) and, when it runs on a thread of its own, its
// progress messages, kept until the calling thread sends them on.
struct BodyWork {
  Infos infos;
  ProgressLog log;
  std::vector<std::pair<mc_log_level, std::string>> lines;
};

// One body's loads and their first solve: f, f_eff = f - K u_prescribed (0 at prescribed
// components), and either v = K^-1 f_eff (no contact) or y = L^-1 P f_eff (contact).
struct LoadSolve {
  std::vector<double> f, lifted, v, y;
  double seconds = 0;
};

class Model {
public:
  std::vector<Body> body = std::vector<Body>(2);  // mc_set_body_count: 2 unless told
  std::vector<ContactPair> pairs;                 // mc_add_contact_pair, or pair 1 by mc_set_contact
  Options options;
  Infos infos;
  bool plane_stress = false;
  bool axisymmetric = false;  // MC_AXISYMMETRIC: x = r >= 0, y the axis; thickness then unused
  double thickness = 1;
  int index_base = 0;
  bool solved = false;
  ProgressLog progress;  // the host's log callback (mc_set_log_callback), called by solve()

  // Anything that changes K, the supports' set, the contact surfaces or the method.
  void structure_changed() { ++structure_version_, solved = false; }
  void values_changed() { solved = false; }
  void solve();

  int n_bodies() const { return int(body.size()); }
  // Whether any pair has both its sides (a contact solve), and whether body b is in one.
  bool contact_active() const;
  bool in_contact(int b) const;
  // The body's unknowns before supports: 2 per node (mesh body) or the host's equations.
  int dof_count(int b) const;
  // The unknown of a node's component (0: x, 1: y), or -1 if a host body has none for it.
  int dof_of(int b, int node, int component) const;
  // Displacements 2 per node (0 where a host body's freedom has no equation).
  std::vector<double> nodal_displacement(int b) const;
  // The weight of every integral: the thickness, or 2 pi r (line_measure.hpp).
  LineMeasure measure() const { return LineMeasure{axisymmetric, thickness}; }
  const ContactSystem *contact() const { return contact_.get(); }
  // g0 of contact position pos (the stacked positions of ContactSystem's groups) with the host's
  // offset (mc_set_gap_offset, mc_set_pair_gap_offset).
  double initial_gap(size_t pos) const;
  // The non-mortar node of position pos, and its group.
  int position_node(size_t pos) const;
  // g0 of constraint row r with the host's offsets.
  double row_initial_gap(int r) const;
  double row_gap(int r) const;
  void add_contact_force(int b, const std::vector<double> &lambda, std::vector<double> &force) const;
  double pointwise_gap(size_t pos) const;
  void add_rigid_motion(int b, const std::vector<double> &alpha, std::vector<double> &u) const;
  double recovered_gap_residual(const std::vector<double> &lambda) const;
  bool refine_solution(DualQp &qp, std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha);
  // Contact results per contact position, the groups' stacked (after a contact solve).
  std::vector<double> contact_force, contact_gap, contact_pressure;
  // Friction's (and the state's, for every pair): shear traction along t, slip of the last solve,
  // accumulated slip, MC_STATE_*.
  std::vector<double> contact_shear, contact_slip, contact_slip_total;
  std::vector<int> contact_state;
  // mc_reset_history: the next frictional solve starts from the unloaded state.
  void reset_history();
  bool has_friction() const;

  // The results computed on demand (DerivedResults), for a solved model (the caller checks
  // `solved`): the first call computes, later ones read the cache. A failure (an overflow, out of
  // memory) throws and caches nothing: the model and its other results stay as they were.
  const std::vector<double> &cell_stresses(int b) const;   // 4 per cell (mc_get_stress)
  const std::vector<double> &nodal_stresses(int b) const;  // 4 per node (mc_get_nodal_stress)
  // Per cell, relative (mc_get_error_indicator); empty for a body not estimated (a host body,
  // or MC_OPTION_ERROR_ESTIMATE 0).
  const std::vector<double> &error_indicators(int b) const;
  double error_estimate() const;  // MC_INFO_ERROR_ESTIMATE; 0 with MC_OPTION_ERROR_ESTIMATE 0
  double results_seconds() const;  // MC_INFO_TIME_RESULTS: what computing them has cost so far

private:
  int body_threads() const;
  // Runs task(b, work) for every body: one after the other, or with two threads the odd ones on
  // a std::thread joined before returning. Exceptions are rethrown here, the first body's first.
  void for_each_body(const std::function<void(int, BodyWork &)> &task) { run_bodies(threads_, task, infos); }
  // The same on `threads` threads (1 or 2), the bodies' infos added to `add_to`.
  void run_bodies(int threads, const std::function<void(int, BodyWork &)> &task, Infos &add_to) const;
  std::unique_ptr<BodySystem> assemble_body(int b, BodyWork &work) const;
  void reduce_body(int b, BodyWork &work);
  void reduce_stiffness(int b, BodyWork &work);  // `reduced` from the stiffness and solve_index
  // needed: the condensed path will use it (refused if the interface is too long for it); else
  // for the automatic choice only (then skipped for such an interface, see body_phases.cpp).
  void analyze_body(int b, BodyWork &work, bool needed);
  void check_host_rigid_candidates(int b, const RigidModes &rigid, BodyWork &work) const;
  void check_held_motions_in_factor(int b, BodyWork &work) const;
  void factorize_body(int b, BodyWork &work);
  // The automatic choice of interface solver (MC_OPTION_INTERFACE_SOLVER); also refuses a path
  // too large for memory. True: sparse. It reads the bodies' analyses for the condensed path,
  // which `analyze_bodies` makes (for the automatic choice; the condensed path forced has made
  // them) unless the choice is clear without them (sparse_path_clear_unanalysed).
  bool choose_interface_solver(const std::function<void()> &analyze_bodies);
  // The condensed path's dense work alone outweighs a bound on the sparse path's (the bodies'
  // envelopes): the sparse path, chosen without analysing the bodies for the other one.
  bool sparse_path_clear_unanalysed(double start);
  // The share of the contact rows apart at the start (the sparse path's active set opens them).
  double rows_apart_at_start() const;
  // MC_ERROR_MEMORY if the condensed path's dense blocks (S, W_b, L_GG) would not fit.
  void check_condensed_fits() const;
  // The condensed path's interface operator as it will be stored (its pattern, no values):
  // its bytes and the flops of one factorization of its active rows (condensed_contact_path.cpp).
  struct CondensedOperatorCost {
    double bytes = 0, flops = 0;
    int blocks = 0;
  };
  CondensedOperatorCost condensed_operator_cost() const;
  // Body b's dense work on the condensed path (flops, no analysis needed): the factorization of
  // its trailing interface block, ng^3 / 3, and W_b = L_GG^-1 B_G^T with its share of S,
  // ng^2 q_b + ng q_b^2 (ng its interface unknowns, q_b the rows touching it).
  struct BodyDenseWork {
    double block = 0, coupling = 0;
  };
  BodyDenseWork condensed_dense_work(int b) const;
  // The sparse path (sparse_contact_path.cpp). solve_sparse returns false if its active-set
  // iteration cycled (then fall_back_to_condensed).
  void build_sparse_structure();
  bool solve_sparse(std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha);
  void sparse_loads(const std::vector<LoadSolve> &loads, std::vector<double> &load, std::vector<double> &target) const;
  bool rows_hold_modes(const std::vector<char> &holding) const;
  [[noreturn]] void fail_sparse_singular(const Error &error) const;
  // The sparse path's answer x in the bodies' terms (loads[b].v, zero at the pins) and the rigid
  // modes' alpha: a floating body's motion split into u = v + R alpha, as the condensed path's.
  // x is y of sparse_rigid_shift: alpha = alpha_0 + the amplitudes of y.
  void sparse_displacements(const std::vector<double> &x, const std::vector<double> &alpha_0,
                            std::vector<LoadSolve> &loads, std::vector<double> &alpha) const;
  std::vector<double> sparse_rigid_amplitudes(const std::vector<double> &x) const;  // of y alone
  std::vector<double> sparse_rigid_shift(const std::vector<char> &near, std::vector<double> &target) const;
  // Body b's columns in the sparse path: DOF -> column within its block (-1 prescribed), and back.
  const std::vector<int> &sparse_index(int b) const;
  const std::vector<int> &sparse_dofs(int b) const;
  // The condensed path (condensed_contact_path.cpp).
  void build_condensed(const std::function<void(int, BodyWork &)> &then);
  void fall_back_to_condensed(std::vector<LoadSolve> &loads);
  void solve_condensed(std::vector<LoadSolve> &loads, DualQp &qp, std::vector<double> &lambda, std::vector<double> &alpha);
  // Row r's share of the rigid modes, G = B R (q x modes, column-major), and e = R^T f_eff (the
  // bodies' modes in body order; mode_offset(b): where body b's start).
  std::vector<double> rigid_mode_rows() const;
  std::vector<double> rigid_mode_loads(const std::vector<LoadSolve> &loads) const;
  int mode_offset(int b) const;
  // The contact pairs joined into groups, their geometry and rows stacked, B per body
  // (contact_pairs.cpp).
  // partial_b: B without the mortar weights of the rows with a mortar value (the sparse path
  // forced: completed by complete_b before anything but its structure reads B).
  std::unique_ptr<ContactSystem> build_contact_system(bool partial_b);
  // B per body (contact_b.cpp): out's arrays as ContactSystem::b_start, b_dof, b_value; without
  // the mortar weights of rows with a mortar value unless mortar_values_weights.
  struct BArrays {
    std::vector<std::vector<int>> start, dof;
    std::vector<std::vector<double>> value;
  };
  void assemble_b(const ContactSystem &cs, bool mortar_values_weights, BArrays &out) const;
  void complete_b(const std::function<void()> &meanwhile);
  void find_interface(int b);
  void check_contact_pairs() const;
  void contact_results(const std::vector<double> &lambda);
  // Friction (friction.cpp): the rows' laws and bounds, the frictional condensed problem, the
  // history and load steps, the results per position.
  void refresh_friction();
  const ContactPair &group_friction(const ContactGroup &group) const;
  void solve_condensed_friction(DualQp &qp, std::vector<double> &lambda, std::vector<double> &alpha);
  void solve_sparse_friction(std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha);
  FrictionProblem friction_problem() const;
  FrictionObserver friction_log();
  // A frictional solve's outcome: its log line, its errors, and (solved) lambda, alpha, the
  // warm start and the infos.
  void accept_friction(const FrictionProblem &f, const FrictionResult &result, double start, const char *path,
                       std::vector<double> &lambda, std::vector<double> &alpha);
  double tangential_reference(int row) const;  // B row `row` (tangential) times u0, less its prescribed part
  void prepare_history();
  void step_loads(int step, int steps, const std::vector<LoadSolve> &target,
                  const std::vector<std::vector<double>> &target_prescribed, std::vector<LoadSolve> &start,
                  std::vector<LoadSolve> &loads);
  void record_step(const std::vector<LoadSolve> &loads);
  std::vector<double> pointwise_slips(const std::vector<std::vector<double>> &from) const;
  void friction_results(const std::vector<double> &lambda, const std::vector<std::vector<double>> &solve_start);
  void merge_gap_offsets();
  // "body 1: translation in y; ..." for the floating bodies, for both paths' messages.
  std::string free_modes_description() const;
  // The rigid motions that no support and no pair can hold, "body 2: translation in x" ("" if
  // the rows together hold every free mode).
  // holding: the B rows that hold (the rows in contact and the sticking ones, for friction);
  // empty: every row.
  std::string unheld_modes_description(const std::vector<char> &holding = {}) const;
  // The active-set iterations' log messages (MC_LOG_ITERATION), for both paths; empty without a
  // log callback.
  DualQpObserver iteration_log(int q);
  void interface_block(int b, std::vector<double> &s_b, BodyWork &work);
  void build_structure(const std::function<void(int, BodyWork &)> &then);
  void solve_loads(int b, BodyWork &work, LoadSolve &out) const;
  // Body b's stresses into the cache (results_on_demand.cpp); ensure_stresses also checks them
  // for overflow first (the solve's eager ones are checked by mc_solve's own check).
  void compute_stresses(int b) const;
  void ensure_stresses(int b) const;
  // MC_INFO_ERROR_ESTIMATE and the cells' indicators into the cache (error_estimate.cpp), once.
  void ensure_estimate() const;
  void estimate_error(double &estimate, std::vector<std::vector<double>> &indicators) const;
  std::vector<double> load_vector(int b) const;
  void effective_supports();
  // The supports a solve uses: the host's (mc_fix) and, in an axisymmetric model, u_r = 0 at
  // the nodes on the axis. Per DOF, like Body::prescribed and prescribed_value.
  std::vector<std::vector<char>> fixed_;
  std::vector<std::vector<double>> fixed_value_;
  int threads_ = 1;  // body threads of the solve under way
  long structure_version_ = 1, built_version_ = 0;
  std::vector<std::unique_ptr<BodySystem>> system_;
  std::unique_ptr<ContactSystem> contact_;
  History history_;
  mutable DerivedResults derived_;
};

}  // namespace mc
