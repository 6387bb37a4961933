#include "forcefield/fem/quad_bending_fem_force_field.h"

#include <cmath>
#include <limits>

#include "core/matrix_sink.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

namespace {

// Natural coordinates (ξ, η) of the four corners, in the quad's vertex order.
constexpr double kCornerXi[4] = {-1, 1, 1, -1};
constexpr double kCornerEta[4] = {-1, -1, 1, 1};

// Half lengths of the edges q0q1 and q0q3 (SOFA's l and h), from positions x.
inline void half_sides(const double* x, const std::array<unsigned, 4>& v, double& l, double& h) {
  const double* p0 = x + 3 * v[0];
  const double* p1 = x + 3 * v[1];
  const double* p3 = x + 3 * v[3];
  const double a0 = p1[0] - p0[0], a1 = p1[1] - p0[1], a2 = p1[2] - p0[2];
  const double b0 = p3[0] - p0[0], b1 = p3[1] - p0[1], b2 = p3[2] - p0[2];
  l = std::sqrt(a0 * a0 + a1 * a1 + a2 * a2) / 2;
  h = std::sqrt(b0 * b0 + b1 * b1 + b2 * b2) / 2;
}

inline bool usable_side(double s) { return std::isfinite(s) && s > std::numeric_limits<double>::epsilon(); }

// Membrane (2×2 Gauss points, summed in SOFA's order) and transverse shear
// (one point, weight 2·2) stiffness of one element with half sides l, h.
void element_stiffness(QuadBendingFEMForceField::Element& e, double l, double h) {
  const double lh = l * h;
  const double c00 = e.c00, c01 = e.c01, c22 = e.c22;
  const double g = std::sqrt(3.0) / 3;
  const double gauss[4][2] = {{g, g}, {-g, g}, {g, -g}, {-g, -g}};
  e.kxy.fill(0.0);
  for (const auto& gp : gauss) {
    // dN/dx (a) and dN/dy (b) of each corner at this Gauss point.
    double a[4], b[4];
    for (int i = 0; i < 4; ++i) {
      a[i] = kCornerXi[i] * (1 + kCornerEta[i] * gp[1]) / (4 * l);
      b[i] = kCornerEta[i] * (1 + kCornerXi[i] * gp[0]) / (4 * h);
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double* rx = e.kxy.data() + (2 * i) * 8 + 2 * j;
        double* ry = e.kxy.data() + (2 * i + 1) * 8 + 2 * j;
        rx[0] += lh * (a[i] * c00 * a[j] + b[i] * c22 * b[j]);
        rx[1] += lh * (a[i] * c01 * b[j] + b[i] * c22 * a[j]);
        ry[0] += lh * (b[i] * c01 * a[j] + a[i] * c22 * b[j]);
        ry[1] += lh * (b[i] * c00 * b[j] + a[i] * c22 * a[j]);
      }
  }
  const double cs = e.cs;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double dxi = kCornerXi[i] / (4 * l), dxj = kCornerXi[j] / (4 * l);
      const double dyi = kCornerEta[i] / (4 * h), dyj = kCornerEta[j] / (4 * h);
      e.kz[4 * i + j] = lh * (dxi * cs * dxj + dyi * cs * dyj) * 2 * 2;
    }
}

// F = K·D on the translational unknowns: D holds (x y z) per corner.
inline void apply(const QuadBendingFEMForceField::Element& e, const double (&D)[12], double (&F)[12]) {
  double dxy[8], dz[4];
  for (int k = 0; k < 4; ++k) {
    dxy[2 * k] = D[3 * k];
    dxy[2 * k + 1] = D[3 * k + 1];
    dz[k] = D[3 * k + 2];
  }
  for (int r = 0; r < 8; ++r) {
    const double* row = e.kxy.data() + 8 * r;
    double s = row[0] * dxy[0];
    for (int c = 1; c < 8; ++c) s += row[c] * dxy[c];
    F[3 * (r / 2) + r % 2] = s;
  }
  for (int r = 0; r < 4; ++r) {
    const double* row = e.kz.data() + 4 * r;
    F[3 * r + 2] = row[0] * dz[0] + row[1] * dz[1] + row[2] * dz[2] + row[3] * dz[3];
  }
}

}  // namespace

void QuadBendingFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("only Vec3d states are supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (method.value() != "small")
    msg_warning("method " + quote_value(method.value()) + " is not implemented (as in SOFA): using small");
  if (young_modulus.get().empty() || poisson_ratio.get().empty()) {
    msg_error("youngModulus and poissonRatio must not be empty");
    set_state(ComponentState::invalid);
    return;
  }
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (a quad mesh is required)");
    set_state(ComponentState::invalid);
    return;
  }
  if (topology->quads().empty()) msg_warning("no quads found in the topology " + topology->describe());
  if (!rebuild()) set_state(ComponentState::invalid);
}

void QuadBendingFEMForceField::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

void QuadBendingFEMForceField::fail(const std::string& why) {
  msg_error(why);
  set_state(ComponentState::invalid);
  el_.clear();
}

