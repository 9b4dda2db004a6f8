#include "linalg/block_sparse_operator.hpp"
#include "support/lapack.hpp"
#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace mc {

namespace {
constexpr size_t kAbsent = std::numeric_limits<size_t>::max();
}

BlockSparseOperator::BlockSparseOperator(int n, const std::vector<std::vector<int>> &body_rows) : n_(n) {
  // Each row's bodies (increasing), and the blocks: rows with the same bodies, numbered by their
  // first row.
  std::vector<std::vector<int>> bodies_of(n);
  for (int b = 0; b < int(body_rows.size()); ++b)
    for (int r : body_rows[b]) bodies_of[r].push_back(b);
  std::map<std::vector<int>, int> block_of_bodies;
  block_of_.assign(n, 0), local_of_.assign(n, 0);
  for (int r = 0; r < n; ++r) {
    auto found = block_of_bodies.emplace(bodies_of[r], int(block_rows_.size()));
    if (found.second) block_rows_.emplace_back();
    const int block = found.first->second;
    block_of_[r] = block, local_of_[r] = int(block_rows_[block].size());
    block_rows_[block].push_back(r);
  }
  // Blocks I and J are coupled iff a body touches both (every block with itself).
  const int nb = int(block_rows_.size());
  std::vector<std::set<int>> coupled(nb);
  for (int i = 0; i < nb; ++i) coupled[i].insert(i);
  for (const std::vector<int> &rows : body_rows) {
    std::set<int> touched;
    for (int r : rows) touched.insert(block_of_[r]);
    for (int i : touched) coupled[i].insert(touched.begin(), touched.end());
  }
  size_t pairs = 0;
  for (const std::set<int> &c : coupled) pairs += c.size();
  if (nb > 1 && pairs == size_t(nb) * size_t(nb)) {  // nothing to leave out: one dense block, rows in order
    block_rows_.assign(1, {});
    for (int r = 0; r < n; ++r) block_of_[r] = 0, local_of_[r] = r, block_rows_[0].push_back(r);
    coupled.assign(1, {0});
  }
  // Offsets: block (I, J), I <= J, in the order of I then J.
  neighbours_.assign(blocks(), {});
  size_t stored = 0;
  for (int i = 0; i < blocks(); ++i)
    for (int j : coupled[i]) {
      if (j < i) {  // stored with J's row of blocks, already placed
        neighbours_[i].push_back({j, offset_of(j, i)});
        continue;
      }
      neighbours_[i].push_back({j, stored});
      stored += block_rows_[i].size() * block_rows_[j].size();
    }
  stored_ = stored;
}

size_t BlockSparseOperator::offset_of(int i, int j) const {
  const std::vector<Neighbour> &list = neighbours_[i];
  auto it = std::lower_bound(list.begin(), list.end(), j, [](const Neighbour &a, int b) { return a.block < b; });
  return it != list.end() && it->block == j ? it->offset : kAbsent;
}

void BlockSparseOperator::allocate() {
  if (values_.size() != stored_) values_.assign(stored_, 0.0);
}

void BlockSparseOperator::add_share(const std::vector<int> &rows, const std::vector<double> &s) {
  allocate();
  const size_t qb = rows.size();
  if (dense()) {  // S's own positions: the entries sum in the order the shares come
    for (size_t j = 0; j < qb; ++j)
      for (size_t i = 0; i <= j; ++i) values_[size_t(rows[j]) * n_ + size_t(rows[i])] += s[j * qb + i];
    return;
  }
  // The few blocks this share touches, and where their pairs are stored.
  std::vector<int> touched;
  for (int r : rows) touched.push_back(block_of_[r]);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  const size_t nt = touched.size();
  std::vector<size_t> offset(nt * nt);
  for (size_t a = 0; a < nt; ++a)
    for (size_t b = a; b < nt; ++b) offset[b * nt + a] = offset_of(touched[a], touched[b]);
  std::vector<size_t> slot(qb);
  for (size_t i = 0; i < qb; ++i)
    slot[i] = size_t(std::lower_bound(touched.begin(), touched.end(), block_of_[rows[i]]) - touched.begin());
  for (size_t j = 0; j < qb; ++j)
    for (size_t i = 0; i <= j; ++i) {
      // rows[i] <= rows[j]: the upper entry (rows[i], rows[j]), in block (I, J) or, if I > J,
      // as its mirror in block (J, I).
      const int r = rows[i], c = rows[j];
      size_t a = slot[i], b = slot[j];
      size_t lr = size_t(local_of_[r]), lc = size_t(local_of_[c]);
      if (a > b) std::swap(a, b), std::swap(lr, lc);
      const size_t ld = block_rows_[touched[a]].size();
      values_[offset[b * nt + a] + lc * ld + lr] += s[j * qb + i];
    }
}

