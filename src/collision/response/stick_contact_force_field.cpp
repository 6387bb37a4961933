// StickContactForceField response (SOFA's BarycentricStickContact; spec/
// interaction.md §4): the contact points of a colliding pair are tied by a
// VectorSpringForceField, one spring per kept output (one per id, the first
// of smallest value) from point 1 to point 2, at rest at their offset of the
// detection, of stiffness contactStiffness1 + contactStiffness2 and damping
// contactFriction1 + contactFriction2 (sums, as SOFA).
//
// keepAlive (responseParams "keepAlive=0|1", default true): the contact
// outlives the collision; a step without outputs leaves the springs as they
// were, so the surfaces pulled apart are pulled back (the stick).
#include <memory>
#include <string>

#include "collision/contact_manager.h"
#include "collision/response/contact.h"
#include "collision/response/contact_mapper.h"
#include "collision/response/outputs_by_id.h"
#include "core/parse.h"
#include "core/registry.h"
#include "forcefield/spring/vector_spring_force_field.h"

namespace sinew {

namespace {

class StickSpringContact final : public Contact {
 public:
  StickSpringContact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method)
      : Contact(m1, m2, method), mapper1_(m1, m1.name.value() + "-stick1"), mapper2_(m2, m2.name.value() + "-stick2") {}

  bool set_param(const std::string& name, const std::string& value, std::string& error) override {
    if (name == "keepAlive") {
      if (parse::read(value, keep_alive_)) return true;
      error = "StickContactForceField: cannot read keepAlive = \"" + value + "\"";
      return false;
    }
    error = "StickContactForceField has no parameter '" + name + "' (keepAlive)";
    return false;
  }

  bool keep_alive() const override { return keep_alive_; }

  void set_detection_outputs(std::vector<DetectionOutput>& outputs) override {
    if (outputs.empty()) return;  // kept alive without outputs: SOFA passes none, the springs stay
    if (!ff_ && !detached_) {
      detached_ = std::make_unique<VectorSpringForceField>();
      detached_->name.set(m1_->name.value() + "-" + m2_->name.value());
      detached_->set_type("VectorSpringForceField", "Vec3d");
      detached_->bind(*mapper1_.state(), *mapper2_.state());
      detached_->mark_initialised();
    }
    VectorSpringForceField& ff = ff_ ? *ff_ : *detached_;
    keep_smallest_per_id(outputs, by_id_, kept_);
    ff.clear_springs(kept_.size());
    mapper1_.resize(kept_.size());
    mapper2_.resize(kept_.size());
    const double ks = m1_->contact_stiffness.value() + m2_->contact_stiffness.value();
    const double kd = m1_->contact_friction.value() + m2_->contact_friction.value();
    for (std::size_t i : kept_) {
      const DetectionOutput& o = outputs[i];
      double r1 = 0, r2 = 0;
      VectorSpringForceField::Spring s;
      s.m1 = mapper1_.add_point(o.point1, o.elem1, r1);
      s.m2 = mapper2_.add_point(o.point2, o.elem2, r2);
      s.ks = ks;
      s.kd = kd;
      for (int c = 0; c < 3; ++c) s.rest[c] = o.point2[c] - o.point1[c];
      ff.add_spring(s);
    }
    if (!kept_.empty() && ff.stiffness.value() != ks) ff.stiffness.set(ks);  // SOFA shows the last stiffness
    mapper1_.update();
    mapper2_.update();
    ff.springs_set();
  }

  void create_response(Node& where) override {
    if (!ff_ && !detached_) return;
    ff_ = attach_response(where, ff_, detached_);
  }

  Component* response() const override { return ff_; }

  void cleanup() override {
    if (ff_ && ff_->node()) ff_->node()->remove_object(ff_);
    ff_ = nullptr;
    detached_.reset();
    mapper1_.cleanup();
    mapper2_.cleanup();
  }

  std::size_t count() const override { return ff_ ? ff_->spring_list().size() : 0; }

 private:
  bool keep_alive_ = true;
  ContactMapper mapper1_, mapper2_;
  VectorSpringForceField* ff_ = nullptr;  // owned by the graph once attached
  std::unique_ptr<VectorSpringForceField> detached_;
  std::vector<std::size_t> kept_;
  std::vector<std::pair<std::int64_t, std::size_t>> by_id_;
};

}  // namespace

// Not a scene component: registers the response with the contact managers.
void register_stick_contact_force_field(Registry& r) {
  (void)r;
  add_contact_response("StickContactForceField",
                       [](CollisionModelBase& a, CollisionModelBase& b, const Intersection& m) -> std::unique_ptr<Contact> {
                         return std::make_unique<StickSpringContact>(a, b, m);
                       });
}

}  // namespace sinew