bool QuadBendingFEMForceField::rebuild() {
  const auto& quads = topology->quads();
  quads_version_ = topology->elements_version(MeshTopologyBase::Elements::quads);
  const std::size_t np = mstate->size();
  const double* x0 = mstate->read(kRestPosition).data();
  const auto& ey = young_modulus.get();
  const auto& pr = poisson_ratio.get();
  const double t = thickness.get();
  if (pr.size() == 1 && (pr[0] <= -1 || pr[0] >= 0.5))
    msg_warning("poissonRatio is " + parse::format_double(pr[0]) + " (must be in (-1, 0.5))");
  if (t <= 0) msg_warning("thickness is " + parse::format_double(t) + ": the quads have no stiffness");
  el_.assign(quads.size(), Element{});
  for (std::size_t i = 0; i < quads.size(); ++i) {
    const Quad& q = quads[i];
    Element& e = el_[i];
    for (int k = 0; k < 4; ++k) {
      if (q[k] >= np) {
        msg_error("quad " + std::to_string(i) + " refers to point " + std::to_string(q[k]) + " but the state has " +
                  std::to_string(np) + " points");
        el_.clear();
        return false;
      }
      e.v[k] = q[k];
    }
    double l = 0, h = 0;
    half_sides(x0, e.v, l, h);
    if (!usable_side(l) || !usable_side(h)) {
      msg_error("quad " + std::to_string(i) + " is degenerate in its rest shape (edge q0q1 or q0q3 of zero length)");
      el_.clear();
      return false;
    }
    // Rest corners relative to the centroid of the diagonal q0q2.
    const double* r0 = x0 + 3 * e.v[0];
    const double* r2 = x0 + 3 * e.v[2];
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) e.rest[3 * k + c] = x0[3 * e.v[k] + c] - (r0[c] + r2[c]) / 2;
    const double y = ey.size() > i ? ey[i] : ey[0];
    const double p = pr.size() > i ? pr[i] : pr[0];
    e.c00 = y * t / (1 - p * p);
    e.c01 = p * y * t / (1 - p * p);
    e.c22 = y * t * (1 - p) / (2 - 2 * p * p);
    constexpr double kappa = 5.0 / 6.0;  // shear correction factor
    e.cs = kappa * y * t / (2 + 2 * p);
  }
  // A stiffness is ready before the first add_force (matrix-only callers).
  return update_stiffness(mstate->read(kPosition).data());
}

bool QuadBendingFEMForceField::update_stiffness(const double* x) {
  for (std::size_t i = 0; i < el_.size(); ++i) {
    Element& e = el_[i];
    double l = 0, h = 0;
    half_sides(x, e.v, l, h);
    if (!usable_side(l) || !usable_side(h)) {
      const Node* root = node() ? node()->root() : nullptr;
      fail("quad " + std::to_string(i) + " is degenerate (edge q0q1 or q0q3 of zero length)" +
           (root ? " at step " + std::to_string(root->step_index) : std::string()) + ": the force field stops");
      return false;
    }
    element_stiffness(e, l, h);
  }
  return true;
}

void QuadBendingFEMForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  if (topology->elements_version(MeshTopologyBase::Elements::quads) != quads_version_ && !rebuild()) {
    set_state(ComponentState::invalid);
    el_.clear();
    return;
  }
  MechanicalState& s = *mstate;
  // SOFA sizes K from the state's current positions, and the displacement from x.
  if (!update_stiffness(s.read(kPosition).data())) return;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  for (const Element& e : el_) {
    const double* p0 = x + 3 * e.v[0];
    const double* p2 = x + 3 * e.v[2];
    double D[12], F[12];
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) {
        const double centroid = (p0[c] + p2[c]) / 2;
        D[3 * k + c] = e.rest[3 * k + c] - (x[3 * e.v[k] + c] - centroid);
      }
    apply(e, D, F);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) f[3 * e.v[k] + c] += F[3 * k + c];
  }
}

void QuadBendingFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  for (const Element& e : el_) {
    double D[12], F[12];
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) D[3 * k + c] = dx[3 * e.v[k] + c];
    apply(e, D, F);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) df[3 * e.v[k] + c] += (-1.0 * F[3 * k + c]) * kfactor;
  }
}

bool QuadBendingFEMForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  for (const Element& e : el_)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        // −K: x, y coupled by the membrane, z alone by the shear; the zero
        // cross terms are emitted so the pattern does not depend on values.
        Mat3 b = Mat3::Zero();
        b(0, 0) = -e.kxy[(2 * i) * 8 + 2 * j];
        b(0, 1) = -e.kxy[(2 * i) * 8 + 2 * j + 1];
        b(1, 0) = -e.kxy[(2 * i + 1) * 8 + 2 * j];
        b(1, 1) = -e.kxy[(2 * i + 1) * 8 + 2 * j + 1];
        b(2, 2) = -e.kz[4 * i + j];
        K.add_block(s, 3 * e.v[i], s, 3 * e.v[j], b);
      }
  return true;
}

void register_quad_bending_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "QuadBendingFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "quad plate elements (small displacements): membrane in world x, y and transverse shear in z";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<QuadBendingFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
