// Penalty contacts (spec/interaction.md §4.4): PenalityContactForceField, an
// interaction force field between the contact points of the two sides, and
// the contact that fills it from the detection outputs.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "collision/response/contact.h"
#include "collision/response/contact_mapper.h"

namespace sinew {

class PenaltyContactForceField final : public ForceField {
 public:
  struct Point {
    unsigned m1, m2;  // contact point indices in state 1 and state 2
    Vec3 normal;      // unit, from side 1 towards side 2
    double dist;      // distance to keep [length]
    double ks;        // stiffness [force/length]
    double pen = 0;   // penetration at the last add_force; the linearisation uses contacts with pen > 0
  };

  PenaltyContactForceField(MechanicalState& s1, MechanicalState& s2, bool fixed1, bool fixed2)
      : s1_(&s1), s2_(&s2), fixed1_(fixed1), fixed2_(fixed2) {}

  void clear(std::size_t reserve) {
    points_.clear();
    points_.reserve(reserve);
  }
  void add_contact(const Point& p) { points_.push_back(p); }
  const std::vector<Point>& points() const { return points_; }

  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override { return {s1_, s2_}; }
  MechanicalState* single_state() const override { return nullptr; }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  // ½·ks·pen² summed over the active contacts (force = −∂E/∂x with the normals frozen).
  std::optional<double> potential_energy() const override;

 private:
  MechanicalState* s1_;
  MechanicalState* s2_;
  // A side whose model is not simulated is an obstacle: never moved, so its
  // positions are read from `position` and it receives no force and no dx.
  bool fixed1_, fixed2_;
  std::vector<Point> points_;
};

class PenaltyContact final : public Contact {
 public:
  PenaltyContact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method);
  ~PenaltyContact() override;

  bool set_param(const std::string& name, const std::string& value, std::string& error) override;
  void set_detection_outputs(std::vector<DetectionOutput>& outputs) override;
  void create_response(Node& where) override;
  Component* response() const override { return ff_; }
  void cleanup() override;
  std::size_t count() const override { return ff_ ? ff_->points().size() : 0; }

 private:
  ContactMapper mapper1_, mapper2_;
  PenaltyContactForceField* ff_ = nullptr;  // owned by the graph once attached
  std::unique_ptr<PenaltyContactForceField> detached_;
  std::vector<std::size_t> kept_;  // outputs kept after de-duplication, in order
  std::vector<std::pair<std::int64_t, std::size_t>> by_id_;
};

}  // namespace sinew
