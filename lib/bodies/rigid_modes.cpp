#include "bodies/rigid_modes.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

// The three rigid motions at a node, about the centroid and scaled by the body size so the
// three columns have comparable norms: translation x, translation y, rotation.
void rigid_rows(Point p, Point centre, double length, double row_x[3], double row_y[3]) {
  row_x[0] = 1, row_x[1] = 0, row_x[2] = -(p.y - centre.y) / length;
  row_y[0] = 0, row_y[1] = 1, row_y[2] = (p.x - centre.x) / length;
}

std::string describe(const double *basis, int count) {
  // basis: 3 x count coefficients of (tx, ty, rotation).
  if (count == 3) return "translations in x and y and rotation";
  std::string text;
  for (int c = 0; c < count; ++c) {
    const double *v = basis + 3 * c;
    std::string one;
    if (std::fabs(v[2]) < 1e-6) one = std::fabs(v[1]) < 1e-6 ? "translation in x" : std::fabs(v[0]) < 1e-6 ? "translation in y" : "a translation";
    else if (std::fabs(v[0]) < 1e-6 && std::fabs(v[1]) < 1e-6) one = "rotation";
    else one = "a rotation about a supported point";
    text += (c ? " and " : "") + one;
  }
  return text;
}

// Orthonormalizes the mode columns (Gram-Schmidt) and picks the pinned unknowns: greedy
// pivoting on the rows of the mode matrix. Each step takes the unknown where the remaining modes
// move most (far from the centre for a rotation), then removes that direction, so the k pinned
// rows are well conditioned.
void orthonormalize_and_pin(RigidModes &result, int ndof, const std::vector<char> &prescribed) {
  const int k = result.count;
  for (int c = 0; c < k; ++c) {
    double *col = &result.modes[size_t(c) * ndof];
    for (int b = 0; b < c; ++b) {
      const double *other = &result.modes[size_t(b) * ndof];
      double dot = 0;
      for (int i = 0; i < ndof; ++i) dot += col[i] * other[i];
      for (int i = 0; i < ndof; ++i) col[i] -= dot * other[i];
    }
    double norm = 0;
    for (int i = 0; i < ndof; ++i) norm += col[i] * col[i];
    norm = std::sqrt(norm);
    for (int i = 0; i < ndof; ++i) col[i] /= norm;
  }
  std::vector<double> rows(size_t(ndof) * k);
  for (int i = 0; i < ndof; ++i)
    for (int c = 0; c < k; ++c) rows[size_t(i) * k + c] = result.modes[size_t(c) * ndof + i];
  for (int step = 0; step < k; ++step) {
    int best = -1;
    double best_norm = 0;
    for (int i = 0; i < ndof; ++i) {
      if (!prescribed.empty() && prescribed[i]) continue;
      double s = 0;
      for (int c = 0; c < k; ++c) s += rows[size_t(i) * k + c] * rows[size_t(i) * k + c];
      if (s > best_norm * (1 + 1e-12)) best_norm = s, best = i;
    }
    if (best < 0) fail(MC_ERROR_INTERNAL, "no unknown left to pin a rigid mode");
    result.pinned_dofs.push_back(best);
    double v[3], norm = std::sqrt(best_norm);
    for (int c = 0; c < k; ++c) v[c] = rows[size_t(best) * k + c] / norm;
    for (int i = 0; i < ndof; ++i) {
      double dot = 0;
      for (int c = 0; c < k; ++c) dot += rows[size_t(i) * k + c] * v[c];
      for (int c = 0; c < k; ++c) rows[size_t(i) * k + c] -= dot * v[c];
    }
  }
}

}  // namespace

