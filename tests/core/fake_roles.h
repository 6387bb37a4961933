// Minimal implementations of core roles for the core tests: enough to be
// filed in a node's slots and gathered by traversals, with no behaviour.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew::fakes {

// A state of the given type holding no point.
class TestState final : public MechanicalState {
 public:
  explicit TestState(StateType t = StateType::vec3) : type_(t) {}
  StateType state_type() const override { return type_; }
  std::size_t size() const override { return 0; }
  void resize(std::size_t) override {}
  void remove_points(const std::vector<unsigned>&) override {}
  void add_points(std::size_t, const std::vector<std::vector<unsigned>>&, const std::vector<std::vector<double>>&) override {}
  bool has_vec(int) const override { return false; }
  const std::vector<double>& read(int) const override { return data_; }
  std::vector<double>& write(int) override { return data_; }
  void touch(int) override {}
  void add_deriv_to_coord(int, int, int, double) override {}
  void end_integration() override {}

 private:
  StateType type_;
  std::vector<double> data_;
};

// An ODE solver that does nothing.
class TestSolver final : public OdeSolver {
 public:
  void solve(double, int, int) override {}
};

}  // namespace sinew::fakes
