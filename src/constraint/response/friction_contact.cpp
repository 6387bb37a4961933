// FrictionContactConstraint response (spec/interaction.md §4.6): the contact
// of a colliding pair becomes an UnilateralLagrangianConstraint between the
// contact points of both sides (Coulomb friction, coefficient `mu`, set by
// responseParams="mu=…"; 0.8 by default).
//
// AugmentedLagrangianResponseConstraint is the same contact with SOFA's
// AugmentedLagrangianConstraint: mu (0 by default) and epsilon (the penalty
// factor of the augmented Lagrangian steps, 0 by default) from responseParams.
//
// Each step: outputs closer than 1e-8 (squared, both points) to a kept one
// are dropped; the mappers place the contact points on their elements; each
// kept output becomes a contact with distance d0 + r1 + r2 and a persistent
// id cantor(output id, contact serial) (read by the LCP solver's warm start).
#include <memory>
#include <string>

#include "collision/contact_manager.h"
#include "collision/intersection.h"
#include "collision/response/contact.h"
#include "collision/response/contact_mapper.h"
#include "constraint/model/unilateral_lagrangian_constraint.h"
#include "constraint/response/distinct_outputs.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

namespace {

// Cantor pairing f(x, y) = ((x+y)² + 3x + y) / 2, SOFA's persistent contact ids.
std::int64_t cantor(std::int64_t x, std::int64_t y) { return ((x + y) * (x + y) + 3 * x + y) / 2; }

std::int64_t next_contact_serial() {
  static std::int64_t serial = 0;
  return serial++;
}

class FrictionContact final : public Contact {
 public:
  FrictionContact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method, bool augmented)
      : Contact(m1, m2, method),
        augmented_(augmented),
        mu_(augmented ? 0.0 : 0.8),
        self_(&m1 == &m2),
        serial_(next_contact_serial()),
        mapper1_(m1, m1.name.value() + "-constraints"),
        mapper2_(m2, m2.name.value() + "-constraints") {}

  bool set_param(const std::string& name, const std::string& value, std::string& error) override {
    const char* response = augmented_ ? "AugmentedLagrangianResponseConstraint" : "FrictionContactConstraint";
    double* slot = name == "mu" ? &mu_ : name == "tol" ? &tol_ : (augmented_ && name == "epsilon") ? &epsilon_ : nullptr;
    if (!slot) {
      error = std::string(response) + " has no parameter '" + name + "' (" + (augmented_ ? "mu, epsilon, tol" : "mu, tol") +
              ")";
      return false;
    }
    if (!parse::read(value, *slot)) {
      error = std::string(response) + ": cannot read " + name + " = \"" + value + "\"";
      return false;
    }
    return true;
  }

  void set_detection_outputs(std::vector<DetectionOutput>& outputs) override {
    kept_.clear();
    if (m1_->contact_stiffness.value() == 0.0 || m2_->contact_stiffness.value() == 0.0) {
      if (!warned_stiffness_) {
        warned_stiffness_ = true;
        m1_->msg_error("contactStiffness 0 on " + m1_->describe() + " or " + m2_->describe() +
                       ": their friction contacts are disabled");
      }
      return;
    }
    keep_distinct_outputs(outputs, kept_);
    outputs_ = &outputs;
  }

  void create_response(Node& where) override {
    if (!outputs_) return;
    if (!constraint_ && !detached_) {
      MechanicalState* s1 = mapper1_.state();
      MechanicalState* s2 = self_ ? s1 : mapper2_.state();
      detached_ = std::make_unique<UnilateralLagrangianConstraint>(*s1, *s2);
      detached_->name.set(m1_->name.value() + "-" + m2_->name.value());
      detached_->set_type(augmented_ ? "AugmentedLagrangianConstraint" : "UnilateralLagrangianConstraint", "Vec3d");
      detached_->custom_tolerance = tol_;
      detached_->augmented = augmented_;
      detached_->mark_initialised();
    }
    UnilateralLagrangianConstraint& c = constraint_ ? *constraint_ : *detached_;
    const std::vector<DetectionOutput>& outputs = *outputs_;
    c.clear(kept_.size());
    if (self_) {
      mapper1_.resize(2 * kept_.size());
    } else {
      mapper1_.resize(kept_.size());
      mapper2_.resize(kept_.size());
    }
    const double d0 = method_->contact_distance() + m1_->contact_distance.value() + m2_->contact_distance.value();
    mapped_.clear();
    for (std::size_t i : kept_) {
      const DetectionOutput& o = outputs[i];
      double r1 = 0, r2 = 0;
      const unsigned i1 = mapper1_.add_point(o.point1, o.elem1, r1);
      const unsigned i2 = (self_ ? mapper1_ : mapper2_).add_point(o.point2, o.elem2, r2);
      mapped_.push_back({i1, i2, d0 + r1 + r2});
    }
    mapper1_.update();
    mapper1_.update_xfree();
    if (!self_) {
      mapper2_.update();
      mapper2_.update_xfree();
    }
    for (std::size_t k = 0; k < kept_.size(); ++k) {
      const DetectionOutput& o = outputs[kept_[k]];
      c.add_contact(mu_, o.normal, mapped_[k].distance, static_cast<int>(mapped_[k].i1),
                    static_cast<int>(mapped_[k].i2), cantor(o.id, serial_), o.id, epsilon_);
    }
    constraint_ = attach_response(where, constraint_, detached_);
  }

  Component* response() const override { return constraint_; }

  void cleanup() override {
    if (constraint_ && constraint_->node()) constraint_->node()->remove_object(constraint_);
    constraint_ = nullptr;
    detached_.reset();
    mapper1_.cleanup();
    if (!self_) mapper2_.cleanup();
  }

  std::size_t count() const override { return constraint_ ? constraint_->contacts().size() : 0; }

 private:
  struct Mapped {
    unsigned i1, i2;
    double distance;
  };
  bool augmented_;
  double mu_;
  bool self_;
  std::int64_t serial_;
  double tol_ = 0.0, epsilon_ = 0.0;
  bool warned_stiffness_ = false;
  ContactMapper mapper1_, mapper2_;
  UnilateralLagrangianConstraint* constraint_ = nullptr;  // owned by the graph once attached
  std::unique_ptr<UnilateralLagrangianConstraint> detached_;
  const std::vector<DetectionOutput>* outputs_ = nullptr;
  std::vector<std::size_t> kept_;
  std::vector<Mapped> mapped_;
};

}  // namespace

// Not a scene component: registers the response with the contact managers.
void register_friction_contact(Registry& r) {
  (void)r;
  add_contact_response("FrictionContactConstraint",
                       [](CollisionModelBase& a, CollisionModelBase& b, const Intersection& m) -> std::unique_ptr<Contact> {
                         return std::make_unique<FrictionContact>(a, b, m, false);
                       });
  add_contact_response("AugmentedLagrangianResponseConstraint",
                       [](CollisionModelBase& a, CollisionModelBase& b, const Intersection& m) -> std::unique_ptr<Contact> {
                         return std::make_unique<FrictionContact>(a, b, m, true);
                       });
}

}  // namespace sinew
