#include "mapping/mapping_base.h"

#include <algorithm>

#include "core/node.h"
#include "core/path.h"
#include "core/value_text.h"

namespace sinew {

StateLink::StateLink(Base* owner, std::string name, std::string help, bool multi, bool allow_visual)
    : BaseLink(owner, std::move(name), std::move(help)), multi_(multi), allow_visual_(allow_visual) {}

bool StateLink::accept(Base* b) {
  const bool ok =
      dynamic_cast<MechanicalState*>(b) != nullptr || (allow_visual_ && dynamic_cast<VisualState*>(b) != nullptr);
  // Single links remember the last accepted candidate (the builder calls accept on the result);
  // multi-links only type-check here and receive their targets through add_target.
  if (ok && !multi_) targets_.assign(1, b);
  return ok;
}

bool StateLink::references(const Base* b) const {
  return std::find(targets_.begin(), targets_.end(), b) != targets_.end();
}

void StateLink::forget(const Base* b) { std::erase(targets_, b); }

MechanicalState* first_link_state(const Component& owner, const StateLink& link, StateType want,
                                  const std::string& what) {
  if (link.targets().empty()) {
    owner.msg_error(what + " is not set or not found");
    return nullptr;
  }
  auto* s = dynamic_cast<MechanicalState*>(link.targets().front());
  if (!s) {
    owner.msg_error(what + " is not a mechanical state");
    return nullptr;
  }
  if (s->state_type() != want) {
    owner.msg_error(what + " is " + s->info().name + ", expected " + state_type_info(want).name);
    return nullptr;
  }
  if (link.targets().size() > 1)
    owner.msg_warning(what + " names " + std::to_string(link.targets().size()) +
                      " states: only the first is used (SOFA)");
  return s;
}

int geometric_stiffness_id(const std::string& text, int fallback) {
  std::string t;
  for (char c : text)
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') t += c;
  if (t.empty()) return fallback;
  if (t == "None" || t == "0") return 0;
  if (t == "Exact" || t == "1") return 1;
  if (t == "Stabilized" || t == "2") return 2;
  return -1;
}

MappingBase::MappingBase(StateType in, StateType out, bool multi_input)
    : input(this, "input", multi_input ? "input states" : "input state", multi_input, false),
      output_link(this, "output", "output state", false, true),
      in_type_(in),
      out_type_(out) {}

void MappingBase::resize_output(std::size_t n) {
  if (out_) {
    if (out_->size() != n) out_->resize(n);
  } else if (vout_->visual_size() != n) {
    vout_->visual_resize(n);
  }
}

bool MappingBase::resolve_links() {
  // Unset links take SOFA's defaults: input "@../" (the parent node's state), output "@./".
  auto resolve_default = [&](StateLink& l, const char* path) {
    if (l.is_set() || !node()) return;
    std::string why;
    Base* t = resolve_object_path(*node(), this, path, [&l](Base* b) {
      return dynamic_cast<MechanicalState*>(b) != nullptr ||
             (l.allows_visual() && dynamic_cast<VisualState*>(b) != nullptr);
    }, &why);
    if (t) l.set_targets({t});
  };
  resolve_default(input, "@../");
  resolve_default(output_link, "@./");

  in_.clear();
  out_ = nullptr;
  vout_ = nullptr;
  if (input.targets().empty()) {
    msg_error("input state not found (input=" + quote_value(input.is_set() ? input.path() : std::string("@../")) + ")");
    return false;
  }
  const char* want_in = state_type_info(in_type_).name;
  for (std::size_t k = 0; k < input.targets().size(); ++k) {
    auto* s = dynamic_cast<MechanicalState*>(input.targets()[k]);
    if (!s) {
      msg_error("input " + std::to_string(k) + " is not a mechanical state");
      return false;
    }
    if (s->state_type() != in_type_) {
      msg_error("input " + std::to_string(k) + " is " + s->info().name + ", expected " + want_in);
      return false;
    }
    in_.push_back(s);
  }
  Base* o = output_link.target();
  if (!o) {
    msg_error("output state not found (output=\"" +
              (output_link.is_set() ? output_link.path() : std::string("@./")) + "\")");
    return false;
  }
  out_ = dynamic_cast<MechanicalState*>(o);
  vout_ = out_ ? nullptr : dynamic_cast<VisualState*>(o);
  if (out_ && out_->state_type() != out_type_) {
    msg_error(std::string("output is ") + out_->info().name + ", expected " + state_type_info(out_type_).name);
    return false;
  }
  if (vout_ && out_type_ != StateType::vec3) {
    msg_error(std::string("a visual model output is Vec3d, expected ") + state_type_info(out_type_).name);
    return false;
  }
  for (MechanicalState* s : in_)
    if (static_cast<Base*>(s) == o) {
      msg_error("input and output are the same state");
      return false;
    }
  return true;
}

void MappingBase::init() {
  if (!resolve_links()) {
    set_state(ComponentState::invalid);
    return;
  }
  // Mappings to visual models are not mechanical (SOFA's setNonMechanical).
  if (vout_) {
    map_forces.set(false);
    map_constraints.set(false);
    map_masses.set(false);
  }
  if (!init_mapping()) {
    set_state(ComponentState::invalid);
    return;
  }
  if (!apply_at_init()) return;
  apply(kPosition);
  apply_j(kVelocity, kVelocity);
  if (apply_rest_position.value()) apply(kRestPosition);
}

}  // namespace sinew

namespace sinew {
bool parse_mapping_template(const std::string& tmpl, StateType& in, StateType& out) {
  const std::size_t comma = tmpl.find(',');
  if (comma == std::string::npos) return false;
  return state_type_from_name(std::string_view(tmpl).substr(0, comma), in) &&
         state_type_from_name(std::string_view(tmpl).substr(comma + 1), out);
}
}  // namespace sinew
