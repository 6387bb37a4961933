#include "mass/diagonal_rigid_mass.h"

#include <Eigen/LU>
#include <cmath>

#include "core/node.h"
#include "core/parse.h"
#include "core/rigid_mass_text.h"
#include "core/value_text.h"

namespace sinew {

namespace {
constexpr int kValuesPerMass = 11;  // mass, volume, inertia by rows
}

DiagonalRigidMass::DiagonalRigidMass() { file_mass.add_alias("fileMass"); }

void DiagonalRigidMass::parse(AttributeMap& attrs, Diagnostics& diag) {
  const std::string* text = attrs.peek("vertexMass");
  if (text && !text->empty() && (*text)[0] != '@') {
    std::vector<double> values;
    if (!parse::read_rigid3_mass_list(*text, values))
      diag.warning(where, describe() + ": vertexMass: only " + std::to_string(values.size() / kValuesPerMass) +
                              " complete rigid masses could be read (each is 'mass volume [I00 I01 I02,I10 I11 "
                              "I12,I20 I21 I22]'): " + quote_value(*text));
    vertex_mass.set(std::move(values));
    attrs.take("vertexMass");
  }
  Mass::parse(attrs, diag);
}

void DiagonalRigidMass::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  if (s.state_type() != StateType::rigid3) {
    msg_error(std::string("the Rigid3d DiagonalMass needs a Rigid3d state, not ") + s.info().name);
    set_state(ComponentState::invalid);
    return;
  }
  if (!file_mass.get().empty()) {
    msg_error("mass files (filename=) are not supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (mass_density.is_set() || total_mass.is_set())
    msg_warning("massDensity and totalMass are not used by a Rigid3d DiagonalMass (as in SOFA): vertexMass gives "
                "each frame's mass");
  const std::vector<double>& vm = vertex_mass.value();
  const std::size_t n = vm.size() / kValuesPerMass;
  // SOFA reads past the list (addForce writes frames it has no mass for) when the counts
  // differ: refused here.
  if (n != s.size()) {
    msg_error("vertexMass has " + std::to_string(n) + " rigid masses for " + std::to_string(s.size()) +
              " frames: give one 'mass volume [inertia]' per frame");
    set_state(ComponentState::invalid);
    return;
  }
  frames_.assign(n, Frame{});
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = vm.data() + i * kValuesPerMass;
    Mat3 inertia;
    for (int k = 0; k < 9; ++k) inertia(k / 3, k % 3) = v[2 + k];
    Frame& f = frames_[i];
    f.mass = v[0];
    f.inertia_mass = inertia * f.mass;
    // SOFA's recalc() asserts both inverses exist: a zero mass or a singular inertia is refused.
    const double det = f.inertia_mass.determinant();
    if (!(f.mass > 0) || !std::isfinite(f.mass) || !(std::abs(det) > 0) || !std::isfinite(det)) {
      msg_error("frame " + std::to_string(i) + ": mass " + parse::format_double(f.mass) +
                " with this inertia has no inverse (mass and inertia must be positive)");
      set_state(ComponentState::invalid);
      return;
    }
    f.inv_inertia_mass = f.inertia_mass.inverse();
  }
  follow_.owner = this;
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
}

void DiagonalRigidMass::Follow::apply(const MeshTopologyBase&, const TopologyChange& c) {
  std::vector<Frame>& frames = owner->frames_;
  if (c.type == TopologyChangeType::points_removed) {
    remove_swap_last(frames, c.indices);
  } else if (c.type == TopologyChangeType::points_added) {
    // SOFA's applyPointCreation gives a new point a zero mass; a frame without mass cannot
    // be integrated, so it is said once.
    Frame zero;
    zero.mass = 0;
    zero.inertia_mass = Mat3::Zero();
    zero.inv_inertia_mass = Mat3::Zero();
    frames.insert(frames.end(), c.indices.size(), zero);
    owner->msg_warning("frames added by a topological change have no mass (as in SOFA)");
  }
}

double DiagonalRigidMass::total() const {
  double sum = 0;
  for (const Frame& f : frames_) sum += f.mass;
  return sum;
}

void DiagonalRigidMass::add_force(const MechParams& p) {
  if (separate_gravity.value()) return;
  std::vector<double>& f = mstate->write(p.f);
  const Vec3 g = node()->gravity.value();
  // SOFA: f_i += (g, 0) × RigidMass_i, i.e. m·g on the centre and I·m·0 on the rotation.
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    for (int c = 0; c < 3; ++c) f[i * 6 + c] += g[c] * frames_[i].mass;
  }
}

std::optional<double> DiagonalRigidMass::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const Vec3 g = node()->gravity.value();
  double e = 0;
  for (std::size_t i = 0; i < frames_.size() && (i + 1) * 7 <= x.size(); ++i) {
    const double gc = g[0] * x[i * 7] + g[1] * x[i * 7 + 1] + g[2] * x[i * 7 + 2];
    e -= gc * frames_[i].mass;
  }
  return e;
}

void DiagonalRigidMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  std::vector<double>& r = mstate->write(res);
  const std::vector<double>& d = mstate->read(dx);
  const std::size_t n = std::min(frames_.size(), std::min(r.size(), d.size()) / 6);
  for (std::size_t i = 0; i < n; ++i) {
    const Frame& f = frames_[i];
    const Vec3 om(d[i * 6 + 3], d[i * 6 + 4], d[i * 6 + 5]);
    const Vec3 t = f.inertia_mass * om;
    if (factor == 1.0) {  // SOFA's two branches: (dx·M) then ·factor
      for (int c = 0; c < 3; ++c) r[i * 6 + c] += d[i * 6 + c] * f.mass;
      for (int c = 0; c < 3; ++c) r[i * 6 + 3 + c] += t[c];
    } else {
      for (int c = 0; c < 3; ++c) r[i * 6 + c] += (d[i * 6 + c] * f.mass) * factor;
      for (int c = 0; c < 3; ++c) r[i * 6 + 3 + c] += t[c] * factor;
    }
  }
}

void DiagonalRigidMass::acc_from_f(const MechParams&, int a, int f) {
  std::vector<double>& av = mstate->write(a);
  const std::vector<double>& fv = mstate->read(f);
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    const Frame& m = frames_[i];
    for (int c = 0; c < 3; ++c) av[i * 6 + c] = fv[i * 6 + c] / m.mass;
    const Vec3 t(fv[i * 6 + 3], fv[i * 6 + 4], fv[i * 6 + 5]);
    const Vec3 al = m.inv_inertia_mass * t;
    for (int c = 0; c < 3; ++c) av[i * 6 + 3 + c] = al[c];
  }
}

void DiagonalRigidMass::add_gravity_to_v(int v, double dt) {
  std::vector<double>& vv = mstate->write(v);
  const Vec3 dv = node()->gravity.value() * dt;
  for (std::size_t i = 0; i < mstate->size(); ++i)
    for (int c = 0; c < 3; ++c) vv[i * 6 + c] += dv[c];
}

bool DiagonalRigidMass::build_mass(MatrixSink& M) {
  MechanicalState* s = mstate.get();
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    const Frame& f = frames_[i];
    for (int c = 0; c < 3; ++c) M.add(s, i * 6 + c, s, i * 6 + c, f.mass);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) M.add(s, i * 6 + 3 + a, s, i * 6 + 3 + b, f.inertia_mass(a, b));
  }
  return true;
}

}  // namespace sinew
