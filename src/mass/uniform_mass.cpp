#include "mass/uniform_mass.h"

#include <Eigen/LU>
#include <fstream>

#include "core/node.h"
#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

void UniformMass::parse(AttributeMap& attrs, Diagnostics& diag) {
  const std::string* text = attrs.peek("vertexMass");
  if (template_name() == "Rigid3d" && text && !text->empty() && (*text)[0] != '@') {
    std::vector<double> values;
    const bool ok = parse::read_rigid3_mass(*text, values);
    // Values missing at the end keep their defaults (mass 1, identity inertia), as init reads them.
    vertex_mass.set(values.empty() ? vertex_mass.default_value() : values);
    if (!ok) diag.warning(where, describe() + ": could not read value for field 'vertexMass': " + quote_value(*text));
    attrs.take("vertexMass");
  }
  Mass::parse(attrs, diag);
}

void UniformMass::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::size_t n_dofs = s.size();

  active_ = indices.get();
  const VecNi<2> range = local_range.get();
  if (range[0] >= 0 && range[1] > 0 && static_cast<std::size_t>(range[1]) + 1 < n_dofs) {
    active_.clear();
    for (int i = range[0]; i <= range[1]; ++i) active_.push_back(static_cast<unsigned>(i));
  }
  if (active_.empty())
    for (unsigned i = 0; i < n_dofs; ++i) active_.push_back(i);
  for (unsigned i : active_)
    if (i >= n_dofs) {
      msg_error("index " + std::to_string(i) + " is out of range (the state has " + std::to_string(n_dofs) +
                " DoFs)");
      set_state(ComponentState::invalid);
      return;
    }
  const double n = static_cast<double>(active_.size());

  const bool rigid = s.state_type() == StateType::rigid3;
  std::vector<double> vm = vertex_mass.get();
  Mat3 inertia = Mat3::Identity();
  if (rigid && vm.size() >= 11)
    for (int k = 0; k < 9; ++k) inertia(k / 3, k % 3) = vm[2 + k];
  // Rigid2d: "mass volume inertia", the inertia a scalar (about the normal axis).
  double inertia2 = 1.0;
  if (s.state_type() == StateType::rigid2 && vm.size() >= 3) inertia2 = vm[2];

  if (!filename.value().empty() && filename.value() != "unused") {
    if (!rigid) {
      msg_warning("filename is read for Rigid3d masses only: ignored for " + std::string(s.info().name));
    } else {
      double mass = vm.empty() ? 1.0 : vm[0];
      if (!load_rigid_file(mass, inertia)) {
        set_state(ComponentState::invalid);
        return;
      }
      vm = vertex_mass.get();  // the file's vertexMass
    }
  }
  if (total_mass.is_set() && total_mass.value() < 0) {
    msg_error("totalMass must not be negative");
    set_state(ComponentState::invalid);
    return;
  }
  if (vertex_mass.is_set() && !vm.empty() && vm[0] < 0) {
    msg_error("vertexMass must not be negative");
    set_state(ComponentState::invalid);
    return;
  }
  if (total_mass.is_set()) {
    if (vertex_mass.is_set()) msg_warning("both totalMass and vertexMass are set: totalMass is used");
    m_ = n > 0 ? total_mass.value() / n : 0.0;
  } else if (vertex_mass.is_set()) {
    m_ = vm.empty() ? 1.0 : vm[0];
    total_mass.set(m_ * n);
  } else {
    msg_error("neither totalMass nor vertexMass is set: the object has no mass");
    set_state(ComponentState::invalid);
    return;
  }
  if (m_ == 0 && n > 0)
    msg_warning("the mass of each point is 0: dynamic solvers need a positive mass (singular system, division by zero)");
  inertia_mass_ = inertia * m_;
  inv_inertia_mass_ = inertia_mass_.inverse();
  inertia_mass2_ = inertia2 * m_;
  inertia_ = inertia;
  inertia2_ = inertia2;
  follow_.owner = this;
  follow_.attach(node() ? node()->get_mesh_topology_link() : nullptr);
}

