#include "forcefield/load/surface_pressure_force_field.h"

#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/sofa_vec.h"

namespace sinew {

namespace {
inline void sub(const double* a, const double* b, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = a[i] - b[i];
}
// s·[v]×, the matrix of w ↦ s·(v × w).
inline void skew(const double* v, double s, double m[3][3]) {
  m[0][0] = 0, m[0][1] = -v[2] * s, m[0][2] = v[1] * s;
  m[1][0] = v[2] * s, m[1][1] = 0, m[1][2] = -v[0] * s;
  m[2][0] = -v[1] * s, m[2][1] = v[0] * s, m[2][2] = 0;
}
}  // namespace

void SurfacePressureForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangle or quad surface is required")) return;
  const std::size_t nt = topology->triangles().size(), nq = topology->quads().size();
  for (unsigned t : triangle_indices.value())
    if (t >= nt) {
      msg_error("triangleIndices holds " + std::to_string(t) + ": the topology has " + std::to_string(nt) + " triangles");
      set_state(ComponentState::invalid);
      return;
    }
  for (unsigned q : quad_indices.value())
    if (q >= nq) {
      msg_error("quadIndices holds " + std::to_string(q) + ": the topology has " + std::to_string(nq) + " quads");
      set_state(ComponentState::invalid);
      return;
    }
  const std::size_t np = mstate->size();
  for (const Triangle& t : topology->triangles())
    for (unsigned v : t)
      if (v >= np) {
        msg_error("the surface refers to point " + std::to_string(v) + ", out of the state (" + std::to_string(np) +
                  " points)");
        set_state(ComponentState::invalid);
        return;
      }
  for (const Quad& q : topology->quads())
    for (unsigned v : q)
      if (v >= np) {
        msg_error("the surface refers to point " + std::to_string(v) + ", out of the state (" + std::to_string(np) +
                  " points)");
        set_state(ComponentState::invalid);
        return;
      }
  if (pulse_mode.value() && pressure_speed.value() == 0.0) {
    msg_warning("pulseMode without pressureSpeed: the speed is set to |pressure| per second");
    pressure_speed.set(std::fabs(pressure.value()));
  }
  reset();
}

void SurfacePressureForceField::reset() {
  increasing_ = pressure.value() > 0;
  pulse_ = 0;
}

double SurfacePressureForceField::pulse_pressure() {
  const double dt = node()->dt.value();
  if (increasing_) {
    const double upper = pressure.value() > 0 ? pressure.value() : pressure_lower_bound.value();
    pulse_ += pressure_speed.value() * dt;
    if (pulse_ >= upper) {
      pulse_ = upper;
      increasing_ = false;
    }
    return pulse_;
  }
  const double lower = pressure.value() > 0 ? pressure_lower_bound.value() : pressure.value();
  pulse_ -= pressure_speed.value() * dt;
  if (pulse_ <= lower) {
    pulse_ = lower;
    increasing_ = true;
  }
  return pulse_;
}

bool SurfacePressureForceField::in_box(const double* x) const {
  const Vec3 lo = min.value(), hi = max.value();
  if (lo == Vec3::Zero() && hi == Vec3::Zero()) return true;
  return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] && x[2] <= hi[2];
}

double SurfacePressureForceField::mesh_volume(const std::vector<double>& x) const {
  double volume = 0, c[3];
  const auto& tris = topology->triangles();
  const auto& quads = topology->quads();
  const auto& ti = triangle_indices.value();
  const auto& qi = quad_indices.value();
  const std::size_t nt = ti.empty() ? tris.size() : ti.size();
  for (std::size_t i = 0; i < nt; ++i) {
    const Triangle& t = tris[ti.empty() ? i : ti[i]];
    sofa_cross(&x[3 * t[0]], &x[3 * t[1]], c);
    volume += c[0] * x[3 * t[2]] + c[1] * x[3 * t[2] + 1] + c[2] * x[3 * t[2] + 2];
  }
  const std::size_t nq = qi.empty() ? quads.size() : qi.size();
  for (std::size_t i = 0; i < nq; ++i) {
    const Quad& q = quads[qi.empty() ? i : qi[i]];
    sofa_cross(&x[3 * q[0]], &x[3 * q[1]], c);
    volume += c[0] * x[3 * q[2]] + c[1] * x[3 * q[2] + 1] + c[2] * x[3 * q[2] + 2];
    sofa_cross(&x[3 * q[0]], &x[3 * q[2]], c);
    volume += c[0] * x[3 * q[3]] + c[1] * x[3 * q[3] + 1] + c[2] * x[3 * q[3] + 2];
  }
  return volume / 6.0;
}

