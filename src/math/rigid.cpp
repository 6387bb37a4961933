#include "math/rigid.h"

#include <cmath>
#include <limits>

namespace sinew {

void rigid3_add_deriv(const double* c, const double* d, double h, double* out) {
  // Half rotation vector w = h·ω/2; e = (sin|w|/|w|·w, cos|w|), or normalise(w, 1) for tiny |w|.
  const double wx = d[3] * h * 0.5, wy = d[4] * h * 0.5, wz = d[5] * h * 0.5;
  const double theta = std::sqrt(wx * wx + wy * wy + wz * wz);
  double ex, ey, ez, ew;
  if (theta < std::numeric_limits<double>::epsilon()) {
    const double n = std::sqrt(wx * wx + wy * wy + wz * wz + 1.0);
    ex = wx / n, ey = wy / n, ez = wz / n, ew = 1.0 / n;
  } else {
    const double s = std::sin(theta) / theta;
    ex = s * wx, ey = s * wy, ez = s * wz, ew = std::cos(theta);
  }
  const double qx = c[3], qy = c[4], qz = c[5], qw = c[6];
  // Hamilton product e ⊗ q on (x, y, z, w) storage.
  const double rx = ew * qx + ex * qw + ey * qz - ez * qy;
  const double ry = ew * qy + ey * qw + ez * qx - ex * qz;
  const double rz = ew * qz + ez * qw + ex * qy - ey * qx;
  const double rw = ew * qw - (ex * qx + ey * qy + ez * qz);
  out[0] = c[0] + d[0] * h;
  out[1] = c[1] + d[1] * h;
  out[2] = c[2] + d[2] * h;
  out[3] = rx, out[4] = ry, out[5] = rz, out[6] = rw;
}

}  // namespace sinew
