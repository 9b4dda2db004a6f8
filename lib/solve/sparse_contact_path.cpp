// The model's side of the two interface solvers: which one runs (MC_OPTION_INTERFACE_SOLVER),
// and the sparse path's problem built from the scene (sparse_contact_solve.hpp does the
// solving). The condensed path is in model.cpp (its operator S) and dual_qp.cpp (its QP).
#include "solve/model.hpp"
#include "linalg/dense_lu.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include <algorithm>
#include "support/stopwatch.hpp"
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sys/resource.h>
#include <cstdlib>

namespace mc {

namespace {

// For the log: how the solves with the factor ran (SparseCholesky::solve: split by subtrees of the
// elimination tree, on two threads where the solve has them).
std::string split_solves_note(double top_share, int threads, int split_factorizations) {
  if (top_share < 0) return "";
  char note[200];
  std::snprintf(note, sizeof note,
                "; solves split in two halves of the factor (%.1f %% of it serial), %s; %d factorizations by halves "
                "on 2 threads since the analysis",
                100 * top_share, threads > 1 ? "on 2 threads" : "in turn", split_factorizations);
  return note;
}


// The memory this process can still get: what the kernel says it can have without swapping
// (MemAvailable), or less if the process runs under an address-space limit (RLIMIT_AS, `ulimit
// -v`: then the limit less what is mapped already). In bytes; 0 if unknown (then no path is
// refused for its size).
// A "Key: value kB" line of a /proc file, in bytes; 0 if absent.
double proc_field_bytes(const char *path, const char *key) {
  FILE *f = std::fopen(path, "r");
  if (!f) return 0;
  char line[256];
  double kib = 0;
  const size_t length = std::strlen(key);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, key, length) == 0) kib = std::atof(line + length);
  std::fclose(f);
  return kib * 1024;
}

double available_memory() {
  double bytes = proc_field_bytes("/proc/meminfo", "MemAvailable:");
  struct rlimit limit;
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const double headroom = std::max(double(limit.rlim_cur) - proc_field_bytes("/proc/self/status", "VmSize:"), 1.0);
    bytes = bytes > 0 ? std::min(bytes, headroom) : headroom;
  }
  return bytes;
}

double gib(double bytes) { return bytes / (1024.0 * 1024.0 * 1024.0); }

// Below this the memory is not asked for: reading /proc costs about 50 microseconds, a few % of
// a solve of 10^3 unknowns, and a process that has got this far has 64 MiB more to give.
constexpr double kMemoryQueryFrom = 64.0 * 1024 * 1024;

// available_memory() for a need of `bytes`; 0 (unknown: nothing is refused) below kMemoryQueryFrom.
double memory_for(double bytes) { return bytes < kMemoryQueryFrom ? 0 : available_memory(); }

}  // namespace

// The automatic choice weighs each path's work in flops of the bodies' sparse factorizations
// (docs/benchmarks.md, "The automatic choice, estimate against measurement", where these
// constants were measured on every benchmark scene):
// - a flop of the condensed path's dense BLAS-3 work (the trailing blocks of its factors, W_b and
//   S, the active-set systems on S) costs about a sixth of one of a sparse factorization of a
//   body: 0.04 to 0.1 s per Gflop against 0.45 to 0.7 on the strips, Westergaard, Hertz, the chain;
constexpr double kDenseFlopWeight = 1.0 / 6;
// - a flop of a triangular solve with the sparse path's factor (4 nnz per Krylov step) about
//   twice one of its factorization: memory-bound, about 1 s per Gflop;
constexpr double kSolveFlopWeight = 2;
// - the sparse path starts from every row in contact: where the surfaces touch at the start
//   (strips, chain) it needs 1 factorization and about 10 Krylov steps; where they are apart
//   (Hertz, Westergaard, Cattaneo) 4 to 5 factorizations (and low-rank updates) and 50 to 143
//   steps (22 to 49 frictionless since the sets on the way are judged by the Krylov solve alone;
//   97 to 275 with friction). Interpolated by the share of contact rows apart at the start. (The
//   constant before, 6 factorizations whatever the scene and no Krylov steps, took the sparse
//   path on Westergaard at 25 wavelengths at 1.3 to 3 times the condensed path's time.)
constexpr double kFactorizationsTouching = 1, kFactorizationsApart = 5;
constexpr double kKrylovStepsTouching = 10, kKrylovStepsApart = 100;
// The condensed path is refused when it would take more than this share of the memory
// available (MemAvailable), the sparse path when it would take more than all of it: the
// operating system would otherwise kill the host process, which a library must not cause.
constexpr double kCondensedMemoryShare = 0.5;

void Model::check_condensed_fits() const {
  const ContactSystem &cs = *contact_;
  const double q = cs.rows.size();
  double bytes = condensed_operator_cost().bytes;
  for (int b = 0; b < n_bodies(); ++b)
    if (system_[b]) {
      const double ng = double(system_[b]->interface.size()), qb = double(cs.body_rows[b].size());
      bytes += 8 * (ng * qb + ng * ng);
    }
  const double memory = memory_for(bytes);
  if (memory > 0 && bytes > memory)
    fail(MC_ERROR_MEMORY,
         "the condensed interface solver (MC_INTERFACE_CONDENSED) would need about %.3g GiB for %d contact rows "
         "(an interface operator of order q), and %.3g GiB are available: use MC_INTERFACE_SPARSE or MC_INTERFACE_AUTO",
         gib(bytes), int(q), gib(memory));
}

