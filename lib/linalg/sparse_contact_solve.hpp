// The contact problem solved sparse (MC_INTERFACE_SPARSE): both bodies, the auxiliary mortar
// values and the active rows together, at the cost of a few sparse factorizations whatever the
// length of the interface (docs/theory.md, "Two interface solvers").
//
// Unknowns x = (u_1, u_2, w): each body's unknowns not prescribed (a floating body's K_b is
// singular: the active rows hold its rigid motion), and the mortar values w of the interior
// trace points (ConstraintRows::aux). H = diag(K_1, K_2, 0) (`blocks`). Rows C x = t, each an
// equation (w's mortar equations, always kept) or an inequality
// (the contact rows, C x <= t: the paper's cone K_h, (3.2)-(3.5)). The KKT system on an active
// set A is
//     H x + C_A^T lambda_A = F,   C_A x = t_A,   lambda = 0 off A.
// It is solved exactly through the augmented-Lagrangian matrix H_P = H + C_A^T P C_A (SPD once
// the active rows hold the rigid modes; P > 0 diagonal, one weight per row): for any lambda,
// x(lambda) = H_P^-1 (F + C_A^T P t_A - C_A^T lambda) satisfies the first equation whenever the
// second holds, and the second is S_P lambda = b with S_P = C_A H_P^-1 C_A^T, solved by
// conjugate gradients preconditioned by P. P's weights make the local compliances of S_P small
// beside 1/P (kAugmentation), so P S_P has its spectrum in (0, 1] clustered at 1 and CG takes a
// few steps; each is a forward and a backward solve with the factor of H_P. The penalty never
// enters the answer: it is the exact solution of the KKT system, refined on its residuals.
//
// The active set is found by the same primal-dual active-set (semismooth Newton) iteration as
// the condensed path's (dual_qp.hpp): one numeric factorization of H_P per active set, one
// symbolic analysis for all (the pattern of H + C^T C holds every row's terms).
#pragma once
#include "linalg/dense_lu.hpp"
#include "bodies/assembly.hpp"
#include "linalg/dual_qp.hpp"
#include "linalg/sparse_cholesky.hpp"
#include <functional>
#include <vector>

namespace mc {

// One block of H: a symmetric matrix (upper triangle by columns) restricted to the unknowns
// `index` keeps, in their order: a body's stiffness read where it is (its supports left out),
// not copied (a copy of K per body was 8 % of the strips' peak memory).
struct SparseBlock {
  const SymmetricCsc *matrix = nullptr;
  const std::vector<int> *index = nullptr;    // the matrix's unknown -> the block's (-1: left out; increasing)
  const std::vector<int> *columns = nullptr;  // the block's unknown -> the matrix's
  int n = 0;
  // f(i, value) for each entry (i, c) of the block's column c, i <= c ascending.
  template <class F> void for_each_in_column(int c, F &&f) const {
    const int column = (*columns)[size_t(c)];
    for (int p = matrix->colptr[column]; p < matrix->colptr[column + 1]; ++p) {
      const int i = (*index)[size_t(matrix->rows[p])];
      if (i >= 0) f(i, matrix->values[p]);
    }
  }
};

// The problem's structure: what stays when only loads or prescribed values change.
struct SparseContactStructure {
  int n_unknowns = 0;             // columns of C and H
  // H's nonzero blocks, placed at block_offset on the diagonal.
  std::vector<SparseBlock> blocks;
  std::vector<int> block_offset;
  // C by rows (CSR); row_is_inequality[r] for the contact rows.
  std::vector<int> row_start{0}, column;
  std::vector<double> value;
  std::vector<char> row_is_inequality;
  int rows() const { return int(row_is_inequality.size()); }
};

enum class SparseContactOutcome { solved, modes_not_held, not_converged };

struct SparseContactResult {
  SparseContactOutcome outcome = SparseContactOutcome::solved;
  std::vector<double> x;       // n_unknowns
  std::vector<double> lambda;  // one per row (the equations' too)
  std::vector<char> active;    // the final active set (contact rows; a re-solve starts from it)
  int iterations = 0;          // active-set iterations
  int factorizations = 0;      // numeric factorizations of H_P in this solve
  int updates = 0;             // active sets solved through a low-rank update of the last factor instead
  int modifications = 0;       // active sets whose factor was the last one modified in place
  int path_refactorizations = 0;  // of those, by computing its rows on the changed paths afresh
  int cg_steps = 0;            // conjugate-gradient steps (each: one forward and one backward solve)
  double violation = 0;        // largest relative violation of complementarity (as MC_INFO_COMPLEMENTARITY)
  double t_factor = 0, t_solve = 0;
  bool cycled = false;         // not_converged because the iteration cycled or wandered
};

class SparseContactSolver {
public:
  // The pattern of H + C^T C, its ordering and symbolic factorization (ordering: MC_ORDERING_*).
  // `structure` must outlive the solver (its blocks are read at each factorization).
  void analyze(const SparseContactStructure &structure, int ordering);
  // Threads the solves with the factor may use (SparseCholesky::set_threads; the answer does not
  // depend on it).
  void set_threads(int threads) { threads_ = threads, cholesky_.set_threads(threads); }
  double split_top_share() const { return cholesky_.split_top_share(); }
  int split_factorizations() const { return cholesky_.split_factorizations(); }
  // Frees the pattern and the factor.
  void release() { cholesky_.release(), matrix_ = SymmetricCsc{}, inverse_order_.clear(), block_position_.clear(), factorized_.clear(), factor_set_.clear(), update_ = {}, modifications_ = 0, path_.clear(), aside_set_.clear(), begin_from_every_row_ = false, values_set_.clear(), column_rows_start_.clear(), column_rows_.clear(); }
  // CHOLMOD's estimates from the analysis, for the automatic choice of path.
  double factor_flops() const { return flops_; }
  long factor_nnz() const { return cholesky_.factor_nnz(); }
  // After a factorization threw MC_ERROR_SINGULAR: the unknown whose pivot failed, or -1.
  int failed_unknown() const { return cholesky_.failed_unknown(); }
  double analysis_seconds() const { return t_analysis_; }

