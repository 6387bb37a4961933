#include "math/decompose.h"

#include <Eigen/SVD>
#include <cmath>

namespace sinew {

namespace {

// Row r of the cross product a × b, in the order SOFA writes it.
inline void cross_row(const Mat3& m, int a, int b, Mat3& out, int r) {
  out(r, 0) = m(a, 1) * m(b, 2) - m(a, 2) * m(b, 1);
  out(r, 1) = m(a, 2) * m(b, 0) - m(a, 0) * m(b, 2);
  out(r, 2) = m(a, 0) * m(b, 1) - m(a, 1) * m(b, 0);
}

// The iteration proper; returns the last iterate Mk (≈ Qᵀ).
Mat3 higham_iterate(const Mat3& M, bool* singular) {
  // Safety cap only: the iteration converges quadratically, so a well-posed
  // input stops after a handful of steps and the cap never changes a result.
  constexpr int max_iterations = 100;
  constexpr double tolerance = 1e-8;

  Mat3 mk = M.transpose();
  double m_one = one_norm(mk);
  double m_inf = inf_norm(mk);
  if (singular) *singular = false;

  for (int it = 0; it < max_iterations; ++it) {
    // Adjugate transpose: rows are cross products of the rows of mk.
    Mat3 adj;
    cross_row(mk, 1, 2, adj, 0);
    cross_row(mk, 2, 0, adj, 1);
    cross_row(mk, 0, 1, adj, 2);
    const double det = mk(0, 0) * adj(0, 0) + mk(0, 1) * adj(0, 1) + mk(0, 2) * adj(0, 2);
    if (det == 0.0) {
      if (singular) *singular = true;
      break;
    }
    const double adj_one = one_norm(adj);
    const double adj_inf = inf_norm(adj);
    const double gamma = std::sqrt(std::sqrt((adj_one * adj_inf) / (m_one * m_inf)) / std::fabs(det));
    const double g1 = gamma * 0.5;
    const double g2 = 0.5 / (gamma * det);

    Mat3 diff;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double next = mk(i, j) * g1 + adj(i, j) * g2;
        diff(i, j) = mk(i, j) - next;
        mk(i, j) = next;
      }
    const double e_one = one_norm(diff);
    m_one = one_norm(mk);
    m_inf = inf_norm(mk);
    if (!(e_one > m_one * tolerance)) break;
  }
  return mk;
}

}  // namespace

double one_norm(const Mat3& A) {
  double norm = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double s = std::fabs(A(0, c)) + std::fabs(A(1, c)) + std::fabs(A(2, c));
    if (s > norm) norm = s;
  }
  return norm;
}

double inf_norm(const Mat3& A) {
  double norm = 0.0;
  for (int r = 0; r < 3; ++r) {
    const double s = std::fabs(A(r, 0)) + std::fabs(A(r, 1)) + std::fabs(A(r, 2));
    if (s > norm) norm = s;
  }
  return norm;
}

Mat3 polar_rotation(const Mat3& M, bool* singular) {
  return higham_iterate(M, singular).transpose();
}

void polar_decomposition(const Mat3& M, Mat3& Q, Mat3& S, bool* singular) {
  const Mat3 mk = higham_iterate(M, singular);
  Q = mk.transpose();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      S(i, j) = mk(i, 0) * M(0, j) + mk(i, 1) * M(1, j) + mk(i, 2) * M(2, j);
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) S(i, j) = S(j, i) = 0.5 * (S(i, j) + S(j, i));
}

Mat3 stable_polar_rotation(const Mat3& M) {
  const Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 U = svd.matrixU();
  const Mat3& V = svd.matrixV();
  // Singular values come sorted in decreasing order: the last pair is the smallest one.
  if (U.determinant() * V.determinant() < 0) U.col(2) = -U.col(2);
  return U * V.transpose();
}

}  // namespace sinew
