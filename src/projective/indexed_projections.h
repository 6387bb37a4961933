// Point, line and plane projective constraints (spec/mechanics.md §4).
//
// Listed DoFs are kept on a point, a line or a plane: derivatives and
// velocities are multiplied by a 3×3 projector per DoF (n·nᵀ for a line,
// I − n·nᵀ for a plane, 0 for a point) and positions are projected after
// each step. Vec3d only, as the scenes use them.
//
// Point removals (SOFA's TopologySubsetIndices on `indices`): the positions
// follow the renumbered list; so do the responses of the point and line
// constraints (SOFA's point reads the list, its line rebuilds its matrix when
// the state size changed), while the plane keeps projecting the DoF numbers of
// init (SOFA's plane never rebuilds its matrix).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/node.h"
#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

// Common part: `indices` (default [0]) checked against the state size.
class IndexedProjection : public ProjectiveConstraint {
 public:
  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the projected DoFs (default: 0)",
                                       "Constraint"};
  Field<double> draw_size{this, "drawSize", 0.0, "point size (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override {
    ProjectiveConstraint::init();
    if (state() != ComponentState::valid) return;
    active_.clear();
    for (unsigned i : indices.get()) {
      if (i >= mstate->size()) {
        msg_error("index " + std::to_string(i) + " is not valid (the state has " + std::to_string(mstate->size()) +
                  " DoFs)");
        continue;
      }
      active_.push_back(i);
    }
    placed_ = active_;
    if (renumbers_response()) follow_.bind(&indices, {&active_, &placed_});
    else follow_.bind(&indices, {&placed_});
    follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
    reinit();
  }

 protected:
  // v_i ← P·v_i for listed DoFs, rows summed left to right as a sparse product does.
  void project(int id, const Mat3& P) {
    auto v = as_vec3(mstate->write(id));
    for (unsigned i : active_) {
      if (i >= v.size()) continue;  // numbered before points were removed
      const Vec3 in = v[i];
      for (int r = 0; r < 3; ++r) v[i][r] = P(r, 0) * in[0] + P(r, 1) * in[1] + P(r, 2) * in[2];
    }
  }
  // Whether the response follows point removals (else it keeps the DoF numbers of init).
  virtual bool renumbers_response() const { return true; }
  std::vector<unsigned> active_;  // DoFs whose responses are projected
  std::vector<unsigned> placed_;  // DoFs whose positions are projected (the renumbered list)
  SubsetIndicesFollower follow_;
  // SOFA's line and plane projections do not project constraint rows: they say so and keep them.
  void rows_not_projected(const ConstraintMatrix& J) {
    if (J.empty() || warned_rows_) return;
    warned_rows_ = true;
    msg_error("cannot project Lagrangian constraint rows (SOFA does not either); the rows on its DoFs are kept");
  }
  bool warned_rows_ = false;
};

class PointProjectiveConstraint final : public IndexedProjection {
 public:
  Field<Vec3> point{this, "point", Vec3::Zero(), "target of the projection", "Constraint"};
  Field<bool> fix_all{this, "fixAll", false, "project every DoF", "Constraint"};

  void project_response(int dx) override {
    auto v = as_vec3(mstate->write(dx));
    if (fix_all.value()) {
      for (Vec3& x : v) x.setZero();
    } else {
      for (unsigned i : active_)
        if (i < v.size()) v[i].setZero();
    }
  }
  void project_velocity(int v, double) override { project_response(v); }
  void project_jacobian(ConstraintMatrix& J) override {
    if (fix_all.value()) return J.zero_all();
    for (unsigned i : active_) J.zero_dof(static_cast<int>(i), 0, J.width());
  }
  void project_position(int x, double) override {
    auto p = as_vec3(mstate->write(x));
    if (fix_all.value()) {
      for (Vec3& q : p) q = point.value();
    } else {
      for (unsigned i : active_)
        if (i < p.size()) p[i] = point.value();
    }
  }
  bool dirichlet_indices(std::vector<std::size_t>& out) override {
    if (fix_all.value()) {
      for (std::size_t i = 0; i < mstate->size() * 3; ++i) out.push_back(i);
    } else {
      for (unsigned i : active_)
        for (int c = 0; c < 3; ++c) out.push_back(i * 3 + c);
    }
    return true;
  }
};

class LineProjectiveConstraint final : public IndexedProjection {
 public:
  Field<Vec3> origin{this, "origin", Vec3::Zero(), "a point of the line", "Constraint"};
  Field<Vec3> direction{this, "direction", Vec3::Zero(), "direction of the line (normalised at init)", "Constraint"};

  void reinit() override {
    Vec3 n = direction.value();
    const double len = n.norm();
    if (len == 0) n[0] = 1;  // arbitrary direction
    else n *= 1 / len;
    direction.set(n);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P_(i, j) = n[i] * n[j];
  }
  void project_response(int dx) override { project(dx, P_); }
  void project_jacobian(ConstraintMatrix& J) override { rows_not_projected(J); }
  void project_velocity(int v, double) override { project(v, P_); }
  void project_position(int x, double) override {
    auto p = as_vec3(mstate->write(x));
    const Vec3 n = direction.value(), o = origin.value();
    for (unsigned i : placed_) {
      if (i >= p.size()) continue;
      const Vec3 d = p[i] - o;
      p[i] = o + n * (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    }
  }

 private:
  Mat3 P_ = Mat3::Identity();
};

class PlaneProjectiveConstraint final : public IndexedProjection {
 public:
  Field<Vec3> origin{this, "origin", Vec3::Zero(), "a point of the plane", "Constraint"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "normal of the plane (normalised at init)", "Constraint"};

  void reinit() override {
    Vec3 n = normal.value();
    const double len = n.norm();
    if (len != 0) n *= 1 / len;  // a zero normal stays zero, as in SOFA
    normal.set(n);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P_(i, j) = (i == j ? 1.0 : 0.0) - n[i] * n[j];
  }
  void project_response(int dx) override { project(dx, P_); }
  void project_jacobian(ConstraintMatrix& J) override { rows_not_projected(J); }
  void project_velocity(int v, double) override { project(v, P_); }
  bool renumbers_response() const override { return false; }
  void project_position(int x, double) override {
    auto p = as_vec3(mstate->write(x));
    const Vec3 n = normal.value(), o = origin.value();
    for (unsigned i : placed_) {
      if (i >= p.size()) continue;
      const Vec3 d = p[i] - o;
      p[i] = p[i] - n * (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    }
  }

 private:
  Mat3 P_ = Mat3::Identity();
};

}  // namespace sinew