// The share of the contact rows whose surfaces are apart at the start (an initial gap above 1e-8
// of the row's length, round-off of flat surfaces that touch being far below): the sparse path's
// active-set iteration opens them from its all-active start.
double Model::rows_apart_at_start() const {
  const ConstraintRows &rows = contact_->rows;
  int apart = 0;
  for (int r = 0; r < rows.size(); ++r) {
    double length = 0;
    for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p) length += std::fabs(rows.weight1[p]);
    apart += row_initial_gap(r) > 1e-8 * length * length;  // (the row's gap is weighted by its length)
  }
  return rows.size() > 0 ? double(apart) / rows.size() : 0;
}

// The sparse path's expected factorizations and Krylov steps, by the share of the rows apart at
// the start (the constants above).
static double expected_factorizations(double apart) {
  return kFactorizationsTouching + apart * (kFactorizationsApart - kFactorizationsTouching);
}
static double expected_krylov_steps(double apart) {
  return kKrylovStepsTouching + apart * (kKrylovStepsApart - kKrylovStepsTouching);
}

// The choice the estimates below would make, when it is clear before the bodies are analysed
// for the condensed path: that path's dense work (each body's trailing block, W_b and its share
// of S, the interface operator's factorization), weighed as below, is a lower bound on its
// estimate; the sparse path's estimate with each body's factorization bounded by its envelope
// (envelope_bound.hpp; the minimum-degree orderings fill less) is an upper bound on its own,
// taken kClearMargin times more. On the strips at 1001 contact nodes the lower bound is 4.5e9
// flops and the bound on the sparse path 1e7 to 1e8: the analyses (two orderings and symbolic
// factorizations, 15 % of the sparse path's solve) would not change the answer.
constexpr double kClearMargin = 10;

Model::BodyDenseWork Model::condensed_dense_work(int b) const {
  const ContactSystem &cs = *contact_;
  const BodySystem &sys = *system_[b];
  double ng = double(sys.interface.size());
  if (cs.b_partial) {
    // B without the mortar weights of the rows with a mortar value w_a: those rows reach the
    // mortar body through D^-1 R, whose support holds R_a's own nodes ((D^-1)_aa != 0), so the
    // interface is at least the partial B's unknowns and every R_a's (a lower bound, as the
    // check that reads it needs).
    std::vector<char> in(size_t(sys.stiffness.n), 0);
    for (int dof : sys.interface) in[size_t(dof)] = 1;
    for (int a = 0; a < cs.rows.aux_count; ++a) {
      if (cs.groups[cs.aux_group[a]].mortar != b) continue;
      for (int p = cs.rows.aux_r_start[a]; p < cs.rows.aux_r_start[a + 1]; ++p)
        for (int c = 0; c < 2; ++c) {
          const int dof = dof_of(b, cs.rows.aux_r_node[p], c);
          if (dof >= 0 && sys.solve_index[dof] >= 0 && !in[size_t(dof)]) in[size_t(dof)] = 1, ng += 1;
        }
    }
  }
  const double qb = double(cs.body_rows[b].size());
  return {ng * ng * ng / 3, ng * ng * qb + ng * qb * qb};
}

bool Model::sparse_path_clear_unanalysed(double start) {
  const ContactSystem &cs = *contact_;
  double dense_flops = condensed_operator_cost().flops, plain_flops = 0, plain_nnz = 0;
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const BodyDenseWork work = condensed_dense_work(b);
    dense_flops += work.block + work.coupling;
    plain_flops += system_[b]->envelope.flops, plain_nnz += system_[b]->envelope.nnz;
  }
  const double apart = rows_apart_at_start();
  const double factorizations = expected_factorizations(apart), krylov_steps = expected_krylov_steps(apart);
  const double condensed_at_least = kDenseFlopWeight * dense_flops;
  const double sparse_at_most = factorizations * plain_flops + krylov_steps * kSolveFlopWeight * 4 * plain_nnz;
  if (kClearMargin * sparse_at_most >= condensed_at_least) return false;
  progress(MC_LOG_PHASE,
           "interface solver: sparse (automatic: fewer operations, clear without analysing the bodies for the "
           "condensed path; condensed estimated %.3g flops at least (%.3g dense), sparse estimated %.3g flops at "
           "most (%.2g factorizations of %.3g flops, %.0f Krylov steps; %.0f %% of the rows apart at the start; the "
           "bodies' envelopes), for %d contact rows), %.3g s",
           condensed_at_least, dense_flops, sparse_at_most, factorizations, plain_flops, krylov_steps, 100 * apart,
           cs.b_rows(), now() - start);
  return true;
}

