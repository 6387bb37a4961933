#include "viewer/mouse_attach.h"

#include "collision/response/contact_mapper.h"
#include "core/matrix_sink.h"
#include "core/node.h"

namespace sinew::viewer {

MouseSpring::MouseSpring(MechanicalState& state, unsigned index, double stiffness) : index_(index), k_(stiffness) {
  mstate.set(&state);
  set_type("SpringForceField", "Vec3d");
  name.set("Spring-Mouse-Contact");
}

void MouseSpring::add_force(const MechParams& p) {
  MechanicalState& s = *mstate.get();
  const std::vector<double>& x = s.read(vec_for(s, p.x, kPosition));
  std::vector<double>& f = s.write(vec_for(s, p.f, kForce));
  if (3 * index_ + 2 >= x.size() || 3 * index_ + 2 >= f.size()) return;  // the state shrank under the mouse
  for (int d = 0; d < 3; ++d) f[3 * index_ + d] += k_ * (target_[d] - x[3 * index_ + d]);
}

void MouseSpring::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate.get();
  const std::vector<double>& dx = s.read(vec_for(s, p.dx, kDx));
  std::vector<double>& df = s.write(vec_for(s, p.df, kDforce));
  if (3 * index_ + 2 >= dx.size() || 3 * index_ + 2 >= df.size()) return;
  for (int d = 0; d < 3; ++d) df[3 * index_ + d] -= kfactor * k_ * dx[3 * index_ + d];
}

bool MouseSpring::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  for (int d = 0; d < 3; ++d) K.add(s, 3 * index_ + d, s, 3 * index_ + d, -k_);
  return true;
}

std::optional<double> MouseSpring::potential_energy() const {
  const std::vector<double>& x = mstate.get()->read(kPosition);
  if (3 * index_ + 2 >= x.size()) return 0.0;
  return 0.5 * k_ * (target_ - Vec3(&x[3 * index_])).squaredNorm();
}

MouseAttach::MouseAttach() = default;

MouseAttach::~MouseAttach() { stop(); }

bool MouseAttach::start(const Pick& p, double stiffness, std::string* why) {
  stop();
  if (!(stiffness > 0)) {
    if (why) *why = "the mouse spring's stiffness must be positive";
    return false;
  }
  MechanicalState* state = nullptr;
  unsigned index = 0;
  if (p.on == Pick::On::collision_element) {
    mapper_ = std::make_unique<ContactMapper>(*p.model, "AttachedPoint");
    state = mapper_->state();
    if (!state) {
      if (why) *why = "the picked collision model has no state to attach to";
      mapper_.reset();
      return false;
    }
    mapper_->resize(1);
    double radius = 0;
    index = mapper_->add_point(p.point, p.element, radius);
    mapper_->update();
  } else if (p.on == Pick::On::particle) {
    state = p.state;
    index = p.index;
  } else {
    if (why) *why = "nothing under the cursor";
    return false;
  }
  Node* node = state ? state->node() : nullptr;
  if (!node || state->state_type() != StateType::vec3) {
    if (why) *why = "the picked body has no Vec3d state to attach a spring to";
    mapper_.reset();
    return false;
  }
  auto spring = std::make_unique<MouseSpring>(*state, index, stiffness);
  // The mouse starts where the picked point is: a rest length of zero, no jump.
  const std::vector<double>& x = state->read(kPosition);
  spring->set_target(3 * index + 2 < x.size() ? Vec3(&x[3 * index]) : p.point);
  spring_ = static_cast<MouseSpring*>(node->add_object(std::move(spring)));
  if (!spring_) {
    if (why) *why = "the graph refused the mouse spring";
    if (mapper_) mapper_->cleanup();
    mapper_.reset();
    return false;
  }
  state_ = state;
  return true;
}

void MouseAttach::move(const Vec3& target) {
  if (spring_) spring_->set_target(target);
}

void MouseAttach::stop() {
  if (spring_ && spring_->node()) spring_->node()->remove_object(spring_);
  spring_ = nullptr;
  state_ = nullptr;
  if (mapper_) mapper_->cleanup();
  mapper_.reset();
}

Vec3 MouseAttach::attached_point() const {
  if (!spring_ || !state_) return Vec3::Zero();
  const std::vector<double>& x = state_->read(kPosition);
  const unsigned i = spring_->index();
  return 3 * i + 2 < x.size() ? Vec3(&x[3 * i]) : Vec3::Zero();
}

Vec3 MouseAttach::target() const { return spring_ ? spring_->target() : Vec3::Zero(); }

}  // namespace sinew::viewer
