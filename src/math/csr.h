// Csr: scalar compressed-row sparse matrix whose pattern is computed once
// (symbolic step, allocates) and whose values are recomputed in place
// (numeric step, never allocates). Used for chains of mapping Jacobians and
// the Jᵀ·K·J products of assembled systems, whose patterns are fixed while
// their values change every step (solver/mapped_assembly.h).
//
// Every numeric function sums in a fixed order (row by row, entries of the
// left operand in pattern order), so results do not depend on history.
#pragma once

#include <cstdint>
#include <vector>

namespace sinew {

struct Csr {
  int rows = 0, cols = 0;
  std::vector<int> ptr;  // rows + 1 offsets into idx/val
  std::vector<int> idx;  // column indices, strictly ascending within a row
  std::vector<double> val;

  int nnz() const { return ptr.empty() ? 0 : ptr.back(); }
  void set_zero();
};

// Pattern of the entries keys[i] = (row << 32) | col; entries outside
// rows×cols are dropped. slot[i] is the value index of entry i (-1 when
// dropped); duplicates share a slot so that refilling sums them.
void csr_pattern(int rows, int cols, const std::vector<std::uint64_t>& keys, Csr& out, std::vector<int>& slot);

// n×n identity (values 1).
void csr_identity(int n, Csr& out);

// C = A·B. Pattern, then values; `work` is a dense accumulator of B.cols
// doubles that must be zero on entry and is left zero.
void csr_multiply_pattern(const Csr& a, const Csr& b, Csr& c);
void csr_multiply_values(const Csr& a, const Csr& b, Csr& c, std::vector<double>& work);

// T = Aᵀ. src[k] is the index in A of entry k of T.
void csr_transpose_pattern(const Csr& a, Csr& t, std::vector<int>& src);
void csr_transpose_values(const Csr& a, const std::vector<int>& src, Csr& t);

// S = Σ terms (all of the same shape). `work` as for the product (S.cols doubles).
void csr_sum_pattern(const std::vector<const Csr*>& terms, Csr& s);
void csr_sum_values(const std::vector<const Csr*>& terms, Csr& s, std::vector<double>& work);

}  // namespace sinew