bool Model::choose_interface_solver(const std::function<void()> &analyze_bodies) {
  const double start = now();
  ContactSystem &cs = *contact_;
  merge_gap_offsets();  // (solve() merges them after the structure; rows_apart_at_start reads them)
  if (options.interface_solver == MC_INTERFACE_AUTO && sparse_path_clear_unanalysed(start)) return true;
  // The condensed path's analyses order each body's interface last: B whole first (its mortar
  // weights name the mortar body's interface unknowns).
  complete_b(nullptr);
  analyze_bodies();
  const double q = cs.b_rows();
  // The condensed path's cost from the bodies' analyses (interface last): their factors, each
  // body's W_b = L_GG^-1 B_G^T (ng x q) and its dense L_GG copy, S (q x q); time: the
  // factorizations, the triangular solve and rank-k update that form S, and the active-set
  // solves (q^3 for one dense block; by S's blocks otherwise: condensed_operator_cost).
  double flops = 0, nnz = 0, dense_block_flops = 0, dense_block_nnz = 0, extra_flops = 0, extra_bytes = 0;
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const double ng = double(system_[b]->interface.size()), qb = double(cs.body_rows[b].size());
    const BodyDenseWork work = condensed_dense_work(b);
    flops += system_[b]->cholesky.analysis_flops();
    nnz += double(system_[b]->cholesky.factor_nnz());
    dense_block_flops += work.block, dense_block_nnz += ng * ng / 2;
    extra_flops += work.coupling;
    extra_bytes += 8 * (ng * qb + ng * ng);
  }
  const CondensedOperatorCost interface_operator = condensed_operator_cost();
  const double condensed_bytes = 8 * nnz + extra_bytes + interface_operator.bytes;
  // The sparse path: about the bodies' factorization without the dense trailing blocks, once
  // per expected factorization, and a solve with that factor per expected Krylov step.
  const double plain_flops = std::max(flops - dense_block_flops, 0.05 * flops);
  const double plain_nnz = std::max(nnz - dense_block_nnz, 0.05 * nnz);
  const double dense_flops = std::min(dense_block_flops, flops) + extra_flops + interface_operator.flops;
  const double condensed_flops = plain_flops + kDenseFlopWeight * dense_flops;
  const double apart = rows_apart_at_start();
  const double factorizations = expected_factorizations(apart), krylov_steps = expected_krylov_steps(apart);
  const double sparse_flops = factorizations * plain_flops + krylov_steps * kSolveFlopWeight * 4 * plain_nnz;
  const double sparse_bytes = 8 * plain_nnz;
  const double memory = memory_for(condensed_bytes);
  bool analysed = true;  // analyze_body skips an interface too long for the condensed path
  for (int b = 0; b < n_bodies(); ++b)
    if (system_[b] && !system_[b]->cholesky.analyzed()) analysed = false;
  const bool condensed_fits = analysed && (memory <= 0 || condensed_bytes <= kCondensedMemoryShare * memory);
  if (options.interface_solver == MC_INTERFACE_CONDENSED) {
    if (memory > 0 && condensed_bytes > memory)
      fail(MC_ERROR_MEMORY,
           "the condensed interface solver (MC_INTERFACE_CONDENSED) would need about %.3g GiB for %d contact rows "
           "(an interface operator of order q), and %.3g GiB are available: use MC_INTERFACE_SPARSE or MC_INTERFACE_AUTO",
           gib(condensed_bytes), int(q), gib(memory));
    progress(MC_LOG_PHASE, "interface solver: condensed (asked for), estimated %.3g flops and %.3g GiB, %.3g s",
             condensed_flops, gib(condensed_bytes), now() - start);
    return false;
  }
  const bool sparse = !condensed_fits || sparse_flops < condensed_flops;
  // The estimates in flops of a sparse factorization: the condensed path's dense work weighed
  // by kDenseFlopWeight, the sparse path's solves by kSolveFlopWeight.
  progress(MC_LOG_PHASE,
           "interface solver: %s (automatic: %s; condensed estimated %.3g flops (%.3g dense) and %.3g GiB, sparse "
           "estimated %.3g flops (%.2g factorizations of %.3g flops, %.0f Krylov steps; %.0f %% of the rows apart at "
           "the start) and %.3g GiB, for %d contact rows), %.3g s",
           sparse ? "sparse" : "condensed",
           !condensed_fits ? "the condensed path would not fit in memory"
                           : sparse ? "fewer operations" : "fewer operations, and a re-solve is then nearly free",
           condensed_flops, dense_flops, gib(condensed_bytes), sparse_flops, factorizations, plain_flops, krylov_steps,
           100 * apart, gib(sparse_bytes), int(q), now() - start);
  return sparse;
}

std::string Model::free_modes_description() const {
  std::string text;
  for (int b = 0; b < n_bodies(); ++b)
    if (system_[b] && system_[b]->rigid.count > 0)
      text += (text.empty() ? "" : "; ") + std::string("body ") + std::to_string(b + 1) + ": " + system_[b]->rigid.description;
  return text;
}

DualQpObserver Model::iteration_log(int q) {
  if (!progress.enabled()) return {};
  return [this, q](const DualQpIteration &it) {
    if (it.holds_modes)
      progress(MC_LOG_ITERATION, "active-set iteration %d: %d active of %d, %d to flip, residual %.3g", it.iteration,
               it.active, q, it.violating, it.residual);
    else
      progress(MC_LOG_ITERATION, "active-set iteration %d: %d active of %d do not hold the floating body", it.iteration,
               it.active, q);
  };
}

