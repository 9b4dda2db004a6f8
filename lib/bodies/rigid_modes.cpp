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

// A host body's rigid modes: the rigid motions (in the coordinates of each unknown's point and
// component) that its own stiffness does not resist. Solves (K R)^T (K R) v = mu R^T R v over
// the candidate motions R (translations and rotation; axisymmetric: the axial translation); a
// mode is free when |K R v| <= 1e-9 max|K_ij| |R v|: round-off for a rigid motion, while a body
// held by one restrained freedom resists it with about max|K_ij| / sqrt(unknowns) (1e-3 of it at
// 10^6 unknowns).
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
  // mu = |K q v|^2 for q v of unit norm. A free mode's is round-off: the eigenvalues are
  // accurate to eps times the largest (measured: 3.8e-16 for a free translation of a Q9 body
  // whose held modes had 0.39 and 1.39), while a body held by one restrained freedom resists
  // with about (kmax / sqrt(unknowns))^2 (1e-6 kmax^2 at 10^6 unknowns). Free: below 1e-10 of
  // the largest, or below (1e-9 kmax)^2 when all are free.
  const double threshold = 1e-18 * kmax * kmax + 1e-10 * mu[n - 1];
  while (result.count < n && mu[result.count] <= threshold) ++result.count;
  if (result.count == 0) return result;
  const int count = result.count;
  result.modes.assign(size_t(ndof) * count, 0.0);
  for (int c = 0; c < count; ++c)
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < ndof; ++i) result.modes[size_t(c) * ndof + i] += g[n * c + a] * q[size_t(a) * ndof + i];
  if (axisymmetric) {
    result.description = "translation along the axis (y)";
  } else {
    // Each mode in the candidates' terms (tx, ty, rotation), for the message: least squares on
    // the candidates that were kept.
    double basis[9] = {0};
    for (int c = 0; c < count; ++c) {
      double a[9] = {0}, rhs[3] = {0};
      for (int x = 0; x < n; ++x) {
        const double *rx = &r[size_t(kept[x]) * ndof];
        for (int i = 0; i < ndof; ++i) rhs[x] += rx[i] * result.modes[size_t(c) * ndof + i];
        for (int y = 0; y < n; ++y) {
          const double *ry = &r[size_t(kept[y]) * ndof];
          double sum = 0;
          for (int i = 0; i < ndof; ++i) sum += rx[i] * ry[i];
          a[n * x + y] = sum;
        }
      }
      int ipiv[3], one = 1, lw = 32;
      double w2[32];
      dsysv_("U", &nn, &one, a, &nn, ipiv, rhs, &nn, w2, &lw, &info);
      for (int x = 0; x < n; ++x) basis[3 * c + kept[x]] = info == 0 ? rhs[x] : 0;
    }
    result.description = describe(basis, count);
  }
  orthonormalize_and_pin(result, ndof, {});
  return result;
}

}  // namespace mc
