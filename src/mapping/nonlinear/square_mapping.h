// SquareMapping: out_i = x_i² for every scalar of a Vec1d input (SOFA's
// Sofa.Component.Mapping.NonLinear). The output takes the input's size at every
// apply. J = diag(2x) from the last apply; geometric stiffness G = diag(2λ)
// (exact). geometricStiffness is None or Exact (SOFA offers no Stabilized here),
// default Exact.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class SquareMapping final : public MappingBase {
 public:
  SquareMapping() : MappingBase(StateType::vec1, StateType::vec1) {}

  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Exact",
                                         "geometric stiffness: None or Exact (0, 1)", "Mapping"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

 protected:
  bool init_mapping() override;

 private:
  std::vector<double> grad_;  // 2x per input scalar, from the last apply
  int gs_ = 1;
};

}  // namespace sinew
