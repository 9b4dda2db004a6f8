#include "bodies/cell_shapes.hpp"
#include <cmath>

namespace mc {

bool is_cell_kind(int npc) { return npc == 3 || npc == 4 || npc == 6 || npc == 8 || npc == 9; }

CellType cell_type(int npc) {
  const int corners = npc == 3 || npc == 6 ? 3 : 4;
  return CellType{npc, corners, npc > 4};
}

const char *cell_name(int npc) {
  switch (npc) {
    case 3: return "P1 triangle";
    case 4: return "Q1 quadrilateral";
    case 6: return "T6 triangle";
    case 8: return "Q8 quadrilateral";
    case 9: return "Q9 quadrilateral";
  }
  return "cell";
}

namespace {

const double kQuadCornerX[4] = {-1, 1, 1, -1}, kQuadCornerY[4] = {-1, -1, 1, 1};
// Q8/Q9 nodes 4..7: the middles of edges 0-1, 1-2, 2-3, 3-0; Q9's node 8: the centre.
const double kQuadNodeX[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0}, kQuadNodeY[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};
const double kTriangleNodeX[6] = {0, 1, 0, 0.5, 0.5, 0}, kTriangleNodeY[6] = {0, 0, 1, 0, 0.5, 0.5};

// The 1D quadratic Lagrange functions on [-1, 1] with nodes -1, 0, 1 (index 0, 1, 2), and derivatives.
void lagrange3(double t, double l[3], double dl[3]) {
  l[0] = 0.5 * t * (t - 1), l[1] = 1 - t * t, l[2] = 0.5 * t * (t + 1);
  dl[0] = t - 0.5, dl[1] = -2 * t, dl[2] = t + 0.5;
}

}  // namespace

void reference_shapes(int npc, double xi, double eta, double n[kMaxCellNodes], double dxi[kMaxCellNodes],
                      double deta[kMaxCellNodes]) {
  switch (npc) {
    case 3:
      n[0] = 1 - xi - eta, n[1] = xi, n[2] = eta;
      dxi[0] = -1, dxi[1] = 1, dxi[2] = 0;
      deta[0] = -1, deta[1] = 0, deta[2] = 1;
      return;
    case 6: {
      // Barycentric L0 = 1 - xi - eta, L1 = xi, L2 = eta: corners L(2L - 1), mid-edge 4 L_i L_j.
      const double l[3] = {1 - xi - eta, xi, eta}, lx[3] = {-1, 1, 0}, ly[3] = {-1, 0, 1};
      for (int a = 0; a < 3; ++a) {
        n[a] = l[a] * (2 * l[a] - 1);
        dxi[a] = (4 * l[a] - 1) * lx[a], deta[a] = (4 * l[a] - 1) * ly[a];
        const int b = (a + 1) % 3;  // node 3 + a: the middle of edge a-b
        n[3 + a] = 4 * l[a] * l[b];
        dxi[3 + a] = 4 * (lx[a] * l[b] + l[a] * lx[b]), deta[3 + a] = 4 * (ly[a] * l[b] + l[a] * ly[b]);
      }
      return;
    }
    case 4:
      for (int a = 0; a < 4; ++a) {
        const double sx = kQuadCornerX[a], sy = kQuadCornerY[a];
        n[a] = 0.25 * (1 + xi * sx) * (1 + eta * sy);
        dxi[a] = 0.25 * sx * (1 + eta * sy), deta[a] = 0.25 * sy * (1 + xi * sx);
      }
      return;
    case 8:
      for (int a = 0; a < 4; ++a) {  // serendipity corners
        const double sx = kQuadCornerX[a], sy = kQuadCornerY[a];
        const double gx = 1 + xi * sx, gy = 1 + eta * sy, sum = xi * sx + eta * sy - 1;
        n[a] = 0.25 * gx * gy * sum;
        dxi[a] = 0.25 * sx * gy * (sum + gx), deta[a] = 0.25 * sy * gx * (sum + gy);
      }
      for (int a = 4; a < 8; ++a) {
        const double sx = kQuadNodeX[a], sy = kQuadNodeY[a];
        if (sx == 0) {
          n[a] = 0.5 * (1 - xi * xi) * (1 + eta * sy);
          dxi[a] = -xi * (1 + eta * sy), deta[a] = 0.5 * (1 - xi * xi) * sy;
        } else {
          n[a] = 0.5 * (1 + xi * sx) * (1 - eta * eta);
          dxi[a] = 0.5 * sx * (1 - eta * eta), deta[a] = -eta * (1 + xi * sx);
        }
      }
      return;
    case 9: {
      double lx[3], dlx[3], ly[3], dly[3];
      lagrange3(xi, lx, dlx);
      lagrange3(eta, ly, dly);
      for (int a = 0; a < 9; ++a) {
        const int i = int(kQuadNodeX[a]) + 1, j = int(kQuadNodeY[a]) + 1;
        n[a] = lx[i] * ly[j], dxi[a] = dlx[i] * ly[j], deta[a] = lx[i] * dly[j];
      }
      return;
    }
  }
}

void reference_node(int npc, int a, double &xi, double &eta) {
  if (cell_type(npc).triangle()) xi = kTriangleNodeX[a], eta = kTriangleNodeY[a];
  else xi = kQuadNodeX[a], eta = kQuadNodeY[a];
}

int quadrature_rule(int npc, bool axisymmetric, double xi[kMaxCellPoints], double eta[kMaxCellPoints],
                    double weight[kMaxCellPoints]) {
  switch (npc) {
    case 3:
    case 6:
      if (npc == 3 && !axisymmetric) {
        xi[0] = eta[0] = 1.0 / 3, weight[0] = 0.5;
        return 1;
      }
      if (npc == 3 || !axisymmetric) {
        // barycentric (2/3, 1/6, 1/6) and its permutations: degree 2
        xi[0] = 1.0 / 6, eta[0] = 1.0 / 6;
        xi[1] = 2.0 / 3, eta[1] = 1.0 / 6;
        xi[2] = 1.0 / 6, eta[2] = 2.0 / 3;
        for (int g = 0; g < 3; ++g) weight[g] = 1.0 / 6;
        return 3;
      }
      {
        // Dunavant's degree-4 rule: two orbits of three points (barycentric (a, a, 1 - 2a)).
        const double a[2] = {0.445948490915965, 0.091576213509771};
        const double w[2] = {0.223381589678011, 0.109951743655322};
        int g = 0;
        for (int orbit = 0; orbit < 2; ++orbit) {
          const double l[3][3] = {{a[orbit], a[orbit], 1 - 2 * a[orbit]},
                                  {a[orbit], 1 - 2 * a[orbit], a[orbit]},
                                  {1 - 2 * a[orbit], a[orbit], a[orbit]}};
          for (int p = 0; p < 3; ++p, ++g) xi[g] = l[p][1], eta[g] = l[p][2], weight[g] = 0.5 * w[orbit];
        }
        return 6;
      }
    case 4: {
      const double gauss = 0.57735026918962576451;  // 1/sqrt(3)
      for (int g = 0; g < 4; ++g) xi[g] = gauss * kQuadCornerX[g], eta[g] = gauss * kQuadCornerY[g], weight[g] = 1;
      return 4;
    }
    default: {  // 8, 9: 3x3 Gauss
      const double x[3] = {-0.77459666924148337704, 0, 0.77459666924148337704}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
      int g = 0;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i, ++g) xi[g] = x[i], eta[g] = x[j], weight[g] = w[i] * w[j];
      return 9;
    }
  }
}

