#include "rigid_modes.hpp"
#include "error.hpp"
#include "lapack.hpp"
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
  for (int c = 0; c < k; ++c) {
    double *col = &result.modes[size_t(c) * 2 * n];
    for (int b = 0; b < c; ++b) {
      const double *other = &result.modes[size_t(b) * 2 * n];
      double dot = 0;
      for (int i = 0; i < 2 * n; ++i) dot += col[i] * other[i];
      for (int i = 0; i < 2 * n; ++i) col[i] -= dot * other[i];
    }
    double norm = 0;
    for (int i = 0; i < 2 * n; ++i) norm += col[i] * col[i];
    norm = std::sqrt(norm);
    for (int i = 0; i < 2 * n; ++i) col[i] /= norm;
  }
  // Pinned unknowns: greedy pivoting on the rows of the mode matrix. Each step takes the
  // unknown where the remaining modes move most (far from the centre for a rotation), then
  // removes that direction, so the k pinned rows are well conditioned.
  std::vector<double> rows(size_t(2 * n) * k);
  for (int i = 0; i < 2 * n; ++i)
    for (int c = 0; c < k; ++c) rows[size_t(i) * k + c] = result.modes[size_t(c) * 2 * n + i];
  for (int step = 0; step < k; ++step) {
    int best = -1;
    double best_norm = 0;
    for (int i = 0; i < 2 * n; ++i) {
      if (prescribed[i]) continue;
      double s = 0;
      for (int c = 0; c < k; ++c) s += rows[size_t(i) * k + c] * rows[size_t(i) * k + c];
      if (s > best_norm * (1 + 1e-12)) best_norm = s, best = i;
    }
    if (best < 0) fail(MC_ERROR_INTERNAL, "no unknown left to pin a rigid mode");
    result.pinned_dofs.push_back(best);
    double v[3], norm = std::sqrt(best_norm);
    for (int c = 0; c < k; ++c) v[c] = rows[size_t(best) * k + c] / norm;
    for (int i = 0; i < 2 * n; ++i) {
      double dot = 0;
      for (int c = 0; c < k; ++c) dot += rows[size_t(i) * k + c] * v[c];
      for (int c = 0; c < k; ++c) rows[size_t(i) * k + c] -= dot * v[c];
    }
  }
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

}  // namespace mc