std::vector<double> Model::rigid_mode_loads(const std::vector<LoadSolve> &loads) const {
  std::vector<double> e;
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const RigidModes &rm = system_[b]->rigid;
    const int ndof = system_[b]->stiffness.n;
    for (int c = 0; c < rm.count; ++c) {
      double s = 0;
      for (int i = 0; i < ndof; ++i) s += rm.modes[size_t(c) * ndof + i] * loads[b].lifted[i];
      e.push_back(s);
    }
  }
  return e;
}

std::vector<double> Model::rigid_mode_rows() const {
  const ContactSystem &cs = *contact_;
  const int q = cs.b_rows();
  std::vector<double> g;
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const RigidModes &rm = system_[b]->rigid;
    const int ndof = system_[b]->stiffness.n;
    for (int c = 0; c < rm.count; ++c) {
      const double *mode = &rm.modes[size_t(c) * ndof];
      for (int r = 0; r < q; ++r) {
        double s = 0;
        for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) s += cs.b_value[b][p] * mode[cs.b_dof[b][p]];
        g.push_back(s);
      }
    }
  }
  return g;
}

// The sparse path's unknowns and rows (ContactSystem, sparse_contact_solve.hpp), and the
// symbolic analysis of H + C^T C.
void Model::build_sparse_structure() {
  const double start = now();
  ContactSystem &cs = *contact_;
  const ConstraintRows &rows = cs.rows;
  const int q = rows.size();
  SparseContactStructure &st = cs.structure;
  st = SparseContactStructure{};
  int offset = 0;
  cs.modes = 0;
  cs.column_offset.assign(body.size(), 0);
  cs.floating.assign(body.size(), ContactSystem::FloatingBlock{});
  for (int b = 0; b < n_bodies(); ++b) {
    cs.column_offset[b] = offset;
    if (!system_[b]) continue;
    BodySystem &sys = *system_[b];
    if (sys.rigid.count > 0) {  // every DOF not prescribed (ContactSystem::FloatingBlock)
      ContactSystem::FloatingBlock &f = cs.floating[b];
      f.index.assign(sys.stiffness.n, -1);
      for (int i = 0; i < sys.stiffness.n; ++i)
        if (!fixed_[b][i]) f.index[i] = int(f.dofs.size()), f.dofs.push_back(i);
    }
    // The block reads K where it is (SparseBlock); the condensed path's K less supports and
    // pins is not used here: freed, and made again if that path takes over (build_condensed).
    sys.reduced = SymmetricCsc(), sys.reduced_held = false;
    const SparseBlock block{&sys.stiffness, &sparse_index(b), &sparse_dofs(b), int(sparse_dofs(b).size())};
    if (block.n > 0) st.blocks.push_back(block), st.block_offset.push_back(offset);
    offset += block.n;
    cs.modes += sys.rigid.count;
  }
  cs.aux_offset = offset;
  offset += 2 * rows.aux_count;
  st.n_unknowns = offset;
  // G reads B of the floating bodies: complete first if a partial B lacks mortar weights of one
  // (a floating mortar body; the strips' floating body is the non-mortar one).
  bool g_reads_partial = false;
  for (const ContactGroup &group : cs.groups)
    if (system_[group.mortar] && system_[group.mortar]->rigid.count > 0 && !group.rows.pending.empty()) g_reads_partial = true;
  if (g_reads_partial) complete_b(nullptr);
  cs.g = rigid_mode_rows();

  std::vector<std::pair<int, double>> entries;
  auto add_row = [&](bool inequality) {
    std::sort(entries.begin(), entries.end());
    size_t kept = 0;
    for (size_t i = 0; i < entries.size(); ++i) {
      if (kept > 0 && entries[kept - 1].first == entries[i].first) entries[kept - 1].second += entries[i].second;
      else entries[kept++] = entries[i];
    }
    for (size_t i = 0; i < kept; ++i)
      if (entries[i].second != 0) st.column.push_back(entries[i].first), st.value.push_back(entries[i].second);
    st.row_start.push_back(int(st.column.size()));
    st.row_is_inequality.push_back(inequality);
    entries.clear();
  };
  auto add_body_entries = [&](int b, int r) {
    const std::vector<int> &index = sparse_index(b);
    for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) {
      const int k = index[cs.b_dof[b][p]];
      if (k >= 0) entries.emplace_back(cs.column_offset[b] + k, cs.b_value[b][p]);
    }
  };
  // A contact row (B's row b_row, of contact row r): the non-mortar body's part, the mortar
  // body's (its weights, or -direction . w_a for a mortar value). direction:
  // the row's normal n, or t = (-n_y, n_x) for its tangential row.
  auto add_contact_row = [&](int r, int b_row, Point direction) {
    const ContactGroup &group = cs.groups[cs.row_group[r]];
    add_body_entries(group.nonmortar, b_row);
    if (rows.aux[r] < 0) {
      add_body_entries(group.mortar, b_row);
    } else {
      const int a = rows.aux[r];
      entries.emplace_back(cs.aux_offset + 2 * a, -direction.x);
      entries.emplace_back(cs.aux_offset + 2 * a + 1, -direction.y);
    }
    add_row(true);
  };
  for (int r = 0; r < q; ++r) add_contact_row(r, r, rows.normal[r]);
  // The mortar equations D w - R u2 = 0, per component (ConstraintRows::aux), u2 the mortar
  // body's of the point's group.
  for (int a = 0; a < rows.aux_count; ++a) {
    const int mortar = cs.groups[cs.aux_group[a]].mortar;
    const std::vector<int> &index2 = sparse_index(mortar);
    for (int c = 0; c < 2; ++c) {
      for (int p = rows.aux_d_start[a]; p < rows.aux_d_start[a + 1]; ++p)
        entries.emplace_back(cs.aux_offset + 2 * rows.aux_d_point[p] + c, rows.aux_d[p]);
      for (int p = rows.aux_r_start[a]; p < rows.aux_r_start[a + 1]; ++p) {
        const int dof = dof_of(mortar, rows.aux_r_node[p], c);  // (a host body's restrained freedom: none)
        const int k = dof >= 0 ? index2[dof] : -1;
        if (k >= 0) entries.emplace_back(cs.column_offset[mortar] + k, -rows.aux_r[p]);
      }
      add_row(false);
    }
  }
  // Friction: the tangential rows (B's rows q + j) after the equations, built as their normal
  // rows are, along t = (-n_y, n_x): -t . w_a for a mortar value. Switched in and out by the
  // stick/slip iteration as the contact rows are by the active set (sparse_friction.cpp).
  cs.tangent_row_offset = st.rows();
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) {
    const int r = cs.tangent_of[j];
    add_contact_row(r, q + int(j), Point{-rows.normal[r].y, rows.normal[r].x});
  }
  // The structure read B's non-mortar parts and the rows without a mortar value. Without
  // friction nothing else reads B's mortar weights (the gaps and contact forces come from w and
  // the equations' multipliers, ContactSystem::aux_values): a partial B stays partial, and its
  // mortar weights (13 % of the strips' peak memory at 4001 contact nodes when held at the
  // factorization) are never formed. Friction reads B whole (friction.cpp): completed while the
  // ordering runs (one thread).
  auto analyze = [&] {
    Stopwatch watch(infos.t_analysis);
    // The halves' orderings on two threads, unless B is completed on the second one meanwhile
    // (friction): the library runs one thread besides the caller's at a time.
    cs.solver.set_threads(cs.tangent_of.empty() ? threads_ : 1);
    cs.solver.analyze(st, options.ordering);
  };
  if (cs.tangent_of.empty()) analyze();
  else complete_b(analyze);
  const double bytes = 8.0 * double(cs.solver.factor_nnz()), memory = memory_for(bytes);
  if (memory > 0 && bytes > memory)
    fail(MC_ERROR_MEMORY,
         "the sparse interface solver's factor would need about %.3g GiB and %.3g GiB are available: the model is "
         "too large for this machine's memory",
         gib(bytes), gib(memory));
  if (cs.b_completion_seconds > 0)
    progress(MC_LOG_PHASE,
             "analysis: sparse interface solver, %d unknowns (%d mortar values, %d rigid modes held by the rows), %d "
             "rows, %ld nonzeros in the factor; B's mortar weights completed %s in %.3g s; %.3g s",
             st.n_unknowns, 2 * rows.aux_count, cs.modes, st.rows(), cs.solver.factor_nnz(),
             cs.b_completed_alongside ? "alongside" : "before it", cs.b_completion_seconds, now() - start);
  else
    progress(MC_LOG_PHASE,
             "analysis: sparse interface solver, %d unknowns (%d mortar values, %d rigid modes held by the rows), %d "
             "rows, %ld nonzeros in the factor, %.3g s",
             st.n_unknowns, 2 * rows.aux_count, cs.modes, st.rows(), cs.solver.factor_nnz(), now() - start);
}

