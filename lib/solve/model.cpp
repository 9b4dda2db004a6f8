#include "solve/model.hpp"
#include "bodies/cell_shapes.hpp"
#include "support/blas_threads.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include "support/stopwatch.hpp"
#include <cmath>
#include <exception>
#include <functional>
#include <pthread.h>
#include <sched.h>
#include <system_error>
#include <thread>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace mc {

namespace {



double dot(const std::vector<double> &a, const std::vector<double> &b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// The cores this process may run on (its affinity mask, which is also how OpenBLAS sizes its pool).
int available_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return CPU_COUNT(&set);
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  return online > 0 ? int(online) : 1;
}

void keep_line(void *work, mc_log_level level, const char *line) {
  static_cast<BodyWork *>(work)->lines.emplace_back(level, line);
}

void add_body_infos(Infos &to, const Infos &from) {
  to.dofs += from.dofs, to.factor_nnz += from.factor_nnz, to.factorizations += from.factorizations;
  to.t_assembly += from.t_assembly, to.t_analysis += from.t_analysis, to.t_factor += from.t_factor;
  to.t_solve += from.t_solve, to.t_contact += from.t_contact;
}

}  // namespace

double axis_tolerance(const Mesh &mesh) { return 1e-12 * mesh.characteristic_length(); }

int first_node_left_of_axis(const Mesh &mesh) {
  for (int i = 0; i < mesh.n_nodes(); ++i)
    if (mesh.node(i).x < -axis_tolerance(mesh)) return i;
  return -1;
}

int Model::dof_count(int b) const {
  return body[b].host ? body[b].host_data.n_equations : 2 * body[b].mesh.n_nodes();
}

int Model::dof_of(int b, int node, int component) const {
  return body[b].host ? body[b].host_data.equation(node, component) : 2 * node + component;
}

std::vector<double> Model::nodal_displacement(int b) const {
  if (!body[b].host) return body[b].u;
  std::vector<double> u(2 * size_t(body[b].mesh.n_nodes()), 0.0);
  for (int i = 0; i < body[b].mesh.n_nodes(); ++i)
    for (int c = 0; c < 2; ++c) {
      const int dof = dof_of(b, i, c);
      if (dof >= 0) u[2 * size_t(i) + c] = body[b].u[dof];
    }
  return u;
}

// A body of revolution: a node on the axis stays there (u_r = 0), whatever its loads, or its
// meridian would tear open along the axis. The host's value of a prescribed u_r there is
// overridden by 0.
void Model::effective_supports() {
  fixed_.resize(body.size()), fixed_value_.resize(body.size());
  for (int b = 0; b < n_bodies(); ++b) {
    fixed_[b] = body[b].prescribed;
    fixed_value_[b] = body[b].prescribed_value;
    if (!axisymmetric || !body[b].has_mesh || body[b].host) continue;  // a host restrains its own axis
    const Mesh &mesh = body[b].mesh;
    for (int i = 0; i < mesh.n_nodes(); ++i)
      if (std::fabs(mesh.node(i).x) <= axis_tolerance(mesh)) fixed_[b][2 * i] = 1, fixed_value_[b][2 * i] = 0;
  }
}

// With more than two bodies the odd ones go to the second thread (for_each_body); the smallest
// body decides, as between two.
int Model::body_threads() const {
  long smaller = -1;
  int meshed = 0;
  for (int b = 0; b < n_bodies(); ++b)
    if (body[b].has_mesh) ++meshed, smaller = smaller < 0 ? dof_count(b) : std::min<long>(smaller, dof_count(b));
  if (meshed < 2 || options.threads == 1) return 1;
  if (options.threads >= 2) return 2;  // asked for: at most that many, and two bodies use two
  return available_cores() >= 2 && smaller >= kParallelMinBodyDofs ? 2 : 1;
}

bool Model::contact_active() const {
  for (const ContactPair &p : pairs)
    if (p.complete()) return true;
  return false;
}

bool Model::in_contact(int b) const {
  for (const ContactPair &p : pairs)
    if (p.complete() && (p.nonmortar == b || p.mortar == b)) return true;
  return false;
}