void BlockSparseOperator::symmetrize() {
  allocate();
  for (int i = 0; i < blocks(); ++i) {
    const size_t m = block_rows_[i].size(), off = offset_of(i, i);
    for (size_t j = 0; j < m; ++j)
      for (size_t k = j + 1; k < m; ++k) values_[off + j * m + k] = values_[off + k * m + j];
  }
}

double BlockSparseOperator::operator()(int r, int c) const {
  int i = block_of_[r], j = block_of_[c], lr = local_of_[r], lc = local_of_[c];
  if (i > j) std::swap(i, j), std::swap(lr, lc);
  const size_t off = offset_of(i, j);
  return off == kAbsent ? 0.0 : values_[off + size_t(lc) * block_rows_[i].size() + size_t(lr)];
}

void BlockSparseOperator::multiply_add(double alpha, const double *x, double *y) const {
  if (n_ == 0) return;
  int one = 1;
  double plus = 1.0, zero = 0.0;
  if (dense()) {
    dgemv_("N", &n_, &n_, &alpha, values_.data(), &n_, x, &one, &plus, y, &one);
    return;
  }
  std::vector<double> xj, yi;
  for (int i = 0; i < blocks(); ++i)
    for (const Neighbour &nj : neighbours_[i]) {
      const int j = nj.block;
      if (j < i) continue;  // each stored block once: S_IJ x_J into y_I, S_IJ^T x_I into y_J
      const std::vector<int> &ri = block_rows_[i], &rj = block_rows_[j];
      int mi = int(ri.size()), mj = int(rj.size());
      const double *block = values_.data() + nj.offset;
      xj.resize(mj), yi.resize(mi);
      for (int c = 0; c < mj; ++c) xj[c] = x[rj[c]];
      dgemv_("N", &mi, &mj, &alpha, block, &mi, xj.data(), &one, &zero, yi.data(), &one);
      for (int a = 0; a < mi; ++a) y[ri[a]] += yi[a];
      if (j == i) continue;
      xj.resize(mi), yi.resize(mj);
      for (int a = 0; a < mi; ++a) xj[a] = x[ri[a]];
      dgemv_("T", &mi, &mj, &alpha, block, &mi, xj.data(), &one, &zero, yi.data(), &one);
      for (int c = 0; c < mj; ++c) y[rj[c]] += yi[c];
    }
}

SymmetricCsc BlockSparseOperator::principal_upper(const std::vector<char> &mask, std::vector<int> &order) const {
  const int nb = blocks();
  std::vector<std::vector<int>> kept(nb);  // per block: its masked local indices
  std::vector<int> first(nb + 1, 0);       // per block: its first unknown
  order.clear();
  for (int b = 0; b < nb; ++b) {
    first[b] = int(order.size());
    for (int l = 0; l < int(block_rows_[b].size()); ++l)
      if (mask[block_rows_[b][l]]) kept[b].push_back(l), order.push_back(block_rows_[b][l]);
  }
  first[nb] = int(order.size());
  SymmetricCsc a;
  a.n = int(order.size());
  a.colptr.assign(1, 0);
  for (int j = 0; j < nb; ++j)
    for (size_t c = 0; c < kept[j].size(); ++c) {
      // Column c of block j: the blocks i <= j coupled to j, in increasing order (their
      // unknowns precede j's), then j's own down to the diagonal.
      for (const Neighbour &ni : neighbours_[j]) {
        const int i = ni.block;
        if (i > j) break;
        const size_t ld = block_rows_[i].size(), off = ni.offset + size_t(kept[j][c]) * ld;
        const size_t last = i < j ? kept[i].size() : c + 1;
        for (size_t r = 0; r < last; ++r) a.rows.push_back(first[i] + int(r)), a.values.push_back(values_[off + size_t(kept[i][r])]);
      }
      a.colptr.push_back(int(a.rows.size()));
    }
  return a;
}

double BlockSparseOperator::elimination_flops() const {
  double flops = 0;
  for (int i = 0; i < blocks(); ++i) {
    double reach = 0;
    for (const Neighbour &nj : neighbours_[i]) reach += double(block_rows_[nj.block].size());
    flops += double(block_rows_[i].size()) * reach * reach;
  }
  return flops;
}

}  // namespace mc