// The sparse path's loads F = (f_b, 0) and right-hand sides: a contact row's initial gap
// less what the prescribed values already close; the mortar equations' share of the prescribed
// values; a tangential row's B_t u0 (where its slip starts) less its prescribed part.
// MC_ERROR_SINGULAR if no pushing contact forces can balance the loads of floating bodies.
void Model::sparse_loads(const std::vector<LoadSolve> &loads, std::vector<double> &load, std::vector<double> &target) const {
  const ContactSystem &cs = *contact_;
  const ConstraintRows &rows = cs.rows;
  const SparseContactStructure &st = cs.structure;
  const int q = rows.size(), nrows = st.rows(), k = cs.modes;
  load.assign(st.n_unknowns, 0.0), target.assign(nrows, 0.0);
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const std::vector<int> &dofs = sparse_dofs(b);
    for (size_t i = 0; i < dofs.size(); ++i) load[cs.column_offset[b] + i] = loads[b].lifted[dofs[i]];
  }
  // A row's prescribed part: on the bodies its unknowns hold (not the mortar body of a row with
  // a mortar value: w carries its prescribed values).
  auto less_prescribed = [&](double g, int r, int b_row) {
    const int mortar = cs.groups[cs.row_group[r]].mortar;
    for (int b = 0; b < n_bodies(); ++b) {
      if (b == mortar && rows.aux[r] >= 0) continue;
      for (int p = cs.b_start[b][b_row]; p < cs.b_start[b][b_row + 1]; ++p) {
        const int dof = cs.b_dof[b][p];
        if (fixed_[b][dof]) g -= cs.b_value[b][p] * fixed_value_[b][dof];
      }
    }
    return g;
  };
  for (int r = 0; r < q; ++r) target[r] = less_prescribed(row_initial_gap(r), r, r);
  for (int a = 0; a < rows.aux_count; ++a) {
    const int mortar = cs.groups[cs.aux_group[a]].mortar;
    for (int c = 0; c < 2; ++c) {
      double t = 0;
      for (int p = rows.aux_r_start[a]; p < rows.aux_r_start[a + 1]; ++p) {
        const int dof = dof_of(mortar, rows.aux_r_node[p], c);
        if (dof >= 0 && fixed_[mortar][dof]) t += rows.aux_r[p] * fixed_value_[mortar][dof];
      }
      target[q + 2 * a + c] = t;
    }
  }
  for (size_t j = 0; j < cs.tangent_of.size(); ++j) {
    const int b_row = q + int(j);
    double reference = 0;
    if (history_.valid)
      for (int b = 0; b < n_bodies(); ++b)
        for (int p = cs.b_start[b][b_row]; p < cs.b_start[b][b_row + 1]; ++p)
          reference += cs.b_value[b][p] * history_.u[b][cs.b_dof[b][p]];
    target[cs.tangent_row_offset + int(j)] = less_prescribed(reference, cs.tangent_of[j], b_row);
  }
  // Floating bodies: loads that no pushing contact forces can balance have no solution (with
  // friction the tangential forces may: its iteration says if nothing holds a body).
  if (k > 0 && cs.tangent_of.empty()) {
    DualQp balance;
    balance.q = q, balance.k = k, balance.e = rigid_mode_loads(loads);
    balance.g.resize(size_t(q) * k);
    for (int c = 0; c < k; ++c)
      std::copy_n(cs.g.begin() + size_t(c) * cs.b_rows(), q, balance.g.begin() + size_t(c) * q);
    const double imbalance = load_imbalance(balance);
    if (imbalance > 1e-8)
      fail(MC_ERROR_SINGULAR,
           "the loads cannot be balanced by contact forces (which only push): with free rigid motion (%s) "
           "the best nonnegative contact forces leave %.3g of the load unbalanced; add supports or change the loads",
           free_modes_description().c_str(), imbalance);
  }
}