void Model::run_bodies(int threads, const std::function<void(int, BodyWork &)> &task, Infos &add_to) const {
  const int n = n_bodies();
  std::vector<BodyWork> work(n);
  std::vector<std::exception_ptr> error(n);
  // With two body threads, each one's BLAS calls get its share of the cores (blas_threads.hpp):
  // one thread with OpenBLAS's pthread build (the count solve() lowered for the whole solve),
  // half the cores with the OpenMP build (each body thread's own setting, here).
  const bool parallel = threads > 1;
  const int blas_per_body = parallel ? std::max(1, available_cores() / 2) : 0;
  auto run = [&](int b) {
    try {
      BlasThreadsOfThisThread blas_share(blas_per_body);
      task(b, work[b]);
    } catch (...) {
      error[b] = std::current_exception();
    }
  };
  if (threads > 1) {
    // The odd bodies (body 2, 4, ...) on a thread of their own, the even ones on the calling
    // thread. The host's log callback is only ever called from the calling thread: each body
    // keeps its messages, sent on below.
    for (BodyWork &w : work)
      if (progress.enabled()) w.log = ProgressLog{&keep_line, &w};
    auto run_every_other = [&](int first) {
      for (int b = first; b < n; b += 2) run(b);
    };
    std::thread other;
    try {
      other = std::thread(run_every_other, 1);
      // A name a host (and test_model_threads) can see in /proc/self/task/*/comm.
      pthread_setname_np(other.native_handle(), "mc-body2");
    } catch (const std::system_error &) {  // no thread to be had: the odd bodies after the even
    }
    run_every_other(0);
    if (other.joinable()) other.join();
    else run_every_other(1);
  } else {
    for (int b = 0; b < n; ++b) {
      bool failed = false;
      for (int a = 0; a < b; ++a) failed = failed || error[a];
      if (failed) break;
      work[b].log = progress, run(b);
    }
  }
  // What a serial solve would have shown: body 1's messages, its error if any, then body 2's...
  for (int b = 0; b < n; ++b) {
    for (const auto &line : work[b].lines) progress(line.first, "%s", line.second.c_str());
    add_body_infos(add_to, work[b].infos);
    if (error[b]) std::rethrow_exception(error[b]);
  }
}

// The contact geometry, then everything one body needs up to the interface problem in one
// phase per body: stiffness, ordering, factorization, its block of S and, through `then`, its
// load solve. One phase, not one per step, so that a body finishing a step early goes on with
// its next one instead of waiting for the other body (docs/benchmarks.md, "Threads").
void Model::build_structure(const std::function<void(int, BodyWork &)> &then) {
  contact_.reset();
  system_.clear();
  system_.resize(body.size());
  // The sparse path reads the mortar values w_a, not B's mortar weights, and the automatic choice
  // reads neither: B is built without them, and completed only for friction (while the sparse
  // path's ordering runs, build_sparse_structure) or before the bodies are analysed for the
  // condensed path (choose_interface_solver, build_condensed). Forced condensed, B is built whole.
  if (contact_active()) {
    Stopwatch watch(infos.t_contact);
    contact_ = build_contact_system(options.interface_solver != MC_INTERFACE_CONDENSED);
  }

  // Each body's factorization and, with contact, its share of S = sum_b s_b. The sum is formed
  // the same way whatever the thread count, so that the results do not depend on it.
  // The sparse path when it is forced; the condensed path's analyses when it is forced. The
  // automatic choice first bounds each body's factorization by its envelope (a few breadth-first
  // searches): where the interface is long that settles it, and the analyses for the condensed
  // path (a constrained ordering and a symbolic factorization per body, up to 15 % of a solve on
  // the strips) are not made; otherwise it analyses the bodies and reads those analyses
  // (choose_interface_solver).
  const bool forced_sparse = contact_ && options.interface_solver == MC_INTERFACE_SPARSE;
  const bool automatic = contact_ && options.interface_solver == MC_INTERFACE_AUTO;
  for_each_body([&](int b, BodyWork &work) {
    system_[b] = assemble_body(b, work);
    reduce_body(b, work);
    if (automatic) {
      Stopwatch watch(work.infos.t_analysis);
      if (system_[b]) system_[b]->envelope = envelope_cholesky_bound(system_[b]->reduced);
    } else if (!forced_sparse) {
      analyze_body(b, work, options.interface_solver == MC_INTERFACE_CONDENSED);
    }
  });
  if (contact_)
    contact_->sparse = forced_sparse || choose_interface_solver([&] {
                         if (automatic) for_each_body([&](int b, BodyWork &work) { analyze_body(b, work, false); });
                       });
  if (contact_ && contact_->sparse) {
    for (auto &sys : system_)
      if (sys) sys->cholesky.release();  // the condensed path's analyses, read by the choice
#ifdef __GLIBC__
    malloc_trim(0);  // and their pages back to the system before the larger factor is allocated
#endif
    build_sparse_structure();
    for_each_body(then);
    built_version_ = structure_version_;
    return;
  }
  build_condensed(then);
  built_version_ = structure_version_;
}

