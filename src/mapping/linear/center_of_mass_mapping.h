// CenterOfMassMapping: one output point at the centre of mass of the input
// frames, x = Σ m_i c_i / M (SOFA's Sofa.Component.Mapping.Linear). Inputs
// Rigid3d (output Vec3d) and Rigid2d (output Vec2d); m_i are the element masses
// of the mass in the input's node, M their total at init.
//
// - Only the output's first DoF is written (SOFA's: the output is meant to hold
//   one point); an empty output gets one.
// - J: the first output row has m_i/M·I on each frame's translation; applyJ
//   sums m_i·v_i then divides by M, applyJT adds f·(m_i/M), as SOFA.
// - SOFA gives no constraint Jacobian (it only warns): constraints are not
//   carried through this mapping either (one warning).
// - The element masses are the translational diagonal entries of the mass's
//   matrix (SOFA's getElementMass), read at init and at every position apply.
// - No mass in the input's node, or a zero total: the mapping is invalid
//   (SOFA logs an error at every apply and leaves the output alone).
#pragma once

#include "core/matrix_sink.h"
#include "mapping/mapping_base.h"

namespace sinew {

class CenterOfMassMapping final : public MappingBase {
 public:
  CenterOfMassMapping(StateType in, StateType out) : MappingBase(in, out) {}

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool apply_jt_constraints() override;

  double total_mass() const { return total_; }

 protected:
  bool init_mapping() override;

 private:
  bool read_masses();

  std::vector<double> m_;  // element mass per input frame
  double total_ = 0;
  int cw_ = 7, dw_ = 6, dim_ = 3;
  bool warned_constraints_ = false;
  MatrixSink mass_sink_;
};

}  // namespace sinew