// Whether the rows set in `holding` (the sparse structure's: contact rows in contact, sticking
// tangential rows) hold the floating bodies: G restricted to them of full rank (judged as the
// condensed path judges it), so that H_P is positive definite.
bool Model::rows_hold_modes(const std::vector<char> &holding) const {
  const ContactSystem &cs = *contact_;
  const int q = cs.rows.size(), qb = cs.b_rows();
  std::vector<int> rows;  // B's rows: q + j for tangential row j
  for (int r = 0; r < q; ++r)
    if (holding[r]) rows.push_back(r);
  for (int j = 0; j < qb - q; ++j)
    if (holding[cs.tangent_row_offset + j]) rows.push_back(q + j);
  return mc::rows_hold_modes(cs.g.data(), qb, cs.modes, rows);
}

// A factorization of the sparse path that failed (MC_ERROR_SINGULAR), named in the body's terms
// where it can be: a host body's equation.
void Model::fail_sparse_singular(const Error &error) const {
  const ContactSystem &cs = *contact_;
  const int failed = cs.solver.failed_unknown();
  for (int b = 0; b < n_bodies() && failed >= 0; ++b) {
    if (!system_[b] || !body[b].host) continue;
    const int local = failed - cs.column_offset[b];
    if (local >= 0 && local < int(sparse_dofs(b).size()))
      fail(MC_ERROR_SINGULAR,
           "body %d: the host's stiffness is not positive definite: the sparse interface solver's factorization "
           "fails at its equation %d (a part of the body moves without resistance, beyond %s, or the matrix is not "
           "a stiffness)",
           b + 1, sparse_dofs(b)[local] + index_base,
           system_[b]->rigid.count > 0 ? "the rigid modes found from the coordinates" : "any rigid mode");
  }
  // Elsewhere the pivot that fails is where the elimination of an indefinite part ends up, which
  // need not be in the body that causes it (contact couples the bodies' unknowns): named as the
  // place it failed, not as the cause.
  for (int b = 0; b < n_bodies() && failed >= 0; ++b) {
    if (!system_[b]) continue;
    const int local = failed - cs.column_offset[b];
    if (local >= 0 && local < int(sparse_dofs(b).size()))
      fail(MC_ERROR_SINGULAR,
           "sparse interface solver: %s; the factorization failed at body %d's unknown %d (every body coupled to it "
           "through contact enters there)",
           error.what(), b + 1, sparse_dofs(b)[local] + index_base);
  }
  fail(MC_ERROR_SINGULAR, "sparse interface solver: %s", error.what());
}

namespace {
// The rigid-motion guess's normal equations square G_S's condition: 1e-10 keeps 5 digits of
// G_S's own; below it no guess is taken out (x_0 = 0).
constexpr double kShiftConditioning = 1e-10;
}  // namespace