int Model::position_node(size_t pos) const {
  const ContactGroup &group = contact_->group_of_position(int(pos));
  return group.geometry.nodes[pos - group.first_position];
}

double Model::initial_gap(size_t pos) const {
  const ContactGroup &group = contact_->group_of_position(int(pos));
  const size_t local = pos - group.first_position;
  const double g0 = group.geometry.gap0[local];
  return group.gap_offset.empty() ? g0 : g0 + group.gap_offset[group.geometry.nodes[local]];
}

double Model::row_initial_gap(int r) const {
  const ConstraintRows &rows = contact_->rows;
  const ContactGroup &group = contact_->groups[contact_->row_group[r]];
  double g = rows.gap0[r];
  if (!group.gap_offset.empty())  // the host's offsets, interpolated like u1 at a trace point inside a segment
    for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p) g += rows.weight1[p] * group.gap_offset[position_node(rows.position1[p])];
  return g;
}

// Row r's gap g_r - B_r u with the bodies' current displacements (body[b].u). With a partial B
// a row with a mortar value has B_r's mortar part -n . w_a, w_a the last sparse solve's.
double Model::row_gap(int r) const {
  const ContactSystem &cs = *contact_;
  double gap = row_initial_gap(r);
  for (int b = 0; b < n_bodies(); ++b)
    for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) gap -= cs.b_value[b][p] * body[b].u[cs.b_dof[b][p]];
  if (cs.b_partial && r < cs.rows.size() && cs.rows.aux[r] >= 0) {
    const size_t a = size_t(cs.rows.aux[r]);
    gap += cs.rows.normal[r].x * cs.aux_values[2 * a] + cs.rows.normal[r].y * cs.aux_values[2 * a + 1];
  }
  return gap;
}

// The contact forces -B^T lambda on body b's DOFs (K u = f + contact_force), added to `force`.
// With a partial B, the rows with a mortar value act on their mortar body through their mortar
// equations: R^T mu (ContactSystem::aux_multipliers).
void Model::add_contact_force(int b, const std::vector<double> &lambda, std::vector<double> &force) const {
  const ContactSystem &cs = *contact_;
  for (int r = 0; r < cs.b_rows(); ++r)  // normal rows, then friction's tangential ones
    for (int p = cs.b_start[b][r]; p < cs.b_start[b][r + 1]; ++p) force[cs.b_dof[b][p]] -= cs.b_value[b][p] * lambda[r];
  if (!cs.b_partial) return;
  const ConstraintRows &rows = cs.rows;
  for (int a = 0; a < rows.aux_count; ++a) {
    if (cs.groups[cs.aux_group[a]].mortar != b) continue;
    for (int p = rows.aux_r_start[a]; p < rows.aux_r_start[a + 1]; ++p)
      for (int c = 0; c < 2; ++c) {
        const int dof = dof_of(b, rows.aux_r_node[p], c);
        if (dof >= 0) force[dof] += rows.aux_r[p] * cs.aux_multipliers[2 * size_t(a) + c];
      }
  }
}

