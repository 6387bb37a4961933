// The 6×6 elasticity tensors SOFA's StandardTetrahedralFEMForceField uses
// (each material's ElasticityTensor): T = 2·∂S/∂C in the storage order of C
// (00, 01, 11, 02, 12, 22), a column per storage direction (off-diagonal
// directions moving both symmetric entries). SOFA writes T out per material;
// the expressions are evaluated here in its order, entry by entry, so that the
// tangent agrees with SOFA's to the last bit and not only to round-off (which
// matters where the linear solver stops before convergence).
#pragma once

#include "forcefield/hyperelastic/hyperelastic_materials.h"

namespace sinew::hyper {

// SOFA's closed form for StVenantKirchhoff, NeoHookean, MooneyRivlin and ArrudaBoyce; for the
// other materials T is assembled from dstress (same values to round-off). False when the
// tangent cannot be formed (prepare_tangent failed).
bool elasticity_tensor(Material m, const Strain& s, const double* p, TangentCache& cache, double T[6][6]);

}  // namespace sinew::hyper