int error_quadrature_rule(int npc, bool axisymmetric, double xi[kMaxCellPoints], double eta[kMaxCellPoints],
                          double weight[kMaxCellPoints]) {
  return quadrature_rule(npc, axisymmetric || npc == 6, xi, eta, weight);
}

void line_shapes(int nodes, double s, double n[3], double ds[3]) {
  if (nodes == 2) {
    n[0] = 1 - s, n[1] = s, n[2] = 0;
    ds[0] = -1, ds[1] = 1, ds[2] = 0;
    return;
  }
  n[0] = (1 - s) * (1 - 2 * s), n[1] = s * (2 * s - 1), n[2] = 4 * s * (1 - s);
  ds[0] = 4 * s - 3, ds[1] = 4 * s - 1, ds[2] = 4 - 8 * s;
}

void gauss_on_unit_interval(int count, double point[5], double weight[5]) {
  static const double x[5][5] = {{0},
                                 {-0.57735026918962576451, 0.57735026918962576451},
                                 {-0.77459666924148337704, 0, 0.77459666924148337704},
                                 {-0.86113631159405257522, -0.33998104358485626480, 0.33998104358485626480,
                                  0.86113631159405257522},
                                 {-0.90617984593866399280, -0.53846931010568309104, 0, 0.53846931010568309104,
                                  0.90617984593866399280}};
  static const double w[5][5] = {{2},
                                 {1, 1},
                                 {5.0 / 9, 8.0 / 9, 5.0 / 9},
                                 {0.34785484513745385737, 0.65214515486254614263, 0.65214515486254614263,
                                  0.34785484513745385737},
                                 {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                                  0.47862867049936646804, 0.23692688505618908751}};
  const int k = count < 1 ? 0 : count > 5 ? 4 : count - 1;
  for (int i = 0; i <= k; ++i) point[i] = 0.5 * (1 + x[k][i]), weight[i] = 0.5 * w[k][i];
}

}  // namespace mc
