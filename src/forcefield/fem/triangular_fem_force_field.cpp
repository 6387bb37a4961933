#include "forcefield/fem/triangular_fem_force_field.h"

#include <cmath>
#include <limits>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "forcefield/fem/triangle_fem_kernels.h"

namespace sinew {

namespace {
using namespace trifem;
// J from the x, y coordinates of B − A and C − A (SOFA's computeStrainDisplacementGlobal
// with A at the origin); the determinant is |AB × AC|. False when ≈ 0.
inline bool global_j(const Vec3& b, const Vec3& c, std::array<double, 18>& J) {
  const double det = std::sqrt(dot(cross(b, c), cross(b, c)));
  if (std::fabs(det) < std::numeric_limits<double>::epsilon()) return false;
  const double inv = 1 / det;
  const double x13 = (0 - c[0]) * inv, x21 = (b[0] - 0) * inv, x32 = (c[0] - b[0]) * inv;
  const double y12 = (0 - b[1]) * inv, y23 = (b[1] - c[1]) * inv, y31 = (c[1] - 0) * inv;
  J = {y23, 0, x32, 0, x32, y23, y31, 0, x13, 0, x13, y31, y12, 0, x21, 0, x21, y12};
  return true;
}
}  // namespace

void TriangularFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (method.value() == "small") {
    small_ = true;
  } else {
    if (method.value() != "large")
      msg_warning("method " + quote_value(method.value()) + " is unknown (large or small): using large");
    small_ = false;
  }
  if (rotated_initial_elements.is_set() || initial_transformation.is_set()) {
    msg_error("rotatedInitialElements/initialTransformation are not supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (young_modulus.get().empty() || poisson_ratio.get().empty()) {
    msg_error("youngModulus and poissonRatio must not be empty");
    set_state(ComponentState::invalid);
    return;
  }
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) msg_warning("no triangles found in the topology " + topology->describe());
  if (!rebuild()) set_state(ComponentState::invalid);
}

void TriangularFEMForceField::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool TriangularFEMForceField::rebuild() {
  const auto& tris = topology->triangles();
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  const std::size_t np = mstate->size();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const auto& ey = young_modulus.get();
  const auto& pr = poisson_ratio.get();
  // SOFA computes the material before checking the values (then warns).
  if (ey.size() == 1 && ey[0] < 0)
    msg_warning("youngModulus is " + parse::format_double(ey[0]) + ": negative (SOFA resets it to 1000 after use)");
  else if (ey.size() == 1 && ey[0] == 0)
    msg_warning("youngModulus is 0: the triangles have no stiffness");
  if (pr.size() == 1 && pr[0] < 0)
    msg_warning("poissonRatio is " + parse::format_double(pr[0]) + ": negative (SOFA resets it to 0.3 after use)");
  else if (pr.size() == 1 && pr[0] >= 0.5)
    msg_warning("poissonRatio is " + parse::format_double(pr[0]) + " (must be in [0, 0.5))");
  el_.assign(tris.size(), Element{});
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    if (!triangle_in_state(*this, i, t, np)) return false;
    Element& e = el_[i];
    e.a = t[0];
    e.b = t[1];
    e.c = t[2];
    const Vec3 pA = at(x0.data(), t[0]), pB = at(x0.data(), t[1]), pC = at(x0.data(), t[2]);
    if (small_) {
      // Rest shape kept in world axes, A at the origin; area = |AB × AC| / 2.
      const Vec3 rb = minus(pB, pA), rc = minus(pC, pA);
      e.rbx = rb[0];
      e.rby = rb[1];
      e.rcx = rc[0];
      e.rcy = rc[1];
      if (!global_j(rb, rc, e.J)) {
        msg_error("triangle " + std::to_string(i) + " is degenerate in its rest shape (zero area)");
        return false;
      }
      e.area = std::sqrt(dot(cross(rb, rc), cross(rb, rc))) * 0.5;
      const double y = ey.size() > i ? ey[i] : ey[0];
      const double p = pr.size() > i ? pr[i] : pr[0];
      const double sc = (y / (1.0 - p * p)) * e.area;
      e.D = {1 * sc, p * sc, 0 * sc, p * sc, 1 * sc, 0 * sc, 0 * sc, 0 * sc, ((1.0 - p) * 0.5) * sc};
      continue;
    }
    const Mat3 R01 = frame_large(pA, pB, pC);
    e.rotation = R01.transpose();
    const Vec3 rb = mul(R01, minus(pB, pA)), rc = mul(R01, minus(pC, pA));
    e.rbx = rb[0];
    e.rcx = rc[0];
    e.rcy = rc[1];
    if (!local_j(rb[0], rc[0], rc[1], e.J)) {
      msg_error("triangle " + std::to_string(i) + " is degenerate in its rest shape (zero area)");
      return false;
    }
    e.area = rb[0] * rc[1] * 0.5;
    const double y = ey.size() > i ? ey[i] : ey[0];
    const double p = pr.size() > i ? pr[i] : pr[0];
    const double s = (y / (1.0 - p * p)) * e.area;
    e.D = {1 * s, p * s, 0 * s, p * s, 1 * s, 0 * s, 0 * s, 0 * s, ((1.0 - p) * 0.5) * s};
  }
  return true;
}