// The floating bodies' rigid motion taken out of the sparse unknowns before the solve: x =
// x_0 + y with x_0 = R alpha_0 on their blocks (alpha_0 the least-squares fit of G alpha to the
// right-hand sides of the rows `near`, or of every contact row if those do not hold the modes),
// and the rows' right-hand sides less C x_0. H x_0 is taken as 0 (K R = 0), as the condensed
// path's u = K^+ f + R alpha does. y is then of the size of the deformation and the gaps left,
// not of a floating body's travel: with x holding the travel (a disc 1000 cells above its
// block, test_contact_hard) its round-off eps |x| had left 1.1e-10 of the load unbalanced.
// Returns alpha_0 (empty if there are no floating bodies). The fit's normal equations are
// solved when their reciprocal condition is above kShiftConditioning.
std::vector<double> Model::sparse_rigid_shift(const std::vector<char> &near, std::vector<double> &target) const {
  const ContactSystem &cs = *contact_;
  const SparseContactStructure &st = cs.structure;
  const int q = cs.rows.size(), qb = cs.b_rows(), k = cs.modes;
  if (k == 0) return {};
  // 1. alpha_0: the normal equations G_S^T G_S alpha = G_S^T t_S over B's rows in S (a normal
  //    row r < q, a tangential row q + j: friction's rows hold modes too, a shaft's rotation),
  //    solved only if well conditioned: a mode the rows hold by round-off (a rotation of a
  //    round shaft against its normal rows) would be fitted to round-off.
  auto fit = [&](const std::vector<char> &rows, std::vector<double> &alpha) {
    std::vector<double> normal(size_t(k) * k, 0.0);
    alpha.assign(k, 0.0);
    for (int b_row = 0; b_row < qb; ++b_row) {
      const int row = b_row < q ? b_row : cs.tangent_row_offset + (b_row - q);  // the structure's
      if (!rows.empty() && !rows[row]) continue;
      for (int c = 0; c < k; ++c) {
        const double gc = cs.g[size_t(c) * qb + b_row];
        if (gc == 0) continue;
        alpha[c] += gc * target[row];
        for (int d = 0; d < k; ++d) normal[size_t(d) * k + c] += gc * cs.g[size_t(d) * qb + b_row];
      }
    }
    DenseLu lu;
    if (!lu.factorize(k, std::move(normal), kShiftConditioning) || !lu.solve(alpha.data())) return false;
    for (double a : alpha)
      if (!std::isfinite(a)) return false;
    return true;
  };
  std::vector<double> alpha;
  const bool held = (!near.empty() && fit(near, alpha)) || fit({}, alpha);
  if (!held) return std::vector<double>(size_t(k), 0.0);  // (the iteration then says what does not hold)
  // 2. x_0 on the floating bodies' blocks, and the right-hand sides less C x_0.
  std::vector<double> shift(size_t(st.n_unknowns), 0.0);
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b] || system_[b]->rigid.count == 0) continue;
    std::vector<double> motion(system_[b]->stiffness.n, 0.0);
    add_rigid_motion(b, alpha, motion);
    const std::vector<int> &dofs = sparse_dofs(b);
    for (size_t i = 0; i < dofs.size(); ++i) shift[cs.column_offset[b] + i] = motion[dofs[i]];
  }
  for (int r = 0; r < st.rows(); ++r) target[r] -= cs.solver.row_times(r, shift);
  return alpha;
}

const std::vector<int> &Model::sparse_index(int b) const {
  const ContactSystem &cs = *contact_;
  return system_[b]->rigid.count > 0 ? cs.floating[b].index : system_[b]->solve_index;
}

const std::vector<int> &Model::sparse_dofs(int b) const {
  const ContactSystem &cs = *contact_;
  return system_[b]->rigid.count > 0 ? cs.floating[b].dofs : system_[b]->solve_dofs;
}

// A floating body's rigid-mode amplitudes in the sparse answer: those that carry its pins'
// values (R restricted to the pins, k x k, is regular: the pins are chosen for that,
// rigid_modes.cpp), so that u - R alpha vanishes at the pins as K^+'s answers do.
std::vector<double> Model::sparse_rigid_amplitudes(const std::vector<double> &x) const {
  const ContactSystem &cs = *contact_;
  std::vector<double> alpha(size_t(cs.modes), 0.0);
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b] || system_[b]->rigid.count == 0) continue;
    const RigidModes &rm = system_[b]->rigid;
    const int k = rm.count, ndof = system_[b]->stiffness.n, offset = mode_offset(b);
    std::vector<double> a(size_t(k) * k), rhs(k);
    for (int i = 0; i < k; ++i) {
      const int pin = rm.pinned_dofs[size_t(i)];
      for (int c = 0; c < k; ++c) a[size_t(c) * k + i] = rm.modes[size_t(c) * ndof + pin];
      const int column = cs.floating[b].index[pin];
      rhs[i] = column >= 0 ? x[cs.column_offset[b] + column] : 0.0;
    }
    int n = k, one = 1, info = 0;
    std::vector<int> pivots(k);
    dgesv_(&n, &one, a.data(), &n, pivots.data(), rhs.data(), &n, &info);
    if (info != 0) fail(MC_ERROR_INTERNAL, "body %d: the rigid modes at the pins are singular", b + 1);
    for (int c = 0; c < k; ++c) alpha[size_t(offset + c)] = rhs[c];
  }
  return alpha;
}

