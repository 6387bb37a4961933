// SPH smoothing kernels of SofaSphFluid (spec/interaction.md §8), as
// functions of q = r/h. Each kernel keeps its three constants (value,
// gradient, Laplacian) computed once from the support radius h; the gradient
// is returned as the scalar g with ∇W = d·g, d = x_i − x_j (length), so that
// the caller multiplies the difference vector itself. Expressions keep SOFA's
// operation order: the regression digits depend on it.
#pragma once

#include <numbers>

namespace sinew::sph {

// Poly6 (Müller 2003): density and colour field.
struct DensityKernel {
  double cw, cgw, clw;
  explicit DensityKernel(double h)
      : cw(315 / (64 * std::numbers::pi * h * h * h)), cgw(-6 * cw / (h * h)), clw(-6 * cw / (h * h)) {}
  double W(double q) const {
    const double a = 1 - q * q;
    return cw * a * a * a;
  }
  double grad(double q) const {
    const double a = 1 - q * q;
    return cgw * a * a;
  }
  double lap(double q) const {
    const double r2 = q * q;
    return clw * ((1 - r2) * (3 - 7 * r2));
  }
};

// Spiky: pressure. Precondition for grad: q > 0.
struct PressureKernel {
  double cw, cgw;
  explicit PressureKernel(double h) : cw(15 / (std::numbers::pi * h * h * h)), cgw((-3 * cw) / (h * h)) {}
  double W(double q) const {
    const double a = 1 - q;
    return cw * a * a * a;
  }
  double grad(double q) const {
    const double a = 1 - q;
    return cgw * a * a / q;
  }
  double lap(double) const { return 0; }
};

// Viscosity kernel (Laplacian positive everywhere). Precondition: q > 0.
struct ViscosityKernel {
  double cw, cgw, clw;
  explicit ViscosityKernel(double h)
      : cw(15 / (2 * std::numbers::pi * h * h * h)), cgw(cw / (h * h)), clw(6 * cw / (h * h)) {}
  double W(double q) const {
    const double q2 = q * q, q3 = q2 * q;
    return cw * (-0.5 * q3 + q2 + 0.5 / q - 1);
  }
  double grad(double q) const {
    const double q3 = q * q * q;
    return cgw * (2.0 - 1.5 * q - 0.5 / q3);
  }
  double lap(double q) const { return clw * (1 - q); }
};

// Cubic spline (Monaghan), used for every role when kernelType = 1. grad precondition: q > 0.
// Both pieces are computed and one is selected (no branch): callers evaluate it
// over arrays of pairs, where the compiler then vectorizes it.
struct CubicKernel {
  double cw, cgw, clw;
  explicit CubicKernel(double h)
      : cw((48 / std::numbers::pi) / (h * h * h)), cgw(cw / (h * h)), clw(cw / (h * h)) {}
  double W(double q) const {
    const double s = 1 - q;
    const double inner = cw * ((1.0 / 6.0) - q * q + q * q * q);
    const double outer = cw * ((1.0 / 3.0) * (s * s * s));
    return q < 0.5 ? inner : (q < 1 ? outer : 0.0);
  }
  double grad(double q) const {
    const double s = 1 - q;
    const double inner = cgw * (3 * q - 2);
    const double outer = cgw * (-s * s / q);
    return q < 0.5 ? inner : (q < 1 ? outer : 0.0);
  }
  double lap(double q) const {
    const double inner = clw * (12 * q - 6);
    const double outer = clw * (6 - 4 * q - 2 / q);
    return q < 0.5 ? inner : (q < 1 ? outer : 0.0);
  }
};

}  // namespace sinew::sph