  // Solves for loads F (n_unknowns) and right-hand sides t (one per row). start: the active
  // contact rows to begin with (one per row, equations ignored), e.g. the previous solve's;
  // empty: the rows whose initial gap (`initial_gap`, one per row; empty: target) is small, see
  // kStartGap. `hold_modes(active)`, if given, says whether an active set holds the floating
  // bodies (G_A of full rank); a set that does not is not factorized.
  SparseContactResult solve(const std::vector<double> &load, const std::vector<double> &target,
                            const std::vector<char> &start, double tolerance, int max_iterations,
                            const std::function<bool(const std::vector<char> &)> &hold_modes,
                            const DualQpObserver &observe = {}, const std::vector<double> &initial_gap = {});

  // Friction (friction_iteration.hpp; sparse_friction.cpp builds the rows): the linear system of
  // one set of rows E (`set`: the rows held to C_r x = t_r; the equations always are), some of
  // whose forces act along D_r = C_r + coefficient C_other instead of C_r (a slipping Coulomb
  // row: its normal row's multiplier pushes along t too, l_t = +-mu l_n):
  //     H x + D_E^T lambda_E = F,   C_E x = t_E.
  // Solved exactly as the frictionless system (the same H_P; refined on its own residuals), by
  // CG when no row is coupled, else by GMRES on the nonsymmetric C_E H_P^-1 D_E^T. x and lambda
  // start from what they hold (lambda: a warm start; x is overwritten).
  struct Coupling {
    int row = 0, other = 0;
    double coefficient = 0;
  };
  void solve_rows(const std::vector<double> &load, const std::vector<double> &target, const std::vector<char> &set,
                  const std::vector<Coupling> &coupling, std::vector<double> &x, std::vector<double> &lambda,
                  SparseContactResult &result);
  // An estimate of row r's compliance c_r H^-1 c_r^T (Jacobi: the one P's weight is made from).
  double row_compliance(int r) const;
  double row_times(int r, const std::vector<double> &x) const;  // C_r x

private:
  // H_P of the rows `active` (and the equations): a low-rank update of the factor it has when
  // few rows differ (update_from_factor), else a numeric factorization.
  void factorize(const std::vector<char> &active, SparseContactResult &result);
  bool update_from_factor(const std::vector<char> &active, SparseContactResult &result);
  void factorize_afresh(const std::vector<char> &active, SparseContactResult &result);  // never an update
  bool modify_factor(const std::vector<char> &active, SparseContactResult &result);
  // H_P of `active` from the factor at hand, its rows on the paths of the columns `changed` (those
  // the differing rows touch, from paths_seconds) computed afresh (SparseCholesky::
  // refactorize_paths); matrix_'s values brought to `active` first. False: not done (the factor
  // is then factorized afresh if it was touched).
  bool refactorize_paths(const std::vector<char> &active, const std::vector<int> &changed, SparseContactResult &result);
  // What refactorize_paths to `to` would take (seconds, kSecondsPerPathEntry), HUGE_VAL where it
  // is not done, cannot cost less than a modification, or would cost more than half a
  // factorization (as a modification); `changed`: the columns it recomputes from (else empty).
  double paths_seconds(const std::vector<char> &to, std::vector<int> &changed);
  // The columns (unknowns) that the rows where `to` differs from `from` touch.
  std::vector<int> columns_of_differing_rows(const std::vector<char> &from, const std::vector<char> &to) const;
  // What modifying the factor of the rows `from` (modified `modifications` times since its
  // factorization) into that of `to` would take (seconds, from measured rates; HUGE_VAL where it
  // is not done: a supernodal or small factor, or one modified too often).
  double modify_seconds(const std::vector<char> &from, int modifications, const std::vector<char> &to);
  // v = H_P^-1 v for the rows factorized_: the factor's solve, then the update's correction.
  void apply_inverse(std::vector<double> &v, SparseContactResult &result) const;
  // The KKT system on the factorized active set, solved as `goal` says: `judge`, by a Krylov
  // solve from lambda's start to kJudgingTolerance (a set on the way); `exact`, by a Krylov solve
  // to round-off, then refined on the KKT residuals; `refine`, refined from x and lambda as they
  // are (a judged or refined answer of this set: the refinement's first step takes it from there
  // to round-off, where a Krylov solve first would only take it part of the way). Returns the
  // relative residual reached (-1 when judged: not measured).
  enum class KktGoal { judge, exact, refine };
  double solve_on_active_set(const std::vector<double> &load, const std::vector<double> &target,
                             std::vector<double> &x, std::vector<double> &lambda, SparseContactResult &result,
                             KktGoal goal) const;
  double complementarity(const std::vector<double> &target, const std::vector<char> &active,
                         const std::vector<double> &x, const std::vector<double> &lambda, std::vector<double> &gap,
                         std::vector<int> &violating, double &lambda_ref) const;
  // CG on S_P lambda = b for the active rows; x follows lambda, until every active row's
  // residual is `tolerance` of its size (0: round-off, 1e-14). Returns the steps taken.
  int conjugate_gradients(const std::vector<double> &load, const std::vector<double> &target, std::vector<double> &x,
                          std::vector<double> &lambda, SparseContactResult &result, double tolerance = 0) const;
  // GMRES on C_E H_P^-1 D_E^T lambda = b for the rows of E (coupled rows); x follows lambda.
  int gmres(const std::vector<double> &load, const std::vector<double> &target, std::vector<double> &x,
            std::vector<double> &lambda, SparseContactResult &result) const;
  void apply_ct(const std::vector<double> &y, std::vector<double> &out) const;  // out = C_A^T y
  void apply_dt(const std::vector<double> &y, std::vector<double> &out) const;  // out = D_A^T y (coupling_)

