// IdentityMapping: out_i = in_i (spec/mechanics.md §6.1). The output is
// resized to the input size at init; J is the identity, Jᵀ adds the output
// forces to the input. Between different types the first min(N_in, N_out)
// scalars of each element are copied (Rigid3d → Vec3d: the centre and the
// linear velocity). Visual models (OglModel) are accepted as outputs.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class IdentityMapping final : public MappingBase {
 public:
  IdentityMapping(StateType in, StateType out) : MappingBase(in, out) {}

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool has_jt_entry() const override { return dwi_ == dwo_; }
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override { sink.add(0, out_dof, v); }
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool same_topology() const override { return true; }

 protected:
  bool init_mapping() override;

 private:
  int cwi_ = 3, cwo_ = 3, dwi_ = 3, dwo_ = 3;  // scalars per coordinate / derivative, input and output
};

}  // namespace sinew
