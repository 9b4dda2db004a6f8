// The contact problem reduced to the interface (design note "Solving the QP fast"):
//
//   minimise 1/2 l^T S l - l^T d   over  l >= 0,  G^T l = e
//
// with S = B K^+ B^T (q x q, SPD on ker G^T; stored by blocks, block_sparse_operator.hpp), d = B K^+ f - g, G = B R (q x k, R the
// rigid modes of floating bodies), e = R^T f. Its KKT conditions are those of (3.5):
//   gap = S l - d - G a >= 0,  l >= 0,  l . gap = 0,  G^T l = e,
// and u = K^+ (f - B^T l) + R a. Solved by a primal-dual active-set (semismooth Newton)
// iteration, which is exact once the active set is right; if it cycles, Murty's least-index
// single pivoting takes over (finite for S positive definite). Each iteration solves a linear
// system on the active rows: dense (LAPACK) when S is one dense block, as with two bodies;
// otherwise sparse (CHOLMOD, or sparse_lu.hpp), never forming the blocks between rows that share
// no body.
#pragma once
#include "linalg/block_sparse_operator.hpp"
#include <functional>
#include <string>
#include <vector>

namespace mc {

struct DualQp {
  int q = 0, k = 0;
  BlockSparseOperator s;  // q x q
  std::vector<double> d;  // q
  std::vector<double> g;  // q x k column-major
  std::vector<double> e;  // k
};

enum class DualQpOutcome { solved, loads_not_balanced, modes_not_held, not_converged };

struct DualQpResult {
  DualQpOutcome outcome = DualQpOutcome::solved;
  std::vector<double> lambda, alpha, gap;
  int iterations = 0;
  double violation = 0;     // largest relative violation of the complementarity conditions
  double imbalance = 0;     // for loads_not_balanced: min ||G^T l - e|| / ||e|| over l >= 0
};

// What one active-set iteration did, for progress messages (mc_set_log_callback).
struct DualQpIteration {
  int iteration = 0;       // 1-based
  int active = 0;          // size of the active set the equality problem was solved on
  int violating = 0;       // rows violating l >= 0 (active) or gap >= 0 (inactive): to be flipped
  double residual = 0;     // largest relative violation of l >= 0, gap >= 0, l . gap = 0
  bool holds_modes = true; // false: the active set does not hold a floating body (step undone)
};
using DualQpObserver = std::function<void(const DualQpIteration &)>;

// active: a starting guess (size q, from a previous solve) or empty. observe (may be empty)
// is called once per iteration.
DualQpResult solve_dual_qp(const DualQp &problem, double tolerance, int max_iterations,
                           const std::vector<char> &active, const DualQpObserver &observe = {});

// After the first active-set iteration of a solve without a start (the all-active set, or the
// rows of initial interference), or the second of one started from an earlier solve's set (the
// first solve on the rows that the new loads made penetrate): rows left active whose force is
// below kSlackForce of the largest, positive but negligible or negative at round-off (so not
// flipped), are released with the pulling ones. Where the bodies touch along far more of the
// interface than carries load (a thin strip pressed over a part of its length, its free parts
// resting on the other at zero gap, or tipped onto it when the load moves past the end of the
// last contact zone), the solve on such a set leaves the forces of those parts at round-off or
// at the tails of a decaying bending wave, of either sign: releasing only the pulling ones
// keeps every other row of those parts holding them, and the primal-dual iteration then
// wanders for dozens of sets (docs/robustness.md, "A load on a part of a long strip": 75 sets
// and a fall-back to the condensed path before, 5 and 6 after). A row released wrongly is taken
// back by the next iteration (its gap < 0), so the answer, checked by the same complementarity
// test, is unchanged. Once per solve: applied after every growing step the rule itself made the
// iteration wander on that scene (tried, 2026-11-27). It applies to the set after the flips, so
// a row entering there (its force 0: it was inactive) waits one more iteration; sparing those
// rows made the same scene's load steps wander again from the second step at 4001 contact
// nodes (tried, 2026-11-27, session 16), and is not done.
constexpr double kSlackForce = 1e-3;
void release_slack_rows(const std::vector<double> &lambda, double lambda_ref, std::vector<char> &active);

// Whether the primal-dual iteration crawls rather than wanders: over the last `window`
// iterations (sizes: the active rows of each so far) its set moved one way by at least a row
// per iteration on average, with at most kCrawlFlips rows flipping now. Both paths judge an
// iteration without fewer violating rows for 20 iterations as wandering, and hand it to a
// slower method; a crawl keeps its count of violating rows (a zone's ends moving a row or two
// per iteration, docs/robustness.md, "A pulled part of a long strip") but is progress: it goes
// on (1001 contact nodes: 89 iterations instead of 390 after a hand-over to the primal active-set
// method, which changes one row per iteration). A wandering set jumps by dozens of rows.
constexpr size_t kCrawlFlips = 16;
bool crawling(const std::vector<int> &sizes, size_t flips, int window);

// The Gram matrix G_R^T G_R of the rows R of G (k columns of leading dimension ld: entry
// (r, c) at g[c * ld + r]) and its eigenvalues, ascending (LAPACK dsyev); with `vectors` the
// eigenvectors replace `gram`, column by column. ok is false if LAPACK failed.
struct RowsGram {
  std::vector<double> gram, eigenvalues;
  bool ok = false;
};
RowsGram rows_gram(const double *g, int ld, int k, const std::vector<int> &rows, bool vectors);
// Whether the rows R hold the k rigid modes: G_R of full rank, judged by its Gram matrix's
// smallest eigenvalue against 1e-12 of its largest. One test for the condensed path's active
// sets, the sparse path's and friction's (a set that fails it leaves a floating body free).
bool rows_hold_modes(const double *g, int ld, int k, const std::vector<int> &rows);

// Floating bodies: min ||G^T l - e|| / ||e|| over l >= 0 (0 without floating bodies). Above
// 1e-8 no contact forces (which only push) can balance the loads (DualQpOutcome::loads_not_balanced).
// Uses p.g, p.e, p.q and p.k only.
double load_imbalance(const DualQp &p);

// One step of iterative refinement on a fixed active set (Model::refine_solution): the
// correction (dl, da) with
//   S_AA dl_A - G_A da = d_A,  G_A^T dl_A = e,  dl = 0 off A,
// where d and e of `problem` hold the residuals (d = B K^+ r_f - gap, e = R^T r_f) and A is the
// set of rows where `active` is set. Returns false if the system is singular.
bool solve_correction(const DualQp &problem, const std::vector<char> &active, std::vector<double> &dl,
                      std::vector<double> &da);

}  // namespace mc