void SurfacePressureForceField::add_force(const MechParams& mp) {
  const std::vector<double>& x = mstate->read(mp.x);
  std::vector<double>& f = mstate->write(mp.f);
  double p = pulse_mode.value() ? pulse_pressure() : pressure.value();
  if (volume_conservation_mode.value()) {
    if (default_volume.value() == -1) {
      default_volume.set(mesh_volume(x));
    } else if (default_volume.value() != 0) {
      const double v = mesh_volume(x);
      if (v != 0) p *= default_volume.value() / v;
    }
  }
  last_pressure_ = p;
  blocks_.clear();
  const bool tangent = use_tangent_stiffness.value();
  const Vec3 dir = main_direction.value();
  const double p6 = p / 6.0;
  const auto& tris = topology->triangles();
  const auto press_triangle = [&](const Triangle& t) {
    double ab[3], ac[3], bc[3], n[3];
    sub(&x[3 * t[1]], &x[3 * t[0]], ab);
    sub(&x[3 * t[2]], &x[3 * t[0]], ac);
    sub(&x[3 * t[2]], &x[3 * t[1]], bc);
    sofa_cross(ab, ac, n);
    double force[3] = {n[0] * p6, n[1] * p6, n[2] * p6};
    if (tangent) {
      Block da{0, t[0], {}}, db{0, t[1], {}}, dc{0, t[2], {}};
      skew(bc, p6, da.k);
      skew(ac, -p6, db.k);
      skew(ab, p6, dc.k);
      for (unsigned v : t)
        for (Block b : {da, db, dc}) {
          b.row = v;
          blocks_.push_back(b);
        }
    }
    if (dir != Vec3::Zero()) {
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double scal = (n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2]) / len;
      for (double& c : force) c *= std::fabs(scal);
    }
    for (unsigned v : t)
      for (int c = 0; c < 3; ++c) f[3 * v + static_cast<unsigned>(c)] += force[c];
  };
  const auto& ti = triangle_indices.value();
  if (!ti.empty()) {
    for (unsigned i : ti) press_triangle(tris[i]);
  } else {
    for (const Triangle& t : tris)
      if (in_box(&x[3 * t[0]]) && in_box(&x[3 * t[1]]) && in_box(&x[3 * t[2]])) press_triangle(t);
  }
  const auto& quads = topology->quads();
  const auto press_quad = [&](const Quad& q) {
    double ab[3], ac[3], ad[3], n1[3], n2[3];
    sub(&x[3 * q[1]], &x[3 * q[0]], ab);
    sub(&x[3 * q[2]], &x[3 * q[0]], ac);
    sub(&x[3 * q[3]], &x[3 * q[0]], ad);
    sofa_cross(ab, ac, n1);
    sofa_cross(ac, ad, n2);
    for (int c = 0; c < 3; ++c) {
      const double p1 = n1[c] * p6, p2 = n2[c] * p6, both = p1 + p2;
      f[3 * q[0] + static_cast<unsigned>(c)] += both;
      f[3 * q[1] + static_cast<unsigned>(c)] += p1;
      f[3 * q[2] + static_cast<unsigned>(c)] += both;
      f[3 * q[3] + static_cast<unsigned>(c)] += p2;
    }
  };
  const auto& qi = quad_indices.value();
  if (!qi.empty()) {
    for (unsigned i : qi) press_quad(quads[i]);
  } else {
    for (const Quad& q : quads)
      if (in_box(&x[3 * q[0]]) && in_box(&x[3 * q[1]]) && in_box(&x[3 * q[2]]) && in_box(&x[3 * q[3]]))
        press_quad(q);
  }
}

void SurfacePressureForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!use_tangent_stiffness.value()) return;
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  for (const Block& b : blocks_) {
    const double* d = &dx[3 * b.col];
    for (unsigned r = 0; r < 3; ++r)
      df[3 * b.row + r] += (b.k[r][0] * d[0] + b.k[r][1] * d[1] + b.k[r][2] * d[2]) * kfactor;
  }
}

bool SurfacePressureForceField::build_stiffness(MatrixSink& K) {
  if (!use_tangent_stiffness.value()) return true;
  const MechanicalState* s = mstate.get();
  for (const Block& b : blocks_) {
    Mat3 m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = b.k[r][c];
    K.add_block(s, 3 * b.row, s, 3 * b.col, m);
  }
  return true;
}

void register_surface_pressure_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SurfacePressureForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "pressure on a closed surface of triangles and quads, optionally pulsed or volume-conserving";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SurfacePressureForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
