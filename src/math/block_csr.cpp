#include "math/block_csr.h"

#include <algorithm>

namespace sinew {

void BlockCsrMatrix::reset(std::size_t n, int bs, Structure s) {
  if (bs < 1 || n % static_cast<std::size_t>(bs) != 0) bs = 1;  // blocks must tile the matrix
  n_ = n;
  bs_ = bs;
  nb_ = n / static_cast<std::size_t>(bs);
  structure_ = s;
  row_begin_.clear();
  cols_.clear();
  values_.clear();
  col_begin_.clear();
  col_blocks_.clear();
  col_rows_.clear();
}

bool BlockCsrMatrix::in_structure(std::size_t r, std::size_t c) const { return storage(r, c); }

bool BlockCsrMatrix::storage(std::size_t& r, std::size_t& c) const {
  if (structure_ == Structure::block_tridiagonal) {
    // SOFA's BTDMatrix keeps three blocks per block row, block (bi, bj) at
    // index 3·bi + (bj − bi + 1), and its add() refuses only bj > bi + 1: an
    // entry further left lands in an earlier block of that array. SOFA's results
    // depend on it (a contact with a state outside the system projects its
    // coupling at local indices: BeamFEMForceField.scn), so it lands there here too.
    // Index beyond the array (SOFA writes past it) or one of the two slots no
    // block uses, (0, −1) and (nb−1, nb): dropped.
    const std::size_t b = static_cast<std::size_t>(bs_);
    const std::size_t bi = r / b, bj = c / b;
    if (bj > bi + 1) return false;
    const std::size_t s = 2 * bi + bj + 1;  // 3·bi + (bj − bi + 1)
    if (s >= 3 * nb_) return false;
    const std::size_t tr = s / 3, slot = s % 3;
    if ((tr == 0 && slot == 0) || tr + slot > nb_) return false;  // column tr + slot − 1 outside [0, nb)
    r = tr * b + r % b;
    c = (tr + slot - 1) * b + c % b;
    return true;
  }
  if (r >= n_ || c >= n_) return false;
  switch (structure_) {
    case Structure::general: return true;
    case Structure::diagonal: return r == c;
    case Structure::block_diagonal: return r / bs_ == c / bs_;
    case Structure::block_tridiagonal: break;
  }
  return true;
}

void BlockCsrMatrix::build_pattern(const std::vector<std::uint64_t>& scalar_keys) {
  const std::uint64_t b = static_cast<std::uint64_t>(bs_);
  std::vector<std::uint64_t> blocks;
  blocks.reserve(scalar_keys.size() / (b * b) + nb_ + 1);
  for (std::uint64_t k : scalar_keys) {
    std::size_t r = k >> 32, c = k & 0xffffffffu;
    if (!storage(r, c)) continue;
    blocks.push_back(((r / b) << 32) | (c / b));
  }
  for (std::uint64_t i = 0; i < nb_; ++i) blocks.push_back((i << 32) | i);
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());

  row_begin_.assign(nb_ + 1, 0);
  cols_.resize(blocks.size());
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    ++row_begin_[(blocks[k] >> 32) + 1];
    cols_[k] = static_cast<int>(blocks[k] & 0xffffffffu);
  }
  for (std::size_t i = 0; i < nb_; ++i) row_begin_[i + 1] += row_begin_[i];
  values_.assign(blocks.size() * b * b, 0.0);

  // Transposed index for column clearing.
  col_begin_.assign(nb_ + 1, 0);
  for (int c : cols_) ++col_begin_[c + 1];
  for (std::size_t i = 0; i < nb_; ++i) col_begin_[i + 1] += col_begin_[i];
  col_blocks_.resize(cols_.size());
  col_rows_.resize(cols_.size());
  std::vector<int> fill(col_begin_.begin(), col_begin_.end() - 1);
  for (std::size_t i = 0; i < nb_; ++i)
    for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k) {
      const int p = fill[cols_[k]]++;
      col_blocks_[p] = k;
      col_rows_[p] = static_cast<int>(i);
    }
}

std::int64_t BlockCsrMatrix::slot(std::size_t r, std::size_t c) const {
  if (row_begin_.empty() || !storage(r, c)) return -1;
  const std::size_t br = r / bs_, bc = c / bs_;
  const auto first = cols_.begin() + row_begin_[br], last = cols_.begin() + row_begin_[br + 1];
  const auto it = std::lower_bound(first, last, static_cast<int>(bc));
  if (it == last || *it != static_cast<int>(bc)) return -1;
  const std::int64_t k = it - cols_.begin();
  return k * bs_ * bs_ + static_cast<std::int64_t>((r % bs_) * bs_ + c % bs_);
}