void Model::sparse_displacements(const std::vector<double> &x, const std::vector<double> &alpha_0,
                                 std::vector<LoadSolve> &loads, std::vector<double> &alpha) const {
  const ContactSystem &cs = *contact_;
  alpha = sparse_rigid_amplitudes(x);
  for (int b = 0; b < n_bodies(); ++b) {
    if (!system_[b]) continue;
    const BodySystem &sys = *system_[b];
    const std::vector<int> &dofs = sparse_dofs(b);
    std::vector<double> &v = loads[b].v;
    v.assign(sys.stiffness.n, 0.0);
    for (size_t i = 0; i < dofs.size(); ++i) v[dofs[i]] = x[cs.column_offset[b] + i];
    if (sys.rigid.count == 0) continue;
    // v = u - R alpha (the rigid modes vanish at prescribed components), exactly 0 at the pins.
    std::vector<double> rigid_motion(sys.stiffness.n, 0.0);
    add_rigid_motion(b, alpha, rigid_motion);
    for (int i = 0; i < sys.stiffness.n; ++i) v[i] -= rigid_motion[i];
    for (int pin : sys.rigid.pinned_dofs) v[pin] = 0;
  }
  for (size_t c = 0; c < alpha_0.size(); ++c) alpha[c] += alpha_0[c];
}

bool Model::solve_sparse(std::vector<LoadSolve> &loads, std::vector<double> &lambda, std::vector<double> &alpha) {
  ContactSystem &cs = *contact_;
  const ConstraintRows &rows = cs.rows;
  const SparseContactStructure &st = cs.structure;
  const int q = rows.size(), nrows = st.rows();
  Stopwatch watch(infos.t_contact);
  const double start = now();
  // 1. Loads, the rows' right-hand sides, and whether contact can balance the loads.
  std::vector<double> load, target;
  sparse_loads(loads, load, target);
  // 3. The active-set iteration. An active set must hold the floating bodies (G_A of full rank,
  //    judged as the condensed path judges it) before H_P is factorized.
  auto hold_modes = [&](const std::vector<char> &active) { return rows_hold_modes(active); };
  std::vector<char> start_set;
  if (int(cs.last_active.size()) == q) start_set.assign(nrows, 1), std::copy(cs.last_active.begin(), cs.last_active.end(), start_set.begin());
  // 2. The floating bodies' rigid motion guessed and taken out (sparse_rigid_shift).
  const std::vector<double> initial_gap(target);  // (for the start's choice of rows)
  const std::vector<double> alpha_0 = sparse_rigid_shift(start_set, target);
  const DualQpObserver observe = iteration_log(q);
  SparseContactResult result;
  cs.solver.set_threads(threads_);  // its solves split over two threads where the bodies' work is
  try {
    result = cs.solver.solve(load, target, start_set, options.tolerance, options.iteration_limit(q), hold_modes, observe,
                             initial_gap);
  } catch (const Error &error) {
    if (error.status() != MC_ERROR_SINGULAR) throw;
    fail_sparse_singular(error);
  }
  infos.iterations = result.iterations;
  infos.factorizations += result.factorizations;
  infos.t_factor += result.t_factor;
  infos.t_solve += result.t_solve;
  infos.factor_nnz += cs.solver.factor_nnz();
  progress(MC_LOG_PHASE,
           "active-set solve (sparse): %s, %d iterations, %d factorizations, %d factor updates, %d conjugate-gradient "
           "steps, residual %.3g, %.3g s (factorizations and updates %.3g s, solves %.3g s; %d of the updates "
           "modified the factor in place, %d of them by computing its rows on the changed paths afresh)%s",
           result.outcome == SparseContactOutcome::solved ? "solved" : "not converged", result.iterations,
           result.factorizations, result.updates + result.modifications, result.cg_steps, result.violation,
           now() - start, result.t_factor, result.t_solve, result.modifications, result.path_refactorizations,
           split_solves_note(cs.solver.split_top_share(), threads_, cs.solver.split_factorizations()).c_str());
  if (result.outcome == SparseContactOutcome::modes_not_held) {
    const std::string unheld = unheld_modes_description();
    fail(MC_ERROR_SINGULAR,
         "contact cannot hold the free rigid motion (%s): the contact normals do not restrain it; add supports",
         (unheld.empty() ? free_modes_description() : unheld).c_str());
  }
  if (result.outcome == SparseContactOutcome::not_converged && result.cycled) return false;
  if (result.outcome == SparseContactOutcome::not_converged)
    fail(MC_ERROR_NOT_CONVERGED,
         "the active-set iteration of the sparse interface solver stopped after %d iterations (limit %d) with a "
         "relative complementarity violation of %.3g (tolerance %.3g)",
         result.iterations, options.iteration_limit(q), result.violation, options.tolerance);
  // 4. The answer in the model's terms (with a partial B, also w and its equations' multipliers).
  lambda.assign(result.lambda.begin(), result.lambda.begin() + q);
  if (cs.b_partial) {
    const int values = 2 * rows.aux_count;
    cs.aux_values.assign(result.x.begin() + cs.aux_offset, result.x.begin() + cs.aux_offset + values);
    cs.aux_multipliers.assign(result.lambda.begin() + q, result.lambda.begin() + q + values);
  }
  sparse_displacements(result.x, alpha_0, loads, alpha);
  infos.complementarity = result.violation;
  // The next solve starts from the set this one ended on, which is the factorized one: a
  // re-solve whose active set does not change factorizes nothing.
  cs.last_active.assign(result.active.begin(), result.active.begin() + q);
  for (int r = 0; r < q; ++r) infos.active += lambda[r] > 0;
  infos.contact_rows = q;
  return true;
}

}  // namespace mc