RigidModes free_rigid_modes(const Mesh &mesh, const std::vector<char> &prescribed) {
  const int n = mesh.n_nodes();
  Point centre{0, 0};
  for (int i = 0; i < n; ++i) centre.x += mesh.node(i).x / n, centre.y += mesh.node(i).y / n;
  const double length = mesh.characteristic_length();
  // C^T C, C = the rows of the rigid modes at the prescribed components.
  double ctc[9] = {0}, rx[3], ry[3];
  int n_prescribed = 0;
  for (int i = 0; i < n; ++i) {
    if (!prescribed[2 * i] && !prescribed[2 * i + 1]) continue;
    rigid_rows(mesh.node(i), centre, length, rx, ry);
    for (int c = 0; c < 2; ++c) {
      if (!prescribed[2 * i + c]) continue;
      const double *r = c == 0 ? rx : ry;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) ctc[3 * a + b] += r[a] * r[b];
      ++n_prescribed;
    }
  }
  double eig[3], work[32];
  int three = 3, lwork = 32, info = 0;
  dsyev_("V", "U", &three, ctc, &three, eig, work, &lwork, &info);
  if (info != 0) fail(MC_ERROR_INTERNAL, "dsyev failed (%d) in the rigid-mode analysis", info);
  // Eigenvalues in ascending order; a mode is free when the supports do not see it. The
  // threshold is relative: the largest eigenvalue grows with the number of supports.
  RigidModes result;
  double threshold = 1e-10 * std::max(1.0, eig[2]);
  while (result.count < 3 && eig[result.count] <= threshold) ++result.count;
  if (n_prescribed == 0) result.count = 3;
  if (result.count == 0) return result;
  const int k = result.count;
  result.description = describe(ctc, k);
  // Mode fields: columns of the free eigenvectors, then orthonormalized (Gram-Schmidt).
  result.modes.assign(size_t(2 * n) * k, 0.0);
  for (int i = 0; i < n; ++i) {
    rigid_rows(mesh.node(i), centre, length, rx, ry);
    for (int c = 0; c < k; ++c) {
      const double *v = ctc + 3 * c;
      result.modes[size_t(c) * 2 * n + 2 * i] = prescribed[2 * i] ? 0 : rx[0] * v[0] + rx[1] * v[1] + rx[2] * v[2];
      result.modes[size_t(c) * 2 * n + 2 * i + 1] = prescribed[2 * i + 1] ? 0 : ry[0] * v[0] + ry[1] * v[1] + ry[2] * v[2];
    }
  }
  orthonormalize_and_pin(result, 2 * n, prescribed);
  return result;
}

RigidModes free_axial_translation(const Mesh &mesh, const std::vector<char> &prescribed) {
  const int n = mesh.n_nodes();
  RigidModes result;
  for (int i = 0; i < n; ++i)
    if (prescribed[2 * i + 1]) return result;  // one axial support holds it
  result.count = 1;
  result.description = "translation along the axis (y)";
  result.modes.assign(size_t(2 * n), 0.0);
  for (int i = 0; i < n; ++i) result.modes[2 * size_t(i) + 1] = 1 / std::sqrt(double(n));
  result.pinned_dofs.push_back(1);  // any axial unknown defines K^+: node 0's
  return result;
}