// The gap at contact position pos itself, g0 - (u1 - u2(y)) . n with y its projection on the
// group's mortar body.
double Model::pointwise_gap(size_t pos) const {
  const ContactGroup &group = contact_->group_of_position(int(pos));
  const ContactGeometry &g = group.geometry;
  const size_t local = pos - group.first_position;
  const CurveSegment &c = g.mortar.segments()[g.projection[local].segment];
  double shape[3], ds[3];
  line_shapes(c.quadratic() ? 3 : 2, g.projection[local].eta, shape, ds);
  const int node2[3] = {c.a, c.b, c.mid}, node1 = g.nodes[local];
  auto u = [&](int b, int node, int component) {
    const int dof = dof_of(b, node, component);
    return dof >= 0 ? body[b].u[dof] : 0.0;
  };
  double ux = u(group.nonmortar, node1, 0), uy = u(group.nonmortar, node1, 1);
  for (int a = 0; a < (c.quadratic() ? 3 : 2); ++a)
    ux -= shape[a] * u(group.mortar, node2[a], 0), uy -= shape[a] * u(group.mortar, node2[a], 1);
  return initial_gap(pos) - (ux * g.normals[local].x + uy * g.normals[local].y);
}

int Model::mode_offset(int b) const {
  int offset = 0;
  for (int a = 0; a < b; ++a)
    if (system_[a]) offset += system_[a]->rigid.count;
  return offset;
}

// u += R alpha for body b (its rigid modes' share of alpha; nothing for a held body).
void Model::add_rigid_motion(int b, const std::vector<double> &alpha, std::vector<double> &u) const {
  const RigidModes &rm = system_[b]->rigid;
  const int ndof = system_[b]->stiffness.n, offset = mode_offset(b);
  for (int c = 0; c < rm.count; ++c)
    for (int i = 0; i < ndof; ++i) u[i] += alpha[offset + c] * rm.modes[size_t(c) * ndof + i];
}

// MC_INFO_GAP_RESIDUAL: the complementarity of the gaps of the displacements returned, not of
// the condensed problem's (MC_INFO_COMPLEMENTARITY). The two agree unless the condensation lost
// accuracy: its right-hand side d = B K^+ f - g0 can be far larger than the gaps it yields (a
// slender body factorized alone is as compliant as a free beam), and the gaps of the recovered
// u then carry round-off of d's size (docs/robustness.md, "Known limitations"). A row's gap is a
// weighted mean (the mortar weights); divided by the sum of its body-1 weights it is a length,
// here relative to the largest displacement or initial gap, the size its round-off scales with.
double Model::recovered_gap_residual(const std::vector<double> &lambda) const {
  const ConstraintRows &rows = contact_->rows;
  double worst = 0, scale = 0;
  for (int b = 0; b < n_bodies(); ++b)
    for (double u : body[b].u) scale = std::max(scale, std::fabs(u));
  for (int r = 0; r < rows.size(); ++r) {
    double weight = 0;
    for (int p = rows.start1[r]; p < rows.start1[r + 1]; ++p) weight += std::fabs(rows.weight1[p]);
    if (weight == 0) continue;
    scale = std::max(scale, std::fabs(row_initial_gap(r)) / weight);
    const double gap = row_gap(r);
    // Active rows must close (gap 0), inactive ones must not penetrate (gap >= 0).
    worst = std::max(worst, (lambda[r] > 0 ? std::fabs(gap) : std::max(0.0, -gap)) / weight);
  }
  return scale > 0 ? worst / scale : worst;
}

