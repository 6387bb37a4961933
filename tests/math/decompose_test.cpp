#include "math/decompose.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <random>

namespace sinew {
namespace {

Mat3 random_matrix(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  Mat3 M;
  for (int i = 0; i < 9; ++i) M.data()[i] = u(rng);
  return M;
}

TEST(PolarRotation, RandomMatricesGiveRotationAndSymmetricFactor) {
  std::mt19937 rng(12345);
  int tested = 0;
  while (tested < 200) {
    Mat3 M = random_matrix(rng);
    const double d = M.determinant();
    if (std::abs(d) < 1e-3) continue;  // keep the conditioning reasonable
    if (d < 0) M.row(0) *= -1.0;       // orientation preserving → rotation
    ++tested;

    bool singular = true;
    const Mat3 Q = polar_rotation(M, &singular);
    EXPECT_FALSE(singular);
    EXPECT_LT((Q.transpose() * Q - Mat3::Identity()).norm(), 1e-12);
    EXPECT_NEAR(Q.determinant(), 1.0, 1e-12);

    // S = QᵀM must be symmetric positive definite and reproduce M.
    const Mat3 S = Q.transpose() * M;
    EXPECT_LT((S - S.transpose()).norm(), 1e-9 * S.norm());
    Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (S + S.transpose()));
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);

    // Same factor as the SVD route Q = U·Vᵀ.
    Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Mat3 Qsvd = svd.matrixU() * svd.matrixV().transpose();
    EXPECT_LT((Q - Qsvd).norm(), 1e-9);

    Mat3 Q2, S2;
    polar_decomposition(M, Q2, S2);
    EXPECT_EQ(Q2, Q);
    EXPECT_EQ(S2, S2.transpose());  // exactly symmetric by construction
    EXPECT_LT((Q2 * S2 - M).norm(), 1e-9 * M.norm());
  }
}

TEST(PolarRotation, RotationTimesScaleReturnsTheRotation) {
  const Mat3 Rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Mat3 S;
  S << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 0.8;
  const Mat3 Q = polar_rotation(Rot * S);
  EXPECT_LT((Q - Rot).norm(), 1e-12);
}

TEST(PolarRotation, OrientationReversingGivesReflection) {
  Mat3 M = Mat3::Identity();
  M(2, 2) = -3.0;
  const Mat3 Q = polar_rotation(M);
  EXPECT_NEAR(Q.determinant(), -1.0, 1e-14);
  EXPECT_NEAR(Q(2, 2), -1.0, 1e-14);
}

TEST(PolarRotation, SingularInputIsReportedNotLooped) {
  Mat3 M = Mat3::Zero();
  M(0, 0) = 1.0;
  M(1, 1) = 2.0;  // rank 2: determinant exactly 0
  bool singular = false;
  const Mat3 Q = polar_rotation(M, &singular);
  EXPECT_TRUE(singular);
  EXPECT_EQ(Q, M);  // stops on the first iterate, as SOFA does
}

TEST(MatrixNorms, OneAndInfinityNorms) {
  Mat3 A;
  A << 1, -2, 3, -4, 5, -6, 7, -8, 10;
  EXPECT_DOUBLE_EQ(one_norm(A), 19.0);  // column 2: 3+6+10
  EXPECT_DOUBLE_EQ(inf_norm(A), 25.0);  // row 2: 7+8+10
}

}  // namespace
}  // namespace sinew