namespace {

// How firmly k holds the motion w: the largest share of a row's forces that w leaves
// unbalanced, max_i |(K w)_i| / (sum_j |K_ij| max_j |w_j|) over the row's entries (rows w does
// not reach skipped). Per row, so that neither the number of unknowns nor a stiffness contrast
// between parts of the body moves it: round-off leaves the precision of the entries, a
// restrained neighbour its column's share. The row's whole scale, not sum_j |K_ij w_j|: an x
// row under a translation in y sees only the x-y couplings, which may themselves be round-off
// (measured: 0.22 that way for an exactly free translation).
double row_resistance(const SymmetricCsc &k, const double *w) {
  std::vector<double> force(k.n, 0.0), scale(k.n, 0.0), reach(k.n, 0.0);
  for (int j = 0; j < k.n; ++j)
    for (int p = k.colptr[j]; p < k.colptr[j + 1]; ++p) {
      const int i = k.rows[p];
      const double v = k.values[p];
      force[i] += v * w[j], scale[i] += std::fabs(v), reach[i] = std::max(reach[i], std::fabs(w[j]));
      if (i != j) force[j] += v * w[i], scale[j] += std::fabs(v), reach[j] = std::max(reach[j], std::fabs(w[i]));
    }
  double worst = 0;
  for (int i = 0; i < k.n; ++i)
    if (scale[i] * reach[i] > 0) worst = std::max(worst, std::fabs(force[i]) / (scale[i] * reach[i]));
  return worst;
}

// The coefficients of w in the kept candidates' terms (least squares on them), as (tx, ty,
// rotation).
void candidate_motion(const std::vector<double> &r, const std::vector<int> &kept, int ndof, const double *w,
                      double motion[3]) {
  int n = int(kept.size()), info = 0, ipiv[3], one = 1, lwork = 32;
  double a[9] = {0}, rhs[3] = {0}, work[32];
  for (int x = 0; x < n; ++x) {
    const double *rx = &r[size_t(kept[x]) * ndof];
    for (int i = 0; i < ndof; ++i) rhs[x] += rx[i] * w[i];
    for (int y = 0; y < n; ++y) {
      const double *ry = &r[size_t(kept[y]) * ndof];
      double sum = 0;
      for (int i = 0; i < ndof; ++i) sum += rx[i] * ry[i];
      a[n * x + y] = sum;
    }
  }
  dsysv_("U", &n, &one, a, &n, ipiv, rhs, &n, work, &lwork, &info);
  motion[0] = motion[1] = motion[2] = 0;
  for (int x = 0; x < n; ++x) motion[kept[x]] = info == 0 ? rhs[x] : 0;
}

}  // namespace

std::string describe_rigid_motion(const double motion[3]) { return describe(motion, 1); }

