// CompositeLinearSystem: several assembled linear systems built together,
// one of which is solved (spec/solvers.md §2.9).
//
// `linearSystems` lists the systems; `solverLinearSystem` is the one whose
// matrix and vectors the linear solver uses (added to the list when absent;
// when unset, the first listed system of the composite's template). Building
// the composite builds every listed system in list order, so the others (e.g.
// a stiffness-only or mass-only system) are available for inspection.
#pragma once

#include <vector>

#include "solver/system/matrix_linear_system.h"

namespace sinew {

// A link to several linear systems (space-separated paths).
class LinearSystemListLink final : public BaseLink {
 public:
  using BaseLink::BaseLink;
  bool accept(Base* b) override { return dynamic_cast<MatrixLinearSystem*>(b) != nullptr; }
  Base* target() const override { return targets_.empty() ? nullptr : targets_.front(); }
  std::string type_name() const override { return "multi-link"; }
  bool is_multi() const override { return true; }
  void clear_targets() override { targets_.clear(); }
  void add_target(Base* b) override {
    if (auto* s = dynamic_cast<MatrixLinearSystem*>(b)) targets_.push_back(s);
  }
  bool references(const Base* b) const override {
    for (MatrixLinearSystem* s : targets_)
      if (static_cast<const Base*>(s) == b) return true;
    return false;
  }
  void forget(const Base* b) override { std::erase_if(targets_, [&](MatrixLinearSystem* s) { return static_cast<const Base*>(s) == b; }); }
  const std::vector<MatrixLinearSystem*>& targets() const { return targets_; }

 private:
  std::vector<MatrixLinearSystem*> targets_;
};

class CompositeLinearSystem final : public MatrixLinearSystem {
 public:
  LinearSystemListLink linear_systems{this, "linearSystems", "sub-systems assembled by this composite"};
  Link<MatrixLinearSystem> solver_linear_system{this, "solverLinearSystem", "sub-system handed to the linear solver"};

  void init() override;
  void build_system_matrix(MechanicalOps& ops, double m, double b, double k) override;

  const std::vector<MatrixLinearSystem*>& systems() const { return systems_; }
  MatrixLinearSystem* solver_system() const { return solver_linear_system.get(); }

 private:
  std::vector<MatrixLinearSystem*> systems_;
};

}  // namespace sinew
