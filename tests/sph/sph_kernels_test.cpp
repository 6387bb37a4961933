// SPH kernels: unit integral over the support (what makes a summed density a
// density), gradient factor consistent with the derivative of W, Laplacian
// consistent with the gradient (cubic spline and poly6), compact support.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sph/sph_kernels.h"

namespace sinew::sph {
namespace {

// 4π ∫₀ʰ W(r/h) r² dr by composite Simpson on [0, h].
template <class K>
double integral(const K& k, double h) {
  const int n = 20000;
  const double dr = h / n;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double r = i * dr;
    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    s += w * k.W(r / h) * r * r;
  }
  return 4 * std::numbers::pi * s * dr / 3;
}

// dW/dr by central differences, to compare with r·g (∇W = d·g, |d| = r).
template <class K>
void expect_gradient_is_derivative(const K& k, double h) {
  for (double q : {0.1, 0.3, 0.49, 0.51, 0.7, 0.9}) {
    const double r = q * h, e = 1e-6 * h;
    const double fd = (k.W((r + e) / h) - k.W((r - e) / h)) / (2 * e);
    EXPECT_NEAR(r * k.grad(q), fd, 1e-6 * (std::abs(fd) + k.cw / h)) << "q = " << q;
  }
}

TEST(SphKernels, UnitIntegral) {
  for (double h : {0.5, 0.745, 2.0}) {
    EXPECT_NEAR(integral(DensityKernel(h), h), 1.0, 1e-9) << "poly6, h = " << h;
    EXPECT_NEAR(integral(PressureKernel(h), h), 1.0, 1e-9) << "spiky, h = " << h;
    EXPECT_NEAR(integral(CubicKernel(h), h), 1.0, 1e-9) << "cubic, h = " << h;
  }
}

TEST(SphKernels, GradientIsTheDerivativeOfW) {
  expect_gradient_is_derivative(DensityKernel(0.745), 0.745);
  expect_gradient_is_derivative(PressureKernel(0.745), 0.745);
  expect_gradient_is_derivative(CubicKernel(0.745), 0.745);
  expect_gradient_is_derivative(ViscosityKernel(1.3), 1.3);
}

TEST(SphKernels, CubicLaplacianMatchesRadialFormula) {
  // ∇²W = W'' + 2W'/r for a radial function; SOFA's cubic Laplacian factor is that times h²/C·C/h².
  const double h = 0.8;
  const CubicKernel k(h);
  for (double q : {0.2, 0.4, 0.6, 0.8}) {
    const double r = q * h, e = 1e-4 * h;
    const double w1 = (k.W((r + e) / h) - k.W((r - e) / h)) / (2 * e);
    const double w2 = (k.W((r + e) / h) - 2 * k.W(r / h) + k.W((r - e) / h)) / (e * e);
    EXPECT_NEAR(k.lap(q), w2 + 2 * w1 / r, 1e-4 * k.cw / (h * h)) << "q = " << q;
  }
}

TEST(SphKernels, CompactSupportAndPeak) {
  const double h = 0.745;
  EXPECT_EQ(CubicKernel(h).W(1.0), 0.0);
  EXPECT_EQ(CubicKernel(h).grad(1.2), 0.0);
  EXPECT_EQ(DensityKernel(h).W(1.0), 0.0);
  EXPECT_EQ(PressureKernel(h).W(1.0), 0.0);
  // Peak values: C/6 (cubic) and C (poly6).
  EXPECT_DOUBLE_EQ(CubicKernel(h).W(0), (48 / std::numbers::pi) / (h * h * h) / 6);
  EXPECT_DOUBLE_EQ(DensityKernel(h).W(0), 315 / (64 * std::numbers::pi * h * h * h));
}

}  // namespace
}  // namespace sinew::sph
