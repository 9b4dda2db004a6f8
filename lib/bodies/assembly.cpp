#include "bodies/assembly.hpp"
#include "bodies/cell_shapes.hpp"
#include <algorithm>

namespace mc {

void SymmetricCsc::multiply(const double *x, double *y) const {
  std::fill(y, y + n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int p = colptr[j]; p < colptr[j + 1]; ++p) {
      int i = rows[p];
      y[i] += values[p] * x[j];
      if (i != j) y[j] += values[p] * x[i];
    }
}

SymmetricCsc SymmetricCsc::principal_submatrix(const std::vector<int> &index, int n_kept) const {
  SymmetricCsc sub;
  sub.n = n_kept;
  sub.colptr.assign(n_kept + 1, 0);
  for (int j = 0; j < n; ++j) {
    if (index[j] < 0) continue;
    for (int p = colptr[j]; p < colptr[j + 1]; ++p)
      if (index[rows[p]] >= 0) sub.colptr[index[j] + 1]++;
  }
  for (int j = 0; j < n_kept; ++j) sub.colptr[j + 1] += sub.colptr[j];
  sub.rows.resize(sub.colptr[n_kept]);
  sub.values.resize(sub.colptr[n_kept]);
  for (int j = 0; j < n; ++j) {
    if (index[j] < 0) continue;
    int q = sub.colptr[index[j]];
    for (int p = colptr[j]; p < colptr[j + 1]; ++p)
      if (index[rows[p]] >= 0) sub.rows[q] = index[rows[p]], sub.values[q++] = values[p];
  }
  return sub;
}

namespace {

// Node-to-node adjacency through cells (each node is its own neighbour), sorted, as CSR.
void node_adjacency(const Mesh &mesh, std::vector<int> &start, std::vector<int> &neighbours) {
  const int n = mesh.n_nodes(), npc = mesh.nodes_per_cell();
  std::vector<int> cell_start(n + 1, 0), node_cells(size_t(mesh.n_cells()) * npc);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int a = 0; a < npc; ++a) cell_start[mesh.cell(c)[a] + 1]++;
  for (int i = 0; i < n; ++i) cell_start[i + 1] += cell_start[i];
  std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int a = 0; a < npc; ++a) node_cells[fill[mesh.cell(c)[a]]++] = c;
  std::vector<int> marker(n, -1);
  start.assign(n + 1, 0);
  neighbours.clear();
  neighbours.reserve(size_t(n) * 10);
  for (int i = 0; i < n; ++i) {
    size_t first = neighbours.size();
    for (int k = cell_start[i]; k < cell_start[i + 1]; ++k)
      for (int a = 0; a < npc; ++a) {
        int m = mesh.cell(node_cells[k])[a];
        if (marker[m] != i) marker[m] = i, neighbours.push_back(m);
      }
    std::sort(neighbours.begin() + first, neighbours.end());
    start[i + 1] = int(neighbours.size());
  }
}

}  // namespace

SymmetricCsc assemble_stiffness(const Mesh &mesh, const std::vector<PlaneLaw> &laws, const LineMeasure &measure,
                                bool bbar) {
  // Pattern: column 2j+c holds rows 2i+c' <= 2j+c for every neighbour i of node j.
  std::vector<int> start, neighbours;
  node_adjacency(mesh, start, neighbours);
  const int n_nodes = mesh.n_nodes();
  SymmetricCsc k;
  k.n = 2 * n_nodes;
  k.colptr.assign(k.n + 1, 0);
  for (int j = 0; j < n_nodes; ++j) {
    int below = 0;  // neighbours with a smaller id
    while (start[j] + below < start[j + 1] && neighbours[start[j] + below] < j) ++below;
    k.colptr[2 * j + 1] = 2 * below + 1;      // x column: rows 2i, 2i+1 of lower nodes, then 2j
    k.colptr[2 * j + 2] = 2 * below + 2;      // y column: also 2j+1
  }
  for (int j = 0; j < k.n; ++j) k.colptr[j + 1] += k.colptr[j];
  k.rows.resize(k.colptr[k.n]);
  k.values.assign(k.colptr[k.n], 0.0);
  for (int j = 0; j < n_nodes; ++j)
    for (int c = 0; c < 2; ++c) {
      int q = k.colptr[2 * j + c];
      for (int p = start[j]; p < start[j + 1] && neighbours[p] <= j; ++p) {
        int i = neighbours[p];
        if (i < j) k.rows[q++] = 2 * i, k.rows[q++] = 2 * i + 1;
        else {
          k.rows[q++] = 2 * j;
          if (c == 1) k.rows[q++] = 2 * j + 1;
        }
      }
    }

  const int npc = mesh.nodes_per_cell(), m = 2 * npc;
  double ke[4 * kMaxCellNodes * kMaxCellNodes];
  Point p[kMaxCellNodes];
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int *v = mesh.cell(c);
    for (int a = 0; a < npc; ++a) p[a] = mesh.node(v[a]);
    const PlaneLaw &law = laws.size() == 1 ? laws[0] : laws[c];
    cell_stiffness(p, npc, law, measure, bbar && npc == 4, ke);
    for (int b = 0; b < m; ++b) {
      int col = 2 * v[b / 2] + b % 2;
      const int *first = &k.rows[k.colptr[col]], *last = &k.rows[k.colptr[col + 1]];
      for (int a = 0; a < m; ++a) {
        int row = 2 * v[a / 2] + a % 2;
        if (row > col) continue;
        k.values[std::lower_bound(first, last, row) - k.rows.data()] += ke[a * m + b];
      }
    }
  }
  return k;
}

}  // namespace mc