// A host body's rigid modes: the rigid motions (in the coordinates of each unknown's point and
// component) that its own stiffness does not resist. The candidates (translations and rotation;
// axisymmetric: the axial translation) are split into directions by (K R)^T (K R) v = mu R^T R v,
// the least resisted first, and each direction w = R v is judged by row_resistance against
// kFreeResistance and kHeldResistance (rigid_modes.hpp). The eigenvalues mu themselves are only
// accurate to eps times the largest (3.8e-16 measured for an exactly free translation of a Q9
// body whose held modes had 0.39 and 1.39), too coarse to tell single-precision round-off (|K w|
// about 3e-8 kmax, mu 1e-15 kmax^2) from a hold; their directions are accurate (errors of eps
// times mu_max / gap), and the row measure on them is not squared.
RigidModes kernel_rigid_modes(const std::vector<Point> &point, const std::vector<int> &component,
                              const SymmetricCsc &k, bool axisymmetric) {
  RigidModes result;
  const int ndof = k.n;
  if (ndof == 0) return result;
  Point centre{0, 0};
  double xmin = point[0].x, xmax = xmin, ymin = point[0].y, ymax = ymin;
  for (const Point &p : point) {
    centre.x += p.x / ndof, centre.y += p.y / ndof;
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  const double length = std::max({xmax - xmin, ymax - ymin, 1e-300});
  // The candidates (translations, rotation; axisymmetric: the axial translation) on the
  // unknowns there are, orthonormalized; one with no unknown to move (every x freedom
  // restrained: no translation in x) or dependent on the others drops out.
  const int candidates = axisymmetric ? 1 : 3;
  std::vector<double> r(size_t(ndof) * 3, 0.0);
  for (int i = 0; i < ndof; ++i) {
    double rx[3], ry[3];
    rigid_rows(point[i], centre, length, rx, ry);
    const double *row = component[i] == 0 ? rx : ry;
    if (axisymmetric) r[i] = component[i] == 1 ? 1 : 0;
    else
      for (int c = 0; c < 3; ++c) r[size_t(c) * ndof + i] = row[c];
  }
  std::vector<double> q;  // orthonormal columns
  std::vector<int> kept;  // which candidate each column came from (for the description)
  for (int c = 0; c < candidates; ++c) {
    std::vector<double> v(r.begin() + size_t(c) * ndof, r.begin() + size_t(c + 1) * ndof);
    double before = 0;
    for (double x : v) before += x * x;
    for (size_t b = 0; b < kept.size(); ++b) {
      double dot = 0;
      for (int i = 0; i < ndof; ++i) dot += v[i] * q[b * ndof + i];
      for (int i = 0; i < ndof; ++i) v[i] -= dot * q[b * ndof + i];
    }
    double after = 0;
    for (double x : v) after += x * x;
    if (!(after > 1e-20 * std::max(before, 1e-300)) || before == 0) continue;
    for (double &x : v) x /= std::sqrt(after);
    q.insert(q.end(), v.begin(), v.end());
    kept.push_back(c);
  }
  const int n = int(kept.size());
  if (n == 0) return result;
  std::vector<double> kq(size_t(ndof) * n);
  for (int c = 0; c < n; ++c) k.multiply(&q[size_t(c) * ndof], &kq[size_t(c) * ndof]);
  double g[9] = {0}, kmax = 0;
  for (double v : k.values) kmax = std::max(kmax, std::fabs(v));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      double sum = 0;
      for (int i = 0; i < ndof; ++i) sum += kq[size_t(a) * ndof + i] * kq[size_t(b) * ndof + i];
      g[n * a + b] = sum;
    }
  int nn = n, lwork = 32, info = 0;
  double mu[3], work[32];
  dsyev_("V", "U", &nn, g, &nn, mu, work, &lwork, &info);
  if (info != 0) fail(MC_ERROR_INTERNAL, "dsyev failed (%d) in the rigid-mode analysis of a host body", info);
  // Each direction w = Q v_c (unit norm), judged on its own; the free ones must come first (the
  // least resisted), or the matrix contradicts itself and every direction after the first
  // held one counts as ambiguous.
  std::vector<double> direction(size_t(ndof) * n, 0.0), kw(ndof);
  bool held_seen = false;
  for (int c = 0; c < n; ++c) {
    double *w = &direction[size_t(c) * ndof];
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < ndof; ++i) w[i] += g[n * c + a] * q[size_t(a) * ndof + i];
    RigidCandidate cand;
    cand.resistance = row_resistance(k, w);
    k.multiply(w, kw.data());
    double norm = 0;
    for (double x : kw) norm += x * x;
    cand.norm_ratio = kmax > 0 ? std::sqrt(norm) / kmax : 0;
    if (cand.resistance <= kFreeResistance && !held_seen) cand.kind = RigidCandidate::free;
    else if (cand.resistance < kHeldResistance || cand.resistance <= kFreeResistance) cand.kind = RigidCandidate::ambiguous;
    else cand.kind = RigidCandidate::held, held_seen = true;
    if (axisymmetric) {
      cand.motion[1] = 1, cand.description = "translation along the axis (y)";
    } else {
      candidate_motion(r, kept, ndof, w, cand.motion);
      cand.description = describe(cand.motion, 1);
    }
    if (cand.kind == RigidCandidate::free) ++result.count;
    result.candidates.push_back(cand);
  }
  for (int c = result.count; c < n; ++c)
    if (result.candidates[c].kind == RigidCandidate::held) {
      result.held.insert(result.held.end(), direction.begin() + size_t(c) * ndof, direction.begin() + size_t(c + 1) * ndof);
      ++result.held_count;
    }
  if (result.count == 0) return result;
  const int count = result.count;
  result.modes.assign(direction.begin(), direction.begin() + size_t(count) * ndof);
  if (axisymmetric) {
    result.description = "translation along the axis (y)";
  } else {
    double basis[9] = {0};
    for (int c = 0; c < count; ++c)
      for (int x = 0; x < 3; ++x) basis[3 * c + x] = result.candidates[c].motion[x];
    result.description = describe(basis, count);
  }
  orthonormalize_and_pin(result, ndof, {});
  return result;
}

}  // namespace mc
