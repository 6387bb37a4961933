#include "forcefield/fem/triangle_fem_force_field.h"

#include <cmath>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "forcefield/fem/triangle_fem_kernels.h"

namespace sinew {

using namespace trifem;

void TriangleFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  // SOFA's setters: an unknown method becomes large, negative values the defaults.
  if (method.value() == "small") {
    small_ = true;
  } else {
    if (method.value() != "large")
      msg_warning("method \"" + method.value() + "\" is unknown (large or small): using large");
    small_ = false;
  }
  if (poisson_ratio.value() < 0) {
    msg_warning("poissonRatio is " + parse::format_double(poisson_ratio.value()) + ": negative, 0.3 is used");
    poisson_ratio.set(0.3);
  }
  if (young_modulus.value() < 0) {
    msg_warning("youngModulus is " + parse::format_double(young_modulus.value()) + ": negative, 1000 is used");
    young_modulus.set(1000.0);
  }
  if (young_modulus.value() == 0) msg_warning("youngModulus is 0: the triangles have no stiffness");
  const double nu = poisson_ratio.value();
  if (plane_strain.value() ? nu >= 0.5 : nu >= 1.0) {
    msg_error("poissonRatio " + parse::format_double(nu) + " gives no finite " +
              (plane_strain.value() ? "plane-strain material (ν must be below 0.5)"
                                    : "plane-stress material (ν must be below 1)"));
    set_state(ComponentState::invalid);
    return;
  }
  if (nu >= 0.5) msg_warning("poissonRatio is " + parse::format_double(nu) + " (must be in [0, 0.5))");
  if (thickness.value() <= 0)
    msg_warning("thickness is " + parse::format_double(thickness.value()) + ": the triangles have no stiffness" +
                (thickness.value() < 0 ? " (negative: it pushes)" : ""));
  if (!bind_node_topology(*this, topology, "a triangular or quad mesh is required")) return;
  if (topology->triangles().empty() && topology->quads().empty())
    msg_warning("no triangles found in the topology " + topology->describe());
  if (!rebuild()) set_state(ComponentState::invalid);
}

void TriangleFEMForceField::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool TriangleFEMForceField::topology_changed() const {
  return topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ ||
         topology->elements_version(MeshTopologyBase::Elements::quads) != quads_version_;
}

bool TriangleFEMForceField::rebuild() {
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  quads_version_ = topology->elements_version(MeshTopologyBase::Elements::quads);
  std::vector<Triangle> tris = topology->triangles();
  if (tris.empty())
    for (const Quad& q : topology->quads()) {
      tris.push_back({q[0], q[1], q[2]});
      tris.push_back({q[0], q[2], q[3]});
    }
  const std::size_t np = mstate->size();
  if (initial_points.get().empty()) {
    const std::vector<double>& x0 = mstate->read(kRestPosition);
    std::vector<Vec3> pts(np);
    for (std::size_t i = 0; i < np; ++i) pts[i] = at(x0.data(), static_cast<unsigned>(i));
    initial_points.set(std::move(pts));
  }
  const std::vector<Vec3>& P = initial_points.get();
  const double E = young_modulus.value(), nu = poisson_ratio.value(), h = thickness.value();
  const double one_nu = 1 - nu;
  const double e_strain = E / ((1 + nu) * (1 - 2 * nu));
  const double e_stress = E / (1 - nu * nu);
  el_.assign(tris.size(), Element{});
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    if (!triangle_in_state(*this, i, t, np)) return false;
    if (t[0] >= P.size() || t[1] >= P.size() || t[2] >= P.size()) {
      msg_error("triangle " + std::to_string(i) + " refers to a point beyond initialPoints (" +
                std::to_string(P.size()) + " points)");
      return false;
    }
    Element& e = el_[i];
    e.a = t[0];
    e.b = t[1];
    e.c = t[2];
    const Vec3 &pA = P[t[0]], &pB = P[t[1]], &pC = P[t[2]];
    if (small_) {
      const Vec3 rb = minus(pB, pA), rc = minus(pC, pA);
      e.rbx = rb[0];
      e.rby = rb[1];
      e.rcx = rc[0];
      e.rcy = rc[1];
      // The stored J before the first add_force (SOFA's is left unset in small mode).
      if (!local_j(rb[0], rc[0], rc[1], e.J)) e.J.fill(0.0);
    } else {
      const Mat3 R01 = frame_large(pA, pB, pC);
      e.rotation = R01.transpose();
      const Vec3 ra = mul(R01, pA), rb = mul(R01, pB), rc = mul(R01, pC);
      e.rbx = rb[0] - ra[0];
      e.rby = rb[1] - ra[1];
      e.rcx = rc[0] - ra[0];
      e.rcy = rc[1] - ra[1];
      if (!local_j(e.rbx, e.rcx, e.rcy, e.J)) {
        msg_error("triangle " + std::to_string(i) + " is degenerate in its rest shape (zero area)");
        return false;
      }
    }
    const Vec3 n = cross(minus(pB, pA), minus(pC, pA));
    const double volume = 0.5 * h * std::sqrt(dot(n, n));
    if (plane_strain.value()) {
      const double s = e_strain * volume;
      e.D = {one_nu * s, nu * s, 0 * s, nu * s, one_nu * s, 0 * s, 0 * s, 0 * s, (0.5 - nu) * s};
    } else {
      const double s = e_stress * volume;
      e.D = {1 * s, nu * s, 0 * s, nu * s, 1 * s, 0 * s, 0 * s, 0 * s, (0.5 * one_nu) * s};
    }
  }
  return true;
}

