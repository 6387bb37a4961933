// BlockCsrMatrix: square block compressed-row matrix (blocks bs×bs, bs = 1
// gives a plain scalar CSR), the storage of assembled linear systems.
//
// The pattern is built once from the (row, col) keys of the first assembly
// and kept; later assemblies only zero and refill `values` through slots
// (value indices) computed once. Every diagonal entry is in the pattern so
// that Dirichlet rows can be set to identity (spec/solvers.md §2.4 step 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sinew {

class BlockCsrMatrix {
 public:
  // Which entries are stored (DiagonalMatrix / BlockDiagonalMatrix drop the others).
  enum class Structure { general, diagonal, block_diagonal, block_tridiagonal };

  // Sets size, block size and structure; clears the pattern.
  void reset(std::size_t n, int bs, Structure s = Structure::general);
  // Builds the pattern from scalar keys ((row << 32) | col, any order, duplicates
  // allowed) plus the full diagonal; values are zero. Keys outside the structure are ignored.
  void build_pattern(const std::vector<std::uint64_t>& scalar_keys);

  std::size_t size() const { return n_; }
  int block_size() const { return bs_; }
  Structure structure() const { return structure_; }
  std::size_t block_rows() const { return nb_; }
  std::size_t nnz_blocks() const { return cols_.size(); }
  bool has_pattern() const { return !row_begin_.empty(); }

  // Value index of scalar entry (r, c), or -1 when outside the pattern/structure.
  // block_tridiagonal stores as SOFA's BTDMatrix does: an entry left of the
  // band lands in another block (see storage()); the slot is that block's.
  std::int64_t slot(std::size_t r, std::size_t c) const;
  bool in_structure(std::size_t r, std::size_t c) const;

  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  const std::vector<int>& row_begin() const { return row_begin_; }
  const std::vector<int>& block_cols() const { return cols_; }

  void set_zero();
  // Value (0 when outside the pattern).
  double coeff(std::size_t r, std::size_t c) const;
  // y = A·x (sizes n).
  void mult(const double* x, double* y) const;
  // Clears row i and column i, then sets A(i,i) = d (Dirichlet condition).
  void clear_row_col_set_diag(std::size_t i, double d);
  // Scalar CSR of the exactly non-zero entries, columns ascending in each row.
  void to_filtered_csr(std::vector<int>& row_begin, std::vector<int>& cols, std::vector<double>& values) const;
  Eigen::MatrixXd to_dense() const;

 private:
  // Where entry (r, c) is stored: true and (r, c) moved there, false when dropped.
  bool storage(std::size_t& r, std::size_t& c) const;

  std::size_t n_ = 0, nb_ = 0;
  int bs_ = 1;
  Structure structure_ = Structure::general;
  std::vector<int> row_begin_, cols_;
  std::vector<double> values_;
  // Transposed index: for each block column, the blocks (indices) in it, by block row.
  std::vector<int> col_begin_, col_blocks_, col_rows_;
};

}  // namespace sinew