void BlockCsrMatrix::set_zero() { std::fill(values_.begin(), values_.end(), 0.0); }

double BlockCsrMatrix::coeff(std::size_t r, std::size_t c) const {
  const std::int64_t s = slot(r, c);
  return s < 0 ? 0.0 : values_[s];
}

void BlockCsrMatrix::mult(const double* x, double* y) const {
  const int b = bs_;
  if (b == 1) {
    for (std::size_t i = 0; i < nb_; ++i) {
      double acc = 0;
      for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k) acc += values_[k] * x[cols_[k]];
      y[i] = acc;
    }
    return;
  }
  if (b == 3) {
    for (std::size_t i = 0; i < nb_; ++i) {
      double a0 = 0, a1 = 0, a2 = 0;
      for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k) {
        const double* v = &values_[static_cast<std::size_t>(k) * 9];
        const double* xs = x + 3 * static_cast<std::size_t>(cols_[k]);
        a0 += v[0] * xs[0] + v[1] * xs[1] + v[2] * xs[2];
        a1 += v[3] * xs[0] + v[4] * xs[1] + v[5] * xs[2];
        a2 += v[6] * xs[0] + v[7] * xs[1] + v[8] * xs[2];
      }
      y[3 * i] = a0;
      y[3 * i + 1] = a1;
      y[3 * i + 2] = a2;
    }
    return;
  }
  for (std::size_t i = 0; i < nb_; ++i) {
    double* yi = y + i * b;
    for (int r = 0; r < b; ++r) yi[r] = 0;
    for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k) {
      const double* v = &values_[static_cast<std::size_t>(k) * b * b];
      const double* xs = x + static_cast<std::size_t>(b) * cols_[k];
      for (int r = 0; r < b; ++r) {
        double s = 0;
        for (int c = 0; c < b; ++c) s += v[r * b + c] * xs[c];
        yi[r] += s;
      }
    }
  }
}

void BlockCsrMatrix::clear_row_col_set_diag(std::size_t i, double d) {
  if (i >= n_ || row_begin_.empty()) return;
  const int b = bs_;
  const std::size_t bi = i / b;
  const int sub = static_cast<int>(i % b);
  for (int k = row_begin_[bi]; k < row_begin_[bi + 1]; ++k) {
    double* v = &values_[static_cast<std::size_t>(k) * b * b + sub * b];
    for (int c = 0; c < b; ++c) v[c] = 0.0;
  }
  for (int p = col_begin_[bi]; p < col_begin_[bi + 1]; ++p) {
    double* v = &values_[static_cast<std::size_t>(col_blocks_[p]) * b * b];
    for (int r = 0; r < b; ++r) v[r * b + sub] = 0.0;
  }
  const std::int64_t s = slot(i, i);
  if (s >= 0) values_[s] = d;
}

void BlockCsrMatrix::to_filtered_csr(std::vector<int>& rb, std::vector<int>& ci, std::vector<double>& v) const {
  const int b = bs_;
  rb.assign(n_ + 1, 0);
  ci.clear();
  v.clear();
  for (std::size_t i = 0; i < nb_; ++i)
    for (int r = 0; r < b; ++r) {
      const std::size_t row = i * b + r;
      for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k) {
        const double* vals = &values_[static_cast<std::size_t>(k) * b * b + r * b];
        for (int c = 0; c < b; ++c)
          if (vals[c] != 0.0) {
            ci.push_back(cols_[k] * b + c);
            v.push_back(vals[c]);
          }
      }
      rb[row + 1] = static_cast<int>(ci.size());
    }
}

Eigen::MatrixXd BlockCsrMatrix::to_dense() const {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(n_));
  const int b = bs_;
  for (std::size_t i = 0; i < nb_; ++i)
    for (int k = row_begin_[i]; k < row_begin_[i + 1]; ++k)
      for (int r = 0; r < b; ++r)
        for (int c = 0; c < b; ++c)
          d(static_cast<Eigen::Index>(i * b + r), static_cast<Eigen::Index>(cols_[k] * b + c)) =
              values_[static_cast<std::size_t>(k) * b * b + r * b + c];
  return d;
}

}  // namespace sinew