void TriangleFEMForceField::stop(std::size_t i) {
  msg_error("triangle " + std::to_string(i) + " is degenerate (zero area) at step " +
            std::to_string(node()->root()->step_index) + ": the force field stops");
  set_state(ComponentState::invalid);
  el_.clear();
}

void TriangleFEMForceField::add_force(const MechParams& p) {
  if (topology_changed() && !rebuild()) {
    set_state(ComponentState::invalid);
    el_.clear();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  for (std::size_t i = 0; i < el_.size(); ++i) {
    Element& e = el_[i];
    const unsigned v[3] = {e.a, e.b, e.c};
    const Vec3 pA = at(x, e.a), pB = at(x, e.b), pC = at(x, e.c);
    std::array<double, 18> J;
    double F[6];
    if (small_) {
      const Vec3 db = minus(pB, pA), dc = minus(pC, pA);
      const double D[6] = {0, 0, e.rbx - db[0], e.rby - db[1], e.rcx - dc[0], e.rcy - dc[1]};
      if (!local_j(db[0], dc[0], dc[1], J)) return stop(i);
      e.J = J;
      kernel_full(J, e.D, D, F);
      for (int k = 0; k < 3; ++k) {
        f[3 * v[k]] += F[2 * k];
        f[3 * v[k] + 1] += F[2 * k + 1];
        f[3 * v[k] + 2] += 0;
      }
      continue;
    }
    const Mat3 R02 = frame_large(pA, pB, pC);
    const Vec3 db = mul(R02, minus(pB, pA)), dc = mul(R02, minus(pC, pA));
    const double D[6] = {0, 0, e.rbx - db[0], 0, e.rcx - dc[0], e.rcy - dc[1]};
    if (!local_j(db[0], dc[0], dc[1], J)) return stop(i);
    kernel(J, e.D, D, F);
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        f[3 * v[k] + c] += R02(0, c) * F[2 * k] + R02(1, c) * F[2 * k + 1] + R02(2, c) * 0;
    e.J = J;
    e.rotation = R02.transpose();
  }
}

void TriangleFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  for (const Element& e : el_) {
    const unsigned v[3] = {e.a, e.b, e.c};
    double D[6], F[6];
    if (small_) {
      for (int k = 0; k < 3; ++k) {
        D[2 * k] = dx[3 * v[k]];
        D[2 * k + 1] = dx[3 * v[k] + 1];
      }
      kernel_full(e.J, e.D, D, F);
      for (int k = 0; k < 3; ++k) {
        df[3 * v[k]] += (-1.0 * F[2 * k]) * kfactor;
        df[3 * v[k] + 1] += (-1.0 * F[2 * k + 1]) * kfactor;
        df[3 * v[k] + 2] += 0 * kfactor;
      }
      continue;
    }
    const Mat3& rot = e.rotation;  // local → world; its transpose maps world → local
    for (int k = 0; k < 3; ++k) {
      const double* d = dx + 3 * v[k];
      D[2 * k] = rot(0, 0) * d[0] + rot(1, 0) * d[1] + rot(2, 0) * d[2];
      D[2 * k + 1] = rot(0, 1) * d[0] + rot(1, 1) * d[1] + rot(2, 1) * d[2];
    }
    kernel(e.J, e.D, D, F);
    for (int k = 0; k < 3; ++k) {
      const double l0 = -1.0 * F[2 * k], l1 = -1.0 * F[2 * k + 1];
      for (int c = 0; c < 3; ++c)
        df[3 * v[k] + c] += (rot(c, 0) * l0 + rot(c, 1) * l1 + rot(c, 2) * 0) * kfactor;
    }
  }
}

bool TriangleFEMForceField::build_stiffness(MatrixSink& K) {
  for (const Element& e : el_) add_element_stiffness(K, mstate.get(), {e.a, e.b, e.c}, e.J, e.D, e.rotation);
  return true;
}

void register_triangle_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "linear-elastic triangles (plane stress or strain, thickness), corotational or small";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangleFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