// One body's loads with the prescribed displacements lifted, f_eff = f - K u_prescribed, and
// their first solve.
void Model::solve_loads(int b, BodyWork &work, LoadSolve &out) const {
  if (!system_[b]) return;
  const double start = now();
  BodySystem &sys = *system_[b];
  {
    Stopwatch watch(work.infos.t_assembly);
    out.f = load_vector(b);
    std::vector<double> up(sys.stiffness.n, 0.0), kup(sys.stiffness.n, 0.0);
    bool any_prescribed_motion = false;  // supports at rest (the usual case) lift nothing
    for (int i = 0; i < sys.stiffness.n; ++i)
      if (fixed_[b][i] && fixed_value_[b][i] != 0) up[i] = fixed_value_[b][i], any_prescribed_motion = true;
    if (any_prescribed_motion) sys.stiffness.multiply(up.data(), kup.data());
    out.lifted.resize(sys.stiffness.n);
    for (int i = 0; i < sys.stiffness.n; ++i) out.lifted[i] = fixed_[b][i] ? 0 : out.f[i] - kup[i];
  }
  // Without contact v = K^+ f_eff; with contact only its first half y = L^-1 P f_eff, which
  // is all the interface problem needs (B v = W^T y_G); the recovery finishes the solve.
  std::vector<double> x(sys.solve_dofs.size());
  for (size_t k = 0; k < x.size(); ++k) x[k] = out.lifted[sys.solve_dofs[k]];
  {
    Stopwatch watch(work.infos.t_solve);
    if (contact_ && contact_->sparse) {
      // the sparse path solves the loads with the contact problem (solve_sparse)
    } else if (contact_) {
      out.y.resize(x.size());
      sys.cholesky.forward(x.data(), out.y.data());
    } else {
      sys.cholesky.solve(x.data());
    }
  }
  out.v.assign(sys.stiffness.n, 0.0);
  if (!contact_)
    for (size_t k = 0; k < x.size(); ++k) out.v[sys.solve_dofs[k]] = x[k];
  work.infos.dofs += long(sys.solve_dofs.size() + sys.rigid.pinned_dofs.size());
  if (!contact_ || !contact_->sparse) work.infos.factor_nnz += sys.cholesky.factor_nnz();  // (sparse: solve_sparse)
  out.seconds = now() - start;
}

