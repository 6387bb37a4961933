// ContactMapping: the mapping of contact points onto the elements of a
// collision model (SOFA's BarycentricContactMapper with its mesh-topology
// barycentric mapper, spec/interaction.md §4.3). Each output point is a
// weighted sum of up to four input points (line: 2, triangle: 3, quad: 4).
// Created by the contact response, never by a scene file.
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew {

class ContactMapping final : public Mapping {
 public:
  struct Point {
    std::array<unsigned, 4> v{};
    std::array<double, 4> w{};
    int n = 0;
  };

  ContactMapping(MechanicalState& in, MechanicalState& out) : in_(&in), out_(&out) {}

  std::vector<MechanicalState*> inputs() const override { return {in_}; }
  MechanicalState* output() const override { return out_; }

  void clear() { points_.clear(); }
  // Adds an output point; returns its index. The output state is sized by the caller.
  unsigned add(const Point& p) {
    points_.push_back(p);
    return static_cast<unsigned>(points_.size() - 1);
  }
  const std::vector<Point>& points() const { return points_; }

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool has_jt_entry() const override { return true; }
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override {
    if (out_dof >= points_.size()) return;
    const Point& p = points_[out_dof];
    for (int k = 0; k < p.n; ++k) {
      const double t[3] = {v[0] * p.w[k], v[1] * p.w[k], v[2] * p.w[k]};
      sink.add(0, p.v[k], t);
    }
  }

 private:
  MechanicalState* in_;
  MechanicalState* out_;
  std::vector<Point> points_;
};

}  // namespace sinew
