// MappingBase: what every mapping shares (spec/mechanics.md §6, framework.md
// §6.6 and trap T1).
//
// - `input` (default "@../") and `output` (default "@./") links, resolved as
//   SOFA does (a path ending on a node takes that node's state). Multi-mappings
//   accept several space-separated inputs.
// - The output is a MechanicalState, or a visual model (VisualState, e.g.
//   OglModel): then the mapping is non-mechanical (mapForces, mapConstraints
//   and mapMasses set to false at init) and only positions are written.
// - init(): resolve the links, let the subclass prepare its data
//   (init_mapping), then apply(position), apply_j(velocity) and, with
//   applyRestPosition, apply(rest_position), like SOFA's Mapping::init.
//
// Vector ids are resolved per state with vec_for() (solver temporaries only
// exist on independent states; mapped states use the standard vector of the
// same role). Helpers below return the flat arrays the hot loops work on.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

// `input` / `output` of a mapping: one or several states (mechanical, or a
// visual model for outputs).
class StateLink final : public BaseLink {
 public:
  StateLink(Base* owner, std::string name, std::string help, bool multi, bool allow_visual);
  bool accept(Base* b) override;
  Base* target() const override { return targets_.empty() ? nullptr : targets_.front(); }
  std::string type_name() const override { return multi_ ? "multi-link" : "link"; }
  bool is_multi() const override { return multi_; }
  void clear_targets() override { targets_.clear(); }
  void add_target(Base* b) override { targets_.push_back(b); }
  bool references(const Base* b) const override;
  void forget(const Base* b) override;
  const std::vector<Base*>& targets() const { return targets_; }
  void set_targets(std::vector<Base*> t) { targets_ = std::move(t); }
  bool allows_visual() const { return allow_visual_; }

 private:
  bool multi_, allow_visual_;
  std::vector<Base*> targets_;
};

// The first state of `link` when it is a mechanical state of type `want` (the
// inputs and output of SOFA's Multi2Mappings); otherwise nullptr after an error of
// `owner` naming `what` (not set or not found, not a state, another type). A link
// naming several states gives a warning: only the first is used (SOFA).
MechanicalState* first_link_state(const Component& owner, const StateLink& link, StateType want,
                                  const std::string& what);

// geometricStiffness option (None / Exact / Stabilized, or 0 / 1 / 2).
int geometric_stiffness_id(const std::string& text, int fallback);

class MappingBase : public Mapping {
 public:
  MappingBase(StateType in, StateType out, bool multi_input = false);

  StateLink input;
  StateLink output_link;

  std::vector<MechanicalState*> inputs() const override { return in_; }
  MechanicalState* output() const override { return out_; }
  VisualState* visual_output() const override { return vout_; }

  void init() final;

 protected:
  // Called once the links are resolved: check inputs, size the output,
  // precompute. Return false (after msg_error naming the problem) to make the
  // mapping invalid; it is then never applied.
  virtual bool init_mapping() = 0;
  // Whether init() applies the mapping once (SOFA's Mapping::init). BarycentricMapping
  // creates its mapper after that point, so its first apply is the end-of-init propagation.
  virtual bool apply_at_init() const { return true; }

  StateType in_type() const { return in_type_; }
  StateType out_type() const { return out_type_; }
  std::size_t in_size(std::size_t k = 0) const { return in_[k]->size(); }
  std::size_t out_size() const { return out_ ? out_->size() : vout_->visual_size(); }
  void resize_output(std::size_t n);

  // Reads of the inputs (apply, apply_j) leave their versions alone; the
  // outputs and the inputs' force accumulators (apply_jt) are writes.
  // Input coordinates for vector `x` (position, rest_position or a solver vector).
  const std::vector<double>& in_coord(int x, std::size_t k = 0) const {
    return in_[k]->read(vec_for(*in_[k], x, kPosition));
  }
  const std::vector<double>& in_deriv(int v, int role, std::size_t k = 0) const {
    return in_[k]->read(vec_for(*in_[k], v, role));
  }
  // Input derivatives that receive Jᵀ·out (forces, force variations).
  std::vector<double>& in_deriv_write(int f, int role, std::size_t k = 0) const {
    return in_[k]->write(vec_for(*in_[k], f, role));
  }
  // Output coordinates, to be written (nullptr when the output has no such vector).
  std::vector<double>* out_coord(int x) const {
    if (out_) return &out_->write(vec_for(*out_, x, kPosition));
    return vout_->visual_vec(x);
  }
  const std::vector<double>* out_coord_read(int x) const {
    if (out_) return &out_->read(vec_for(*out_, x, kPosition));
    return vout_->visual_vec(x);
  }
  // Output derivatives, to be written by apply_j (nullptr for visual outputs).
  std::vector<double>* out_deriv(int v, int role) const {
    return out_ ? &out_->write(vec_for(*out_, v, role)) : nullptr;
  }
  // Output derivatives read by apply_jt (nullptr for visual outputs).
  const std::vector<double>* out_deriv_read(int f, int role) const {
    return out_ ? &out_->read(vec_for(*out_, f, role)) : nullptr;
  }

  // Output positions at init (for mappings that compute local coordinates from them).
  const std::vector<double>& initial_output_positions() const { return *out_coord_read(kPosition); }

  std::vector<MechanicalState*> in_;
  MechanicalState* out_ = nullptr;
  VisualState* vout_ = nullptr;

 private:
  bool resolve_links();
  StateType in_type_, out_type_;
};

}  // namespace sinew

namespace sinew {
// "In,Out" template name → the two state types (false when not a pair of state types).
bool parse_mapping_template(const std::string& tmpl, StateType& in, StateType& out);
}  // namespace sinew