  // P's weights: row r gets kAugmentation / sigma_r, sigma_r = sum_i c_ri^2 / H_ii (a Jacobi
  // estimate of the row's local compliance c_r H^-1 c_r^T). Then P S_P's local eigenvalues are
  // about kAugmentation / (1 + kAugmentation), and CG converges in a few steps; larger values
  // cost conditioning of H_P, which the refinement must then win back (chosen by measurement,
  // docs/notes/interface-solver.md).
  static constexpr double kAugmentation = 1e3;
  const SparseContactStructure *structure_ = nullptr;
  int position(int i, int j) const;  // of entry (min(i, j), max(i, j)) in matrix_
  SymmetricCsc matrix_;              // H_P's pattern (H + C^T C), values of the factorized set
  // Where the factor is simplicial, matrix_ is in its order: H_P(p, p), inverse_order_[i] the
  // position of unknown i (empty: matrix_ in the unknowns' own order), block_position_ the
  // place in matrix_ of each entry of H's blocks (in add_blocks_of_h's order).
  std::vector<int> inverse_order_, block_position_;
  // The active set whose rows' terms matrix_'s values hold (set by a factorization afresh; a
  // modification leaves the values as they were, refactorize_paths brings them to its set).
  std::vector<char> values_set_;
  void set_values(const std::vector<char> &active);  // matrix_'s values of `active` (refactorize_paths)
  std::vector<int> column_rows_start_, column_rows_;  // C by columns: each unknown's rows (set_values)
  void order_as_factor();
  void add_rows_terms(const std::vector<char> &active);
  void add_blocks_of_h();
  std::vector<double> weight_;       // P, one per row
  SparseCholesky cholesky_;
  int threads_ = 1;  // set_threads
  // task(0) and task(1): at once on two threads where threads_ allows and worth_a_thread, else
  // in turn (the tasks must not share what they write).
  void run_in_pairs(const std::function<void(size_t)> &task, bool worth_a_thread) const;
  // The residuals' H x, and the analysis's pattern and placing of H_P, on two threads from this
  // many unknowns.
  static constexpr int kResidualThreadsFromUnknowns = 20000;
  std::vector<char> factorized_;     // the active set H_P is of (empty: none)
  std::vector<char> factor_set_;     // the active set of the Cholesky factor (differs by update_)
  // H_P = H_0 + sum_r sign_r P_r c_r^T c_r over the rows that differ from the factor's set
  // (Sherman-Morrison-Woodbury): Z = H_0^-1 [c_r^T], M = diag(1 / (sign_r P_r)) + [c_r] Z, LU.
  struct LowRankUpdate {
    std::vector<int> rows;
    std::vector<double> z;  // n x k, column-major
    DenseLu m;              // M, k x k
  } update_;
  int modifications_ = 0;            // of the factor in place since its factorization
  // Below 5e7 flops a factorization takes a few milliseconds and the costs of updates and
  // modifications were not measured: there the flops decide whether to update, as before the
  // measurement (every small scene of the test suite: an update loses some digits that a
  // factorization of such a size costs nothing to keep), nothing is modified in place and no
  // factor is kept aside (sparse_factor_update.cpp).
  bool measured_costs() const { return flops_ >= 5e7; }
  // Within solve(): the factor before the last factorization, kept aside with its set, for a set
  // that comes back near it (a load step's wild set, sparse_factor_update.cpp). The factor of
  // every contact row, unmodified, is kept past the solve: a re-solve whose first step proposes
  // a set only a factorization reaches starts again from it instead (solve()).
  bool keep_aside_ = false;
  int aside_modifications_ = 0;
  std::vector<char> aside_set_;
  bool aside_holds_every_row() const;
  // Whether H_P of `set` would take a numeric factorization (factorize(): neither factor at hand
  // modified, nor the last one updated, at under half a factorization's cost).
  bool needs_factorization(const std::vector<char> &set);
  // Whether `to` is more rows away from `from` than a low-rank update of from's factor takes.
  bool far_apart(const std::vector<char> &from, const std::vector<char> &to);
  // The last re-solve's start (its previous answer's set) was a poor one: its first step proposed
  // a set only a factorization reaches, or it began from every row and ended far from that start.
  // The next re-solve then begins from every row (the factor aside) instead of judging a start
  // that would send it there after a solve (a load moving along the strips: every step's first
  // iteration, bench/moving_load). Cleared by a re-solve that ends near its start.
  bool begin_from_every_row_ = false;
  void update_rows(const std::vector<char> &active, std::vector<int> &rows, std::vector<int> &kept, int &fresh) const;
  bool update_fits(int k, int fresh) const;
  std::vector<double> path_;         // each unknown's elimination-tree path in L (entries)
  std::vector<Coupling> coupling_;   // of the system being solved (solve_rows; empty: D = C)
  double flops_ = 0, t_analysis_ = 0;
};

}  // namespace mc