void UniformMass::update_mass_on_resize(std::size_t n) {
  if (n == 0) {
    total_mass.set(0.0);
    return;
  }
  if (preserve_total_mass.value()) {
    m_ = total_mass.value() / static_cast<double>(n);
    inertia_mass_ = inertia_ * m_;
    inv_inertia_mass_ = inertia_mass_.inverse();
    inertia_mass2_ = inertia2_ * m_;
  } else {
    total_mass.set(static_cast<double>(n) * m_);
  }
}

void UniformMass::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  std::vector<unsigned>& active = owner->active_;
  switch (c.type) {
    case TopologyChangeType::points_removed: {
      // Received before the container changes: its count is the one before the removal.
      auto n = static_cast<unsigned>(t.nb_points());
      for (unsigned r : c.indices) {
        if (n == 0) break;
        const unsigned last = --n;
        for (std::size_t k = 0; k < active.size();) {
          if (active[k] == r) {
            active[k] = active.back();
            active.pop_back();
          } else {
            ++k;
          }
        }
        if (r != last)
          for (unsigned& v : active)
            if (v == last) v = r;
      }
      break;
    }
    case TopologyChangeType::points_added:
      active.insert(active.end(), c.indices.begin(), c.indices.end());
      break;
    case TopologyChangeType::ending: owner->update_mass_on_resize(active.size()); break;
    default: break;
  }
}

bool UniformMass::load_rigid_file(double& mass, Mat3& inertia) {
  std::ifstream in(filename.value());
  if (!in) {
    msg_error("cannot open mass file '" + filename.value() + "'");
    return false;
  }
  std::string line;
  std::getline(in, line);  // header ("Xsp 3.0")
  std::string cmd;
  auto read = [&](double* v, int n, const char* what) {
    for (int i = 0; i < n; ++i)
      if (!(in >> v[i])) {
        msg_error("mass file '" + filename.value() + "': cannot read the values of '" + what + "'");
        return false;
      }
    return true;
  };
  double skip[4];
  while (in >> cmd) {
    if (cmd == "inrt") {
      double v[9];
      if (!read(v, 9, "inrt")) return false;
      for (int k = 0; k < 9; ++k) inertia(k / 3, k % 3) = v[k];
    } else if (cmd == "vertexMass") {
      if (!read(&mass, 1, "vertexMass")) return false;
      // The file's mass is the vertex mass; when the scene gave none, it also
      // replaces totalMass (SOFA forces vertexMass set and unsets totalMass).
      const bool given = vertex_mass.is_set();
      std::vector<double> vm = vertex_mass.value();
      if (vm.empty()) vm.push_back(mass);
      else vm[0] = mass;
      vertex_mass.set(vm);
      if (!given) total_mass.unset();
    } else if (cmd == "cntr" || cmd == "center" || cmd == "grav") {
      if (!read(skip, 3, cmd.c_str())) return false;  // not used by the mass
    } else if (cmd == "frme") {
      if (!read(skip, 4, "frme")) return false;
    } else if (cmd == "volm" || cmd == "visc" || cmd == "stck" || cmd == "step" || cmd == "prec") {
      if (!read(skip, 1, cmd.c_str())) return false;
    } else if (cmd[0] == '#') {
      std::getline(in, line);
    } else {
      msg_error("mass file '" + filename.value() + "': unknown command '" + cmd + "'");
      std::getline(in, line);
    }
  }
  return true;
}

void UniformMass::add_force(const MechParams& p) {
  if (separate_gravity.value()) return;
  MechanicalState& s = *mstate;
  std::vector<double>& f = s.write(p.f);
  const Vec3 g = node()->gravity.value();
  const int w = s.info().deriv_width;
  const int dim = std::min(3, s.info().spatial_dim);
  const Vec3 mg = g * m_;
  for (unsigned i : active_)
    for (int c = 0; c < dim; ++c) f[i * w + c] += mg[c];
}

std::optional<double> UniformMass::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const MechanicalState& s = *mstate;
  const std::vector<double>& x = mstate->read(kPosition);
  const Vec3 g = node()->gravity.value();
  const int w = s.info().coord_width;
  const int dim = std::min(3, s.info().spatial_dim);
  double e = 0;
  for (unsigned i : active_)
    for (int c = 0; c < dim; ++c) e -= m_ * g[c] * x[i * w + c];
  return e;
}

void UniformMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  MechanicalState& s = *mstate;
  std::vector<double>& r = s.write(res);
  const std::vector<double>& d = s.read(dx);
  const int w = s.info().deriv_width;
  if (s.state_type() == StateType::rigid2) {
    for (unsigned i : active_) {
      for (int c = 0; c < 2; ++c) r[i * 3 + c] += d[i * 3 + c] * m_ * factor;
      r[i * 3 + 2] += d[i * 3 + 2] * inertia_mass2_ * factor;
    }
    return;
  }
  if (s.state_type() == StateType::rigid3) {
    for (unsigned i : active_) {
      for (int c = 0; c < 3; ++c) r[i * 6 + c] += d[i * 6 + c] * m_ * factor;
      const Vec3 om(d[i * 6 + 3], d[i * 6 + 4], d[i * 6 + 5]);
      const Vec3 t = inertia_mass_ * om * factor;
      for (int c = 0; c < 3; ++c) r[i * 6 + 3 + c] += t[c];
    }
    return;
  }
  const double mf = m_ * factor;
  if (w == 3) {  // the common case, unrolled (once per CG iteration)
    for (unsigned i : active_) {
      r[3 * i] += d[3 * i] * mf;
      r[3 * i + 1] += d[3 * i + 1] * mf;
      r[3 * i + 2] += d[3 * i + 2] * mf;
    }
    return;
  }
  for (unsigned i : active_)
    for (int c = 0; c < w; ++c) r[i * w + c] += d[i * w + c] * mf;
}

void UniformMass::acc_from_f(const MechParams&, int a, int f) {
  MechanicalState& s = *mstate;
  std::vector<double>& av = s.write(a);
  const std::vector<double>& fv = s.read(f);
  const int w = s.info().deriv_width;
  if (s.state_type() == StateType::rigid2) {
    for (unsigned i : active_) {
      for (int c = 0; c < 2; ++c) av[i * 3 + c] = fv[i * 3 + c] / m_;
      av[i * 3 + 2] = fv[i * 3 + 2] / inertia_mass2_;
    }
    return;
  }
  if (s.state_type() == StateType::rigid3) {
    for (unsigned i : active_) {
      for (int c = 0; c < 3; ++c) av[i * 6 + c] = fv[i * 6 + c] / m_;
      const Vec3 t(fv[i * 6 + 3], fv[i * 6 + 4], fv[i * 6 + 5]);
      const Vec3 al = inv_inertia_mass_ * t;
      for (int c = 0; c < 3; ++c) av[i * 6 + 3 + c] = al[c];
    }
    return;
  }
  for (unsigned i : active_)
    for (int c = 0; c < w; ++c) av[i * w + c] = fv[i * w + c] / m_;
}

void UniformMass::add_gravity_to_v(int v, double dt) {
  MechanicalState& s = *mstate;
  std::vector<double>& vv = s.write(v);
  const Vec3 dv = node()->gravity.value() * dt;
  const int w = s.info().deriv_width;
  const int dim = std::min(3, s.info().spatial_dim);
  for (unsigned i : active_)
    for (int c = 0; c < dim; ++c) vv[i * w + c] += dv[c];
}

bool UniformMass::build_mass(MatrixSink& M) {
  MechanicalState* s = mstate.get();
  const int w = s->info().deriv_width;
  for (unsigned i : active_) {
    if (s->state_type() == StateType::rigid2) {
      for (int c = 0; c < 2; ++c) M.add(s, i * 3 + c, s, i * 3 + c, m_);
      M.add(s, i * 3 + 2, s, i * 3 + 2, inertia_mass2_);
    } else if (s->state_type() == StateType::rigid3) {
      for (int c = 0; c < 3; ++c) M.add(s, i * 6 + c, s, i * 6 + c, m_);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) M.add(s, i * 6 + 3 + a, s, i * 6 + 3 + b, inertia_mass_(a, b));
    } else {
      for (int c = 0; c < w; ++c) M.add(s, i * w + c, s, i * w + c, m_);
    }
  }
  return true;
}

void register_uniform_mass(Registry& r) {
  ComponentInfo info;
  info.name = "UniformMass";
  info.category = "Mass";
  info.description = "same mass on every degree of freedom";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<UniformMass>();
  r.add(std::move(info));
}

}  // namespace sinew
