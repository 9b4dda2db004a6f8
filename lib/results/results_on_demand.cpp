// The results a solve's displacements give (DerivedResults, solve/model.hpp): the cells'
// stresses, the nodal stresses and the error estimate, computed when a getter first asks for them
// (mc_get_stress, mc_get_nodal_stress, mc_get_error_indicator, MC_INFO_ERROR_ESTIMATE,
// mc_write_vtu) or by the solve itself with MC_OPTION_EAGER_RESULTS, by the same code either
// way: the same numbers to the bit. A re-solve after a load change then costs its triangular
// solves, not the stresses and the estimate nobody reads (docs/benchmarks.md, "Re-solves").
#include "bodies/cell_shapes.hpp"
#include "solve/model.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <cmath>
#include <utility>

namespace mc {

namespace {

void require_body_slot(const DerivedResults &derived, int b) {
  if (b < 0 || size_t(b) >= derived.has_stresses.size())
    fail(MC_ERROR_INTERNAL, "results of body %d asked for without a solve", b + 1);
}

}  // namespace

// Stresses averaged over each cell, and at the nodes: each cell's stress at its own nodes,
// averaged over the cells sharing a node. (With two body threads the solve runs this for both
// bodies at once: each writes only its own slot of the cache, sized by the solve.)
void Model::compute_stresses(int b) const {
  const double start = now();
  const Body &body_ = body[b];
  const Mesh &mesh = body_.mesh;
  const std::vector<PlaneLaw> &laws = system_[b]->laws;
  const int npc = mesh.nodes_per_cell();
  const bool bbar = options.q1_integration == MC_Q1_BBAR && npc == 4;
  std::vector<double> &stress = derived_.stress[b], &nodal_stress = derived_.nodal_stress[b];
  stress.assign(4 * size_t(mesh.n_cells()), 0.0);
  nodal_stress.assign(4 * size_t(mesh.n_nodes()), 0.0);
  std::vector<int> cells_at(mesh.n_nodes(), 0);
  Point p[kMaxCellNodes];
  double ue[2 * kMaxCellNodes], at_nodes[4 * kMaxCellNodes];
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int *cv = mesh.cell(c);
    for (int a = 0; a < npc; ++a) p[a] = mesh.node(cv[a]), ue[2 * a] = body_.u[2 * cv[a]], ue[2 * a + 1] = body_.u[2 * cv[a] + 1];
    const PlaneLaw &law = laws.size() == 1 ? laws[0] : laws[c];
    cell_stress(p, npc, law, measure(), bbar, ue, &stress[4 * size_t(c)]);
    cell_nodal_stresses(p, npc, law, measure(), bbar, ue, at_nodes);
    for (int a = 0; a < npc; ++a) {
      cells_at[cv[a]]++;
      for (int k = 0; k < 4; ++k) nodal_stress[4 * size_t(cv[a]) + k] += at_nodes[4 * a + k];
    }
  }
  for (int i = 0; i < mesh.n_nodes(); ++i)
    for (int k = 0; k < 4; ++k) nodal_stress[4 * size_t(i) + k] /= cells_at[i];
  derived_.has_stresses[b] = 1;
  derived_.stress_seconds[b] += now() - start;
}

// On demand: computed, then checked as mc_solve checks the eager ones (stresses beyond double
// range are an error, never inf or NaN with MC_OK); a failure leaves nothing cached.
void Model::ensure_stresses(int b) const {
  require_body_slot(derived_, b);
  if (derived_.has_stresses[b]) return;
  if (!body[b].has_mesh || body[b].host || !system_[b])
    fail(MC_ERROR_INTERNAL, "stresses of body %d asked for, which has no cells", b + 1);
  const double start = now();
  compute_stresses(b);
  const std::vector<double> &stress = derived_.stress[b];
  for (size_t i = 0; i < stress.size(); ++i)
    if (!std::isfinite(stress[i])) {
      const double v = stress[i];
      derived_.has_stresses[b] = 0, derived_.stress[b].clear(), derived_.nodal_stress[b].clear();
      fail(MC_ERROR_ARGUMENT,
           "the stresses overflow: %s of body %d is %g; the scene's numbers (Young's moduli, thickness, loads, "
           "prescribed values) are beyond what double precision can give: rescale the units",
           array_position("sigma", i, index_base).c_str(), b + 1, v);
    }
  progress(MC_LOG_PHASE, "stresses: body %d, %d cells and %d nodes, %.3g s", b + 1, body[b].mesh.n_cells(),
           body[b].mesh.n_nodes(), now() - start);
}

const std::vector<double> &Model::cell_stresses(int b) const {
  ensure_stresses(b);
  return derived_.stress[b];
}

const std::vector<double> &Model::nodal_stresses(int b) const {
  ensure_stresses(b);
  return derived_.nodal_stress[b];
}

// The estimate of both bodies at once (its denominator is their energy together), or nothing
// when MC_OPTION_ERROR_ESTIMATE is 0. Called by the solve (eager) or by the first getter.
void Model::ensure_estimate() const {
  if (derived_.has_estimate) return;
  if (!options.error_estimate) {
    derived_.has_estimate = true;  // 0, and no indicators
    return;
  }
  const double start = now();
  double estimate = 0;
  std::vector<std::vector<double>> indicators;
  estimate_error(estimate, indicators);
  const double seconds = now() - start;
  derived_.error_estimate = estimate, derived_.error_indicator = std::move(indicators);
  derived_.estimate_seconds += seconds, derived_.has_estimate = true;
  progress(MC_LOG_PHASE, "error estimate: %.3g (relative, energy norm), %.3g s", estimate, seconds);
}

const std::vector<double> &Model::error_indicators(int b) const {
  require_body_slot(derived_, b);
  ensure_estimate();
  return derived_.error_indicator[b];
}

// (An info reads as the last solve's even after the model changed: computed before the change it
// is kept; not computed yet, it can no longer be, and reads 0 as it does before any solve.)
double Model::error_estimate() const {
  if (derived_.has_estimate) return derived_.error_estimate;
  if (!options.error_estimate || !solved) return 0;
  ensure_estimate();
  return derived_.error_estimate;
}

double Model::results_seconds() const {
  double seconds = derived_.estimate_seconds;
  for (double s : derived_.stress_seconds) seconds += s;
  return seconds;
}

}  // namespace mc