void TriangularFEMForceField::add_force(const MechParams& p) {
  if (topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ && !rebuild()) {
    set_state(ComponentState::invalid);
    el_.clear();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  if (small_) {
    add_force_small(x, f);
    return;
  }
  for (std::size_t i = 0; i < el_.size(); ++i) {
    Element& e = el_[i];
    const Vec3 pA = at(x, e.a), pB = at(x, e.b), pC = at(x, e.c);
    const Mat3 R02 = frame_large(pA, pB, pC);
    const Vec3 db = mul(R02, minus(pB, pA)), dc = mul(R02, minus(pC, pA));
    const double D[6] = {0, 0, e.rbx - db[0], 0, e.rcx - dc[0], e.rcy - dc[1]};
    std::array<double, 18> J;
    if (!local_j(db[0], dc[0], dc[1], J)) {
      msg_error("triangle " + std::to_string(i) + " is degenerate (zero area) at step " +
                std::to_string(node()->root()->step_index) + ": the force field stops");
      set_state(ComponentState::invalid);
      el_.clear();
      return;
    }
    double F[6];
    kernel(J, e.D, D, F);
    const unsigned v[3] = {e.a, e.b, e.c};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        f[3 * v[k] + c] += R02(0, c) * F[2 * k] + R02(1, c) * F[2 * k + 1] + R02(2, c) * 0;
    e.J = J;
    e.rotation = R02.transpose();
  }
}

void TriangularFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  if (small_) {
    add_dforce_small(dx, df, kfactor);
    return;
  }
  for (const Element& e : el_) {
    const Mat3& rot = e.rotation;  // local → world; its transpose maps world → local
    const unsigned v[3] = {e.a, e.b, e.c};
    double D[6];
    for (int k = 0; k < 3; ++k) {
      const double* d = dx + 3 * v[k];
      D[2 * k] = rot(0, 0) * d[0] + rot(1, 0) * d[1] + rot(2, 0) * d[2];
      D[2 * k + 1] = rot(0, 1) * d[0] + rot(1, 1) * d[1] + rot(2, 1) * d[2];
    }
    double F[6];
    kernel(e.J, e.D, D, F);
    for (int k = 0; k < 3; ++k) {
      const double l0 = -1.0 * F[2 * k], l1 = -1.0 * F[2 * k + 1];
      for (int c = 0; c < 3; ++c)
        df[3 * v[k] + c] += (rot(c, 0) * l0 + rot(c, 1) * l1 + rot(c, 2) * 0) * kfactor;
    }
  }
}

void TriangularFEMForceField::add_force_small(const double* x, double* f) {
  for (std::size_t i = 0; i < el_.size(); ++i) {
    Element& e = el_[i];
    const Vec3 pA = at(x, e.a);
    const Vec3 db = minus(at(x, e.b), pA), dc = minus(at(x, e.c), pA);
    const double D[6] = {0, 0, e.rbx - db[0], e.rby - db[1], e.rcx - dc[0], e.rcy - dc[1]};
    std::array<double, 18> J;
    if (!global_j(db, dc, J)) {
      msg_error("triangle " + std::to_string(i) + " is degenerate (zero area) at step " +
                std::to_string(node()->root()->step_index) + ": the force field stops");
      set_state(ComponentState::invalid);
      el_.clear();
      return;
    }
    double F[6];
    kernel_full(J, e.D, D, F);
    const unsigned v[3] = {e.a, e.b, e.c};
    for (int k = 0; k < 3; ++k) {
      f[3 * v[k]] += F[2 * k];
      f[3 * v[k] + 1] += F[2 * k + 1];
      f[3 * v[k] + 2] += 0;
    }
    e.J = J;
  }
}

void TriangularFEMForceField::add_dforce_small(const double* dx, double* df, double kfactor) const {
  for (const Element& e : el_) {
    const unsigned v[3] = {e.a, e.b, e.c};
    double D[6];
    for (int k = 0; k < 3; ++k) {
      D[2 * k] = dx[3 * v[k]];
      D[2 * k + 1] = dx[3 * v[k] + 1];
    }
    double F[6];
    kernel_full(e.J, e.D, D, F);
    for (int k = 0; k < 3; ++k) {
      df[3 * v[k]] += (-1.0 * F[2 * k]) * kfactor;
      df[3 * v[k] + 1] += (-1.0 * F[2 * k + 1]) * kfactor;
      df[3 * v[k] + 2] += 0 * kfactor;
    }
  }
}

bool TriangularFEMForceField::build_stiffness(MatrixSink& K) {
  for (const Element& e : el_) add_element_stiffness(K, mstate.get(), {e.a, e.b, e.c}, e.J, e.D, e.rotation);
  return true;
}

void register_triangular_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "plane-stress triangles, corotational (large: J rebuilt from the current shape) or small";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
