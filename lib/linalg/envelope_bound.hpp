// A cheap upper bound on what a sparse Cholesky factorization of a symmetric matrix costs,
// without ordering it for the factorization: the envelope (profile) of the matrix in a reverse
// Cuthill-McKee order. A Cholesky factor's fill stays inside the envelope (George and Liu,
// "Computer Solution of Large Sparse Positive Definite Systems", ch. 4), so the envelope's
// entries bound nnz(L) in that order, and its column counts c_j bound the flops sum_j c_j^2
// (CHOLMOD's measure, Common->fl). The minimum-degree orderings the solvers use fill less
// than an envelope on the meshes met here; the bound is for the automatic choice of interface
// solver (sparse_contact_path.cpp), which only needs to know that a factorization is cheap.
// O(nnz) work: a breadth-first search or three per connected component, no elimination.
#pragma once
#include "bodies/assembly.hpp"

namespace mc {

struct EnvelopeBound {
  double nnz = 0;    // entries of L's envelope, diagonal included
  double flops = 0;  // sum over columns of the envelope's column count squared
};

// a: the upper triangle by columns (SymmetricCsc).
EnvelopeBound envelope_cholesky_bound(const SymmetricCsc &a);

}  // namespace mc
