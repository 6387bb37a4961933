// SPHFluidForceField (SofaSphFluid): smoothed particle hydrodynamics forces
// between the particles of a Vec3d state (spec/interaction.md §8): density by
// kernel summation, pressure k(ρ − ρ0), pressure forces with the spiky (or
// cubic) gradient, viscosity by the kernel Laplacian or as Monaghan's
// artificial viscosity, surface tension from the colour field.
//
// Each add_force finds the neighbour pairs (q = r/h < 1) — through the
// node's SpatialGridContainer when there is one, else by brute force —
// stores each pair once in compressed rows under its lower index, then sums in
// SOFA's order. The force is explicit: add_dforce adds nothing (SOFA's
// derivative list is never filled), even under an implicit solver. `mass` is
// the SPH particle mass, independent of the node's mass component.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/roles.h"
#include "sph/spatial_grid.h"

namespace sinew {

class SpatialGridContainer;

class SPHFluidForceField final : public ForceField {
 public:
  Field<double> radius{this, "radius", 1.0, "smoothing radius h of a particle", "SPH", "length"};
  Field<double> mass{this, "mass", 1.0, "SPH mass of a particle", "SPH", "mass"};
  Field<double> pressure{this, "pressure", 100.0, "pressure stiffness k (p = k(ρ − ρ0))", "SPH"};
  Field<double> density{this, "density", 1.0, "rest density ρ0", "SPH", "mass/length³"};
  Field<double> viscosity{this, "viscosity", static_cast<double>(0.001f), "viscosity μ (0: none)", "SPH"};
  Field<double> surface_tension{this, "surfaceTension", 0.0, "surface tension σ (<= 0: none)", "SPH"};
  Field<int> kernel_type{this, "kernelType", 0, "0: poly6/spiky/viscosity kernels, 1: cubic spline", "SPH"};
  Field<int> pressure_type{this, "pressureType", 1, "0: none, 1: default pressure (SOFA reads it nowhere)", "SPH"};
  Field<int> viscosity_type{this, "viscosityType", 1,
                            "0: none, 1: kernel Laplacian, 2: artificial viscosity", "SPH"};
  Field<int> surface_tension_type{this, "surfaceTensionType", 1,
                                  "0: none, 1: colour-field Laplacian, 2: cohesion (adds nothing, as SOFA)", "SPH"};
  Field<bool> debug_grid{this, "debugGrid", false,
                         "also find the pairs by brute force and report where the grid differs", "SPH"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

  // Per-particle results of the last add_force (density ρ, pressure p).
  const std::vector<double>& densities() const { return density_; }
  const std::vector<double>& pressures() const { return pressure_; }
  // Neighbour pairs of the last add_force: row i lists (j > i, q = r/h) in
  // [row_start()[i], row_start()[i + 1]); the vectors have spare slots past the last pair.
  std::size_t pair_count() const { return row_start_.empty() ? 0 : row_start_.back(); }
  const std::vector<std::uint32_t>& row_start() const { return row_start_; }
  const std::vector<std::uint32_t>& neighbours() const { return nb_j_; }
  const std::vector<double>& neighbour_q() const { return nb_q_; }

 private:
  // Slots past the last pair in nb_j_ and nb_q_ (4-wide passes over the rows).
  static constexpr std::size_t kPairPad = 4;

  void find_neighbours(const std::vector<double>& x);
  // r² of each pair into nb_q_ (the search does not keep it; see sph::PairBuffer).
  void squared_distances(const std::vector<double>& x);
  template <class Kd, class Kp, class Kv, class Kc>
  void compute_force(const std::vector<double>& x, const std::vector<double>& v, std::vector<double>& f);

  SpatialGridContainer* grid_ = nullptr;  // found each step in the node (see find_neighbours)
  // Pairs as the grid finds them, then sorted by row (stable) into CSR: row i
  // lists (j > i, q = r/h).
  sph::PairBuffer found_;
  std::vector<std::uint32_t> row_start_, nb_j_;
  std::vector<double> nb_q_;
  std::vector<double> density_, pressure_, normal_, curvature_, p_over_rho2_;
  std::vector<double> pair_w_, pair_g_;  // per pair: m·W(q), the pressure kernel's gradient scalar
  std::vector<double> records_;          // scratch of the SIMD passes (sph_pair_forces.h)
  bool warned_kernel_ = false;
};

}  // namespace sinew
