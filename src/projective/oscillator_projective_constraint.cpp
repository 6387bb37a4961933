// OscillatorProjectiveConstraint (old name OscillatorConstraint): listed DoFs follow
// sinusoids, x = mean + amplitude·sin(ω·t + φ), v = amplitude·ω·cos(ω·t + φ), t the node's
// time; responses and constraint-row columns of those DoFs are zeroed.
// `oscillators` holds, per DoF: index, mean (a coordinate), amplitude (a derivative), ω, φ
// — 9 numbers for Vec3d, 16 for Rigid3d, where mean + amplitude·s is SOFA's rigid sum
// (centre moved, orientation turned by the exponential of the angular part).
// Assembled systems are not projected (SOFA does not either).
#include <cmath>
#include <string>
#include <vector>

#include "core/constraint_matrix.h"
#include "core/node.h"
#include "core/registry.h"
#include "projective/indices_in_state.h"
#include "core/state_creator.h"
#include "math/rigid.h"

namespace sinew {

namespace {

class OscillatorProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit OscillatorProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<double>> oscillators{
      this, "oscillators", {},
      "oscillating DoFs, each: index, mean (coordinate), amplitude (derivative), pulsation, phase", "Constraint"};

  void init() override {
    if (!init_state_of_type(*this, type_)) return;
    cw_ = mstate->info().coord_width;
    dw_ = mstate->info().deriv_width;
    const std::size_t stride = 1 + cw_ + dw_ + 2;
    const std::vector<double>& v = oscillators.get();
    if (v.size() % stride != 0) {
      msg_error("oscillators has " + std::to_string(v.size()) + " numbers: each oscillator takes " +
                std::to_string(stride) + " (index, mean, amplitude, pulsation, phase)");
      set_state(ComponentState::invalid);
      return;
    }
    osc_.clear();
    for (std::size_t o = 0; o * stride < v.size(); ++o) {
      const double* r = &v[o * stride];
      if (r[0] < 0 || r[0] != std::floor(r[0]) || r[0] >= static_cast<double>(mstate->size())) {
        msg_error("oscillator " + std::to_string(o) + " names DoF " + std::to_string(r[0]) + " but the state has " +
                  std::to_string(mstate->size()) + " DoFs");
        set_state(ComponentState::invalid);
        return;
      }
      Osc s;
      s.index = static_cast<unsigned>(r[0]);
      s.mean.assign(r + 1, r + 1 + cw_);
      s.amplitude.assign(r + 1 + cw_, r + 1 + cw_ + dw_);
      s.pulsation = r[1 + cw_ + dw_];
      s.phase = r[2 + cw_ + dw_];
      osc_.push_back(std::move(s));
    }
  }

  void project_response(int dx) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& d = mstate->write(dx);
    for (const Osc& o : osc_)
      if ((o.index + 1) * dw_ <= d.size())
        for (int c = 0; c < dw_; ++c) d[o.index * dw_ + c] = 0.0;
  }

  void project_jacobian(ConstraintMatrix& J) override {
    if (state() != ComponentState::valid) return;
    for (const Osc& o : osc_) J.zero_dof(static_cast<int>(o.index), 0, J.width());
  }

  void project_velocity(int vid, double) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& v = mstate->write(vid);
    const double t = node()->time.value();
    for (const Osc& o : osc_) {
      if ((o.index + 1) * dw_ > v.size()) continue;
      const double w = o.pulsation, c = std::cos(w * t + o.phase);
      // SOFA's a·w·cos(…): each component times w, then times the cosine.
      for (int k = 0; k < dw_; ++k) v[o.index * dw_ + k] = o.amplitude[k] * w * c;
    }
  }

  void project_position(int xid, double) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& x = mstate->write(xid);
    const double t = node()->time.value();
    for (const Osc& o : osc_) {
      if ((o.index + 1) * cw_ > x.size()) continue;
      const double s = std::sin(o.pulsation * t + o.phase);
      double* out = &x[o.index * cw_];
      if (type_ == StateType::rigid3) {
        rigid3_add_deriv(o.mean.data(), o.amplitude.data(), s, out);
      } else {
        for (int k = 0; k < cw_; ++k) out[k] = o.mean[k] + o.amplitude[k] * s;
      }
    }
  }

 private:
  struct Osc {
    unsigned index = 0;
    std::vector<double> mean, amplitude;
    double pulsation = 0, phase = 0;
  };
  StateType type_;
  int cw_ = 3, dw_ = 3;
  std::vector<Osc> osc_;
};

}  // namespace

void register_oscillator_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "OscillatorProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves points along sinusoidal trajectories";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<OscillatorProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
