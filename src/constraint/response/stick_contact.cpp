// StickContactConstraint response (spec/interaction.md §4.7): the contact
// points of a colliding pair are glued where they touched, by a Vec3d
// BilateralLagrangianConstraint between the contact points of both sides,
// each pair held at rest vector point2 − point1 (their offset at detection).
//
// keepAlive (responseParams "keepAlive=0|1", default true): the contact, and
// so the glue, outlives the collision: once the pair separates the manager
// passes no outputs and the constraint is kept as it was. While the pair
// collides (or without keepAlive) the pairs are rebuilt from the step's
// outputs, duplicates (both points within 1e-4) dropped as SOFA does.
#include <memory>
#include <string>

#include "collision/contact_manager.h"
#include "collision/intersection.h"
#include "collision/response/contact.h"
#include "collision/response/contact_mapper.h"
#include "constraint/model/bilateral_lagrangian_constraint.h"
#include "constraint/response/distinct_outputs.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

namespace {

class StickContact final : public Contact {
 public:
  StickContact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method)
      : Contact(m1, m2, method), mapper1_(m1, m1.name.value() + "-stick1"), mapper2_(m2, m2.name.value() + "-stick2") {}

  bool set_param(const std::string& name, const std::string& value, std::string& error) override {
    if (name == "keepAlive") {
      if (!parse::read(value, keep_alive_)) {
        error = "StickContactConstraint: cannot read keepAlive = \"" + value + "\"";
        return false;
      }
      return true;
    }
    error = "StickContactConstraint has no parameter '" + name + "' (keepAlive)";
    return false;
  }

  bool keep_alive() const override { return keep_alive_; }

  void set_detection_outputs(std::vector<DetectionOutput>& outputs) override {
    kept_.clear();
    keep_distinct_outputs(outputs, kept_);
    outputs_ = &outputs;
  }

  void create_response(Node& where) override {
    if (!outputs_) return;
    if (!kept_.empty() || !keep_alive_) rebuild();
    if (!constraint_ && !detached_) return;
    constraint_ = attach_response(where, constraint_, detached_);
  }

  Component* response() const override { return constraint_; }

  void cleanup() override {
    if (constraint_ && constraint_->node()) constraint_->node()->remove_object(constraint_);
    constraint_ = nullptr;
    detached_.reset();
    mapper1_.cleanup();
    mapper2_.cleanup();
  }

  std::size_t count() const override {
    return constraint_ ? std::min(constraint_->first_point.value().size(), constraint_->second_point.value().size())
                       : 0;
  }

 private:
  // The pairs from this step's kept outputs (SOFA's activateMappers + addContact).
  void rebuild() {
    if (!constraint_ && !detached_) {
      detached_ = std::make_unique<BilateralLagrangianConstraint>(StateType::vec3);
      detached_->name.set(m1_->name.value() + "-" + m2_->name.value());
      detached_->set_type("BilateralLagrangianConstraint", "Vec3d");
      detached_->set_states(*mapper1_.state(), *mapper2_.state());
      detached_->init();
      detached_->mark_initialised();
    }
    BilateralLagrangianConstraint& c = constraint_ ? *constraint_ : *detached_;
    const std::vector<DetectionOutput>& outputs = *outputs_;
    c.clear_pairs();
    mapper1_.resize(kept_.size());
    mapper2_.resize(kept_.size());
    mapped_.clear();
    for (std::size_t i : kept_) {
      const DetectionOutput& o = outputs[i];
      double r1 = 0, r2 = 0;  // radii: a bilateral constraint has no distance to keep
      const unsigned i1 = mapper1_.add_point(o.point1, o.elem1, r1);
      const unsigned i2 = mapper2_.add_point(o.point2, o.elem2, r2);
      mapped_.push_back({i1, i2});
    }
    mapper1_.update();
    mapper1_.update_xfree();
    mapper2_.update();
    mapper2_.update_xfree();
    for (std::size_t k = 0; k < kept_.size(); ++k) {
      const DetectionOutput& o = outputs[kept_[k]];
      c.add_contact(mapped_[k].first, mapped_[k].second, o.point2 - o.point1);
    }
  }

  bool keep_alive_ = true;
  ContactMapper mapper1_, mapper2_;
  BilateralLagrangianConstraint* constraint_ = nullptr;  // owned by the graph once attached
  std::unique_ptr<BilateralLagrangianConstraint> detached_;
  const std::vector<DetectionOutput>* outputs_ = nullptr;
  std::vector<std::size_t> kept_;
  std::vector<std::pair<unsigned, unsigned>> mapped_;
};

}  // namespace

// Not a scene component: registers the response with the contact managers.
void register_stick_contact(Registry& r) {
  (void)r;
  add_contact_response("StickContactConstraint",
                       [](CollisionModelBase& a, CollisionModelBase& b, const Intersection& m) -> std::unique_ptr<Contact> {
                         return std::make_unique<StickContact>(a, b, m);
                       });
}

}  // namespace sinew
