// Quaternion ↔ rotation matrix as SOFA's Quat::toMatrix / fromMatrix compute them:
// hand-derived matrices, and the round trip through each branch of fromMatrix.
#include "math/quat.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sinew;

TEST(QuatMatrix, QuarterTurnsAboutTheAxes) {
  const double h = std::sqrt(0.5);
  // 90° about z: x → y, y → −x.
  const Mat3 Rz = quat_to_matrix({0, 0, h, h});
  Mat3 want;
  want << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_LT((Rz - want).cwiseAbs().maxCoeff(), 1e-15);
  // 90° about x: y → z, z → −y.
  const Mat3 Rx = quat_to_matrix({h, 0, 0, h});
  want << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_LT((Rx - want).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(QuatMatrix, FromMatrixInvertsToMatrixInEachBranch) {
  // Positive trace; then a dominant y, z and x diagonal entry (half-turns about each axis, nearly).
  const Quat cases[] = {{0.1, 0.2, 0.3, 0.927362}, {0.1, 0.98, 0.1, 0.1404}, {0.1, 0.1, 0.98, 0.1404},
                        {0.98, 0.1, 0.1, 0.1404}, {0, 0, 1, 0}};
  for (const Quat& raw : cases) {
    const double n = std::sqrt(raw.x * raw.x + raw.y * raw.y + raw.z * raw.z + raw.w * raw.w);
    const Quat q{raw.x / n, raw.y / n, raw.z / n, raw.w / n};
    Quat r = quat_from_matrix(quat_to_matrix(q));
    if (r.w * q.w + r.x * q.x + r.y * q.y + r.z * q.z < 0) r = {-r.x, -r.y, -r.z, -r.w};  // q and −q: one rotation
    EXPECT_NEAR(r.x, q.x, 1e-14);
    EXPECT_NEAR(r.y, q.y, 1e-14);
    EXPECT_NEAR(r.z, q.z, 1e-14);
    EXPECT_NEAR(r.w, q.w, 1e-14);
  }
  // Half-turn about z: diag(−1, −1, 1) takes the z branch and gives (0, 0, 1, 0) exactly.
  Mat3 m;
  m << -1, 0, 0, 0, -1, 0, 0, 0, 1;
  const Quat z = quat_from_matrix(m);
  EXPECT_EQ(z.x, 0.0);
  EXPECT_EQ(z.y, 0.0);
  EXPECT_EQ(z.z, 1.0);
  EXPECT_EQ(z.w, 0.0);
}
