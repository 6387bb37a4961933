// Rigid-body coordinate arithmetic on flat arrays, as SOFA's Rigid3 types:
// coordinates (x y z qx qy qz qw), derivatives (vx vy vz ωx ωy ωz) with ω in
// the world frame.
#pragma once

namespace sinew {

// out = c + h·d: centre moved by h·v; orientation rotated by the world-frame
// exponential of h·ω (left multiplication), not renormalised. `out` may alias `c`.
void rigid3_add_deriv(const double* c, const double* d, double h, double* out);

}  // namespace sinew