void Model::solve() {
  const double start = now();
  infos = Infos{};
  solved = false;
  derived_.reset(body.size());  // the previous solve's stresses and estimate
  bool any_mesh = false;
  for (const Body &b : body) any_mesh = any_mesh || b.has_mesh;
  if (!any_mesh) fail(MC_ERROR_STATE, "no mesh: call mc_set_mesh first");
  for (int b = 0; b < n_bodies(); ++b) {
    // Two bodies: one may be left out (a single body's elasticity). An assembly's every body
    // is part of the scene.
    if (!body[b].has_mesh && n_bodies() > 2)
      fail(MC_ERROR_STATE, "body %d has no mesh: call mc_set_mesh or mc_set_host_body (the model has %d bodies, "
           "mc_set_body_count)", b + 1, n_bodies());
    if (body[b].host && body[b].host_data.entry_value.empty())
      fail(MC_ERROR_STATE, "body %d is a host body without stiffness: call mc_add_stiffness or mc_add_element_matrices",
           b + 1);
    if (body[b].has_mesh && !body[b].host && !body[b].has_material)
      fail(MC_ERROR_STATE, "body %d has no material: call mc_set_material or mc_set_cell_elasticity", b + 1);
    // Checked here, before any work, so that this error comes first whatever else is wrong
    // (the contact geometry is built before the bodies are assembled).
    if (body[b].has_mesh && axisymmetric && !body[b].cell_elasticity.empty())
      fail(MC_ERROR_MATERIAL,
           "body %d: mc_set_cell_elasticity gives the in-plane law only, and an axisymmetric model also needs "
           "its hoop terms: use mc_set_material, or a plane model",
           b + 1);
  }
  check_contact_pairs();
  const bool rebuild = built_version_ != structure_version_;
  threads_ = body_threads();
  infos.threads = threads_;
  // With two body threads, OpenBLAS's pthread build runs one thread per call for the whole
  // solve (from before its first log message), not only while both bodies run: its threaded
  // level-3 calls take turns on one process-wide lock (two bodies asking for more would wait
  // on each other), and a call between the phases (the active-set solve's) would wake its
  // worker, which then spins for a while after the call, into the next phase, on a core a body
  // thread needs (measured: the re-solve's recovery at 5*10^5 DOFs took 0.06 or 0.10 s,
  // depending on it; docs/benchmarks.md, "Threads").
  BlasPoolShare pool_share(threads_ > 1 ? 1 : 0);
  progress(MC_LOG_PHASE, "solve: start, %s%s",
           rebuild ? "assembling and factorizing" : "reusing the factorizations and the interface operator",
           threads_ > 1 ? " (the two bodies at once, on 2 threads)" : "");
  effective_supports();
  // Each body's loads and their first solve: in the phase that factorizes it when the structure
  // is rebuilt, on their own otherwise.
  std::vector<LoadSolve> loads(body.size());
  auto load_step = [&](int b, BodyWork &work) { solve_loads(b, work, loads[b]); };
  if (rebuild) {
    built_version_ = 0;
    build_structure(load_step);
  } else {
    for_each_body(load_step);
  }
  if (contact_) merge_gap_offsets();  // values: offsets set since the last solve count
  double t_loads = 0;
  for (const LoadSolve &l : loads) t_loads += l.seconds;
  progress(MC_LOG_PHASE, "loads: load vectors and %s, %.3g s", contact_ ? "forward solves y = L^-1 P f" : "solves v = K^-1 f",
           t_loads);
  std::vector<double> lambda;
  std::vector<double> alpha;
  DualQp qp;  // kept for the refinement (its S and G)
  // displacements_known: loads[b].v already holds K^+ (f_eff - B^T lambda) (the sparse path, or
  // after a refinement).
  bool displacements_known = false;
  // u = K^+ (f_eff - B^T lambda) + R alpha, then the prescribed values.
  const double t_recovery = now();
  std::vector<double> f_norm2(body.size(), 0.0), residual_norm2(body.size(), 0.0), energy(body.size(), 0.0);
  auto recover = [&](int b, BodyWork &work) {
    if (!system_[b]) return;
    BodySystem &sys = *system_[b];
    const int ndof = sys.stiffness.n;
    std::vector<double> contact_force(ndof, 0.0), rigid_motion(ndof, 0.0);  // rigid_motion: R alpha
    if (contact_) {
      add_contact_force(b, lambda, contact_force);
      add_rigid_motion(b, alpha, rigid_motion);
    }
    if (contact_ && !displacements_known) {
      // u = K^+ (f_eff - B^T lambda) = P^T L^-T (y - [0; W lambda]): the backward half only.
      std::vector<double> x(sys.solve_dofs.size()), z(loads[b].y);
      const std::vector<int> &columns = contact_->body_rows[b];
      const int ng = contact_->w_rows[b], qb = int(columns.size());
      if (ng > 0 && qb > 0) {
        int one = 1;
        double minus = -1.0, plus = 1.0;
        double *z_interface = z.data() + sys.cholesky.interface_start();
        std::vector<double> lambda_b(qb);  // lambda on the rows touching b (W_b's columns)
        for (int k = 0; k < qb; ++k) lambda_b[k] = lambda[columns[k]];
        dgemv_("N", &ng, &qb, &minus, contact_->w[b].data(), &ng, lambda_b.data(), &one, &plus, z_interface, &one);
      }
      {
        Stopwatch watch(work.infos.t_solve);
        sys.cholesky.backward(z.data(), x.data());
      }
      std::fill(loads[b].v.begin(), loads[b].v.end(), 0.0);
      for (size_t k = 0; k < x.size(); ++k) loads[b].v[sys.solve_dofs[k]] = x[k];
    }
    Body &body_ = body[b];
    // Reactions, energy and the equilibrium residual from the full stiffness. K R = 0, so K is
    // applied to u without R alpha: a floating body that travels far compared with its
    // deformation (a large initial gap) would otherwise leave round-off eps |K| |R alpha| in all
    // three. (The rigid modes vanish at prescribed components.)
    std::vector<double> elastic(loads[b].v);
    for (int i = 0; i < ndof; ++i) if (fixed_[b][i]) elastic[i] = fixed_value_[b][i];
    body_.u = elastic;
    for (int i = 0; i < ndof; ++i) body_.u[i] += rigid_motion[i];
    std::vector<double> ku(ndof);
    sys.stiffness.multiply(elastic.data(), ku.data());
    body_.reaction.assign(ndof, 0.0);
    for (int i = 0; i < ndof; ++i) {
      double r = ku[i] - loads[b].f[i] - contact_force[i];
      if (fixed_[b][i]) body_.reaction[i] = r;
      // Relative to the load of the reduced problem, f - K u_prescribed: a body moved only by
      // prescribed displacements has f = 0, and its residual is then measured against the forces
      // those displacements cause, not in absolute units.
      else residual_norm2[b] += r * r, f_norm2[b] += loads[b].lifted[i] * loads[b].lifted[i] + contact_force[i] * contact_force[i];
    }
    energy[b] = 0.5 * dot(elastic, ku);
    body_.contact_load = contact_force;
    if (options.eager_results && !body_.host) compute_stresses(b);  // else when asked for
  };
  // Friction: the solve is a step from the last converged state (a rebuilt structure starts from
  // the unloaded one), in MC_OPTION_LOAD_STEPS increments of the loads and prescribed values;
  // each increment reuses the factorizations (friction.cpp).
  const bool friction = contact_ && !contact_->tangent_of.empty();
  if (rebuild) reset_history();
  std::vector<std::vector<double>> solve_start;  // the displacements the solve starts from (empty: zero)
  std::vector<LoadSolve> target, step_start;
  std::vector<std::vector<double>> target_prescribed;
  if (friction) {
    refresh_friction();
    prepare_history();
    solve_start = history_.u, target = loads, target_prescribed = fixed_value_;
  }
  const int steps = friction ? options.load_steps : 1;
  for (int step = 1; step <= steps; ++step) {
    if (friction) {
      step_loads(step, steps, target, target_prescribed, step_start, loads);
      if (steps > 1) progress(MC_LOG_PHASE, "load step %d of %d", step, steps);
    }
    displacements_known = false;
    if (contact_ && contact_->sparse && friction) {
      solve_sparse_friction(loads, lambda, alpha);
      displacements_known = true;
    } else if (contact_ && contact_->sparse) {
      // The sparse path, or (if its active-set iteration cycles) the condensed one, whose QP
      // solver has a fallback for that (fall_back_to_condensed).
      if (solve_sparse(loads, lambda, alpha)) displacements_known = true;
      else fall_back_to_condensed(loads);
    }
    if (contact_ && !contact_->sparse) solve_condensed(loads, qp, lambda, alpha);
    if (contact_) infos.interface_solver = contact_->sparse ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED;
    std::fill(f_norm2.begin(), f_norm2.end(), 0.0), std::fill(residual_norm2.begin(), residual_norm2.end(), 0.0);
    for_each_body(recover);
    if (contact_) {
      infos.gap_residual = recovered_gap_residual(lambda);
      // (The refinement works on the normal rows' active set: not with friction's rows.)
      if (!friction && !contact_->sparse && infos.gap_residual > kRefineAboveGapResidual &&
          refine_solution(qp, loads, lambda, alpha)) {
        displacements_known = true;
        std::fill(f_norm2.begin(), f_norm2.end(), 0.0), std::fill(residual_norm2.begin(), residual_norm2.end(), 0.0);
        for_each_body(recover);  // reactions, energy and stresses of the refined displacements
      }
    }
    if (friction) record_step(loads);
  }
  // Per-body sums added in body order, whatever the thread count.
  double residual_norm = 0, f_norm = 0;
  infos.energy = 0;
  for (int b = 0; b < n_bodies(); ++b) residual_norm += residual_norm2[b], f_norm += f_norm2[b], infos.energy += energy[b];
  infos.equilibrium = std::sqrt(residual_norm) / std::max(std::sqrt(f_norm), 1e-300);
  if (f_norm == 0) infos.equilibrium = std::sqrt(residual_norm);

  contact_results(lambda);
  if (contact_) friction_results(lambda, solve_start);
  progress(MC_LOG_PHASE, "recovery: displacements, reactions%s and contact results, %.3g s",
           options.eager_results ? ", stresses" : "", now() - t_recovery);
  // The error estimate now (MC_OPTION_EAGER_RESULTS), or when a getter first asks for it.
  if (options.eager_results) ensure_estimate();
  infos.t_total = now() - start;
  progress(MC_LOG_PHASE, "solve: done, %ld unknowns, %ld active of %ld contact nodes, %.3g s", infos.dofs, infos.active,
           infos.contact_rows, infos.t_total);
  solved = true;
}

}  // namespace mc
