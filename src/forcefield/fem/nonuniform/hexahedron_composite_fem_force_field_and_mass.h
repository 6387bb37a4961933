// HexahedronCompositeFEMForceFieldAndMass: NonUniformHexahedronFEMForceFieldAndMass
// whose coarse cells are homogenized from composite material (Nesme, Kry, Jeřábková,
// Faure, SIGGRAPH 2009, as SOFA's FEM/NonUniform implements it). On a ramified sparse
// grid with virtual finer levels (SparseGridMultipleTopology: one stiffness per
// material file), each cell's 2×2×2 finer cells are assembled on the 27 nodes of the
// cell, the 8 corners held and the rest solved for statically (empty octants filled
// with a very stiff cube), which gives the fine displacements as weights W of the
// corner displacements. W is masked to the trilinear support of each fine node (an
// edge node moves with its edge, a face node with its face), its rows normalised to
// sum 1, and the cell's matrices are Wᵀ·K·W and Wᵀ·M·W; level by level down to the
// finest level used. The products of the W's down the levels (final_weights()) let
// HexahedronCompositeFEMMapping move points with the fine displacements.
//
// Modes: SOFA's examples use the ramified path (useRamification, the default, on a
// SparseGridRamificationTopology or SparseGridMultipleTopology) and, with
// nbVirtualFinerLevels = 0, the classical matrices. The others (finestToCoarse, the
// unramified path, homogenizationMethod ≠ 0) are refused with an error.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "forcefield/fem/nonuniform/nonuniform_hexahedron_fem_force_field_and_mass.h"

namespace sinew {

class HexahedronCompositeFEMForceFieldAndMass final : public NonUniformHexahedronFEMForceFieldAndMass {
 public:
  Field<bool> finest_to_coarse{this, "finestToCoarse", false,
                               "homogenize from the finest level directly to the coarse one (not supported)",
                               "Mass"};
  Field<int> homogenization_method{this, "homogenizationMethod", 0,
                                   "0: static (the only one SOFA computes), 1: constrained static, 2: modal",
                                   "Mass"};
  Field<bool> complete_interpolation{this, "completeInterpolation", false,
                                     "the mapping moves points with the complete (unmasked) weights", "Mass"};
  Field<bool> use_ramification{this, "useRamification", true,
                               "follow the ramifications of a SparseGridRamificationTopology", "Mass"};
  Field<int> draw_type{this, "drawType", 0, "drawing of the weights (viewer)", "Visualization"};
  Field<int> draw_color{this, "drawColor", 0, "colour of the drawing (viewer)", "Visualization"};
  Field<float> draw_size{this, "drawSize", -1.0f, "size of the drawing; -1: 0.4 % of the grid's width", "Visualization"};

  using Weight = Eigen::Matrix<double, 24, 24>;
  // For each hexahedron of the finest level used (level nbVirtualFinerLevels of the grid): the
  // coarse hexahedron it lies in and the weights u_fine (its 8 corners × 3) = W · u_coarse (the
  // coarse hexahedron's 8 corners × 3, in its frame). SOFA's _finalWeights; a fine hexahedron
  // no coarse one reaches keeps SOFA's default (hexahedron 0, zero weights).
  struct FinalWeight {
    unsigned coarse = 0;
    Weight W = Weight::Zero();
  };
  const std::vector<FinalWeight>& final_weights() const { return final_weights_; }
  // Homogenized mass of element e: one 8×8 nodal matrix per component (row-major), or empty
  // (nbVirtualFinerLevels = 0: element_mass() holds the classical one).
  const std::vector<std::array<std::array<double, 64>, 3>>& component_masses() const { return component_mass_; }

  void init() override;

 protected:
  bool compute_element_matrices(const SparseGridTopology& grid, int levels) override;

 private:
  std::vector<FinalWeight> final_weights_;
};

}  // namespace sinew
