#include "forcefield/fem/beam_fem.h"

namespace sinew::beam {

Mat12 local_stiffness(const BeamSection& s) {
  const double L = s.L, L2 = L * L, L3 = L2 * L;
  const double EIy = s.E * s.Iy, EIz = s.E * s.Iz;
  // Shear-deformation parameters (0 without shear areas).
  const double phiy = s.Asy == 0 ? 0.0 : 24.0 * (1.0 + s.nu) * s.Iz / (s.Asy * L2);
  const double phiz = s.Asz == 0 ? 0.0 : 24.0 * (1.0 + s.nu) * s.Iy / (s.Asz * L2);
  Mat12 k{};
  auto at = [&k](int i, int j) -> double& { return k[i * 12 + j]; };
  at(0, 0) = at(6, 6) = s.E * s.A / L;
  at(1, 1) = at(7, 7) = 12.0 * EIz / (L3 * (1.0 + phiy));
  at(2, 2) = at(8, 8) = 12.0 * EIy / (L3 * (1.0 + phiz));
  at(3, 3) = at(9, 9) = s.G * s.J / L;
  at(4, 4) = at(10, 10) = (4.0 + phiz) * EIy / (L * (1.0 + phiz));
  at(5, 5) = at(11, 11) = (4.0 + phiy) * EIz / (L * (1.0 + phiy));
  at(4, 2) = -6.0 * EIy / (L2 * (1.0 + phiz));
  at(5, 1) = 6.0 * EIz / (L2 * (1.0 + phiy));
  at(6, 0) = -at(0, 0);
  at(7, 1) = -at(1, 1);
  at(7, 5) = -at(5, 1);
  at(8, 2) = -at(2, 2);
  at(8, 4) = -at(4, 2);
  at(9, 3) = -at(3, 3);
  at(10, 2) = at(4, 2);
  at(10, 4) = (2.0 - phiz) * EIy / (L * (1.0 + phiz));
  at(10, 8) = -at(4, 2);
  at(11, 1) = at(5, 1);
  at(11, 5) = (2.0 - phiy) * EIz / (L * (1.0 + phiy));
  at(11, 7) = -at(5, 1);
  for (int i = 0; i <= 10; ++i)
    for (int j = i + 1; j < 12; ++j) at(i, j) = at(j, i);
  return k;
}

}  // namespace sinew::beam
