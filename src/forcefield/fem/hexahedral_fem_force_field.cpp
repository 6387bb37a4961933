#include "forcefield/fem/hexahedral_fem_force_field.h"

#include <cmath>
#include <string>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "forcefield/fem/hexahedron_fem_force_field.h"

namespace sinew {

namespace {

// Corner signs of the 8 nodes in the reference cube [-1,1]³ (Hexahedron order).
constexpr int kSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

}  // namespace

namespace fem {

namespace {

inline double len3(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// ∫ over [-1,1]³ of ∂N_i/∂ξ_p · ∂N_j/∂ξ_q for the trilinear shape functions
// N = Π(1 + s_k ξ_k)/8. Per axis: ∫(1+aξ)(1+bξ) = 2 + 2ab/3, ∫(1+aξ) = 2.
double shape_gradient_integral(const int* si, const int* sj, int p, int q) {
  double r = si[p] * sj[q] / 64.0;
  for (int k = 0; k < 3; ++k) {
    if (k == p || k == q) r *= 2.0;             // zero or one shape factor on axis k: ∫ = 2
    else r *= 2.0 + 2.0 * si[k] * sj[k] / 3.0;  // both shape factors on axis k
  }
  return r;
}

}  // namespace

void hexahedral_element_stiffness(const std::array<Vec3, 8>& n, const HexaMaterial& mat, Mat24& K,
                                  bool float_entries) {
  const Vec3 l = n[6] - n[0];
  const double J[3] = {2.0 / l[0], 2.0 / l[1], 2.0 / l[2]};  // J⁻¹, exact only for axis-aligned boxes
  const double vol = len3(n[1] - n[0]) * len3(n[3] - n[0]) * len3(n[4] - n[0]) / 8.0;
  K.setZero();
  for (int i = 0; i < 8; ++i)
    for (int j = i; j < 8; ++j) {
      const int* si = kSign[i];
      const int* sj = kSign[j];
      double G[3][3];
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) G[p][q] = shape_gradient_integral(si, sj, p, q);
      for (int m = 0; m < 3; ++m)
        for (int c = 0; c < 3; ++c) {
          double k;
          if (m == c) {
            // Normal term plus the two shear terms, all scaled by axis m (SOFA's form).
            double shear = 0;
            for (int a = 0; a < 3; ++a)
              if (a != m) shear += G[a][a];
            k = J[m] * J[m] * (mat.u * G[m][m] + mat.w * shear);
          } else {
            k = J[m] * J[c] * (mat.v * G[m][c] + mat.w * G[c][m]);
          }
          // SOFA stores the integrated entry as a float before scaling by the volume.
          if (float_entries) k = static_cast<float>(k);
          K(3 * i + m, 3 * j + c) += vol * k;
        }
    }
  for (int r = 0; r < 24; ++r)
    for (int c = r + 1; c < 24; ++c) K(c, r) = K(r, c);
}

}  // namespace fem

namespace {

// True when the 8 nodes form a box whose edges follow the world axes (to 1e-6
// of the diagonal): the only shape SOFA's closed-form stiffness is meant for.
bool axis_aligned_box(const std::array<Vec3, 8>& n, bool& cube) {
  const Vec3 l = n[6] - n[0];
  const double tol = 1e-6 * l.norm();
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) {
      const double expect = n[0][c] + (kSign[k][c] > 0 ? l[c] : 0.0);
      if (std::fabs(n[k][c] - expect) > tol) return false;
    }
  cube = std::fabs(std::fabs(l[0]) - std::fabs(l[1])) <= tol && std::fabs(std::fabs(l[0]) - std::fabs(l[2])) <= tol;
  return true;
}
}  // namespace

template <class Role>
void HexahedralFEMBase<Role>::init() {
  Role::init();
  if (this->state() != ComponentState::valid) return;
  if (!topology) topology.set(this->node()->get_mesh_topology_link());
  if (!topology) {
    this->msg_error("no topology found (a hexahedral mesh is required)");
    this->set_state(ComponentState::invalid);
    return;
  }
  const auto& hexas = topology->hexahedra();
  hexa_version_ = topology->elements_version(MeshTopologyBase::Elements::hexahedra);
  if (hexas.empty()) {
    this->msg_error("Object must have a Topology with hexahedra: " + topology->describe() + " has none");
    this->set_state(ComponentState::invalid);
    return;
  }
  fem::HexaMethod m;
  if (method.value() == "large") m = fem::HexaMethod::large;
  else if (method.value() == "polar") m = fem::HexaMethod::polar;
  else {
    // SOFA leaves its method undefined here; "small" exists only in HexahedronFEMForceField.
    this->msg_error("unknown method '" + method.value() + "' (expected large or polar)");
    this->set_state(ComponentState::invalid);
    return;
  }
  MechanicalState& s = *this->mstate;
  if (s.state_type() != StateType::vec3) {
    this->msg_error("only Vec3d states are supported");
    this->set_state(ComponentState::invalid);
    return;
  }
  const std::size_t ne = hexas.size();
  std::vector<double> E, nu;
  hexa_element_materials(*this, young_modulus.get(), poisson_ratio.get(), ne, E, nu);
  const auto x0 = as_vec3(s.read(kRestPosition));
  std::vector<std::array<int, 8>> h(ne);
  for (std::size_t i = 0; i < ne; ++i)
    for (int k = 0; k < 8; ++k) h[i][k] = static_cast<int>(hexas[i][k]);

  // Frames, rotated rest nodes, index checks: the Hexahedron kernel's (same in SOFA).
  bool fatal = false;
  for (const auto& is : fem_.init(x0, h, E, nu, m)) {
    const std::string where = is.element >= 0 ? "element " + std::to_string(is.element) + ": " : "";
    if (is.fatal) this->msg_error(where + is.message);
    else this->msg_warning(where + is.message);
    fatal = fatal || is.fatal;
  }
  if (fatal) {
    this->set_state(ComponentState::invalid);
    return;
  }
  // Stiffness: SOFA's closed form on the unrotated rest nodes replaces the kernel's Gauss K.
  int not_box = 0, not_cube = 0, first_not_box = -1, first_not_cube = -1;
  for (std::size_t e = 0; e < ne; ++e) {
    std::array<Vec3, 8> nodes;
    for (int k = 0; k < 8; ++k) nodes[k] = x0[h[e][k]];
    // SOFA divides by each component of the diagonal n6 − n0: a (near) zero one
    // gives an infinite or absurd stiffness (flat element, or one turned in its plane).
    const Vec3 l = nodes[6] - nodes[0];
    if (std::fabs(l[0]) <= 1e-6 * l.norm() || std::fabs(l[1]) <= 1e-6 * l.norm() ||
        std::fabs(l[2]) <= 1e-6 * l.norm()) {
      this->msg_error("element " + std::to_string(e) + ": the diagonal n6 - n0 = (" + parse::format_double(l[0]) + " " +
                parse::format_double(l[1]) + " " + parse::format_double(l[2]) +
                ") has a zero component: SOFA's closed-form stiffness cannot be computed (flat or rotated element; "
                "use HexahedronFEMForceField)");
      fatal = true;
      continue;
    }
    fem::hexahedral_element_stiffness(nodes, fem_.material[e], fem_.K[e]);
    if (!fem_.K[e].allFinite()) {
      this->msg_error("element " + std::to_string(e) + ": non-finite stiffness (check youngModulus, poissonRatio, positions)");
      fatal = true;
      continue;
    }
    bool cube = false;
    if (!axis_aligned_box(nodes, cube)) {
      if (not_box++ == 0) first_not_box = static_cast<int>(e);
    } else if (!cube) {
      if (not_cube++ == 0) first_not_cube = static_cast<int>(e);
    }
  }
  fem_.touch_stiffness();
  if (fatal) {
    this->set_state(ComponentState::invalid);
    return;
  }
  if (not_box > 0)
    this->msg_warning(std::to_string(not_box) + " element(s) (first: " + std::to_string(first_not_box) +
                ") are not axis-aligned boxes: SOFA's closed-form stiffness, reproduced here, is wrong for them "
                "(use HexahedronFEMForceField)");
  if (not_cube > 0)
    this->msg_info(std::to_string(not_cube) + " element(s) (first: " + std::to_string(first_not_cube) +
             ") are not cubes: SOFA's closed-form stiffness scales the shear terms of each diagonal entry "
             "by one edge length, so it differs from HexahedronFEMForceField on them");
}

template <class Role>
void HexahedralFEMBase<Role>::follow_topology() {
  if (!topology || topology->elements_version(MeshTopologyBase::Elements::hexahedra) == hexa_version_) return;
  if (topology->hexahedra().empty()) {
    // Every element was removed: no force, no error.
    fem_ = fem::HexaFEM{};
    hexa_version_ = topology->elements_version(MeshTopologyBase::Elements::hexahedra);
    return;
  }
  init();
}

template <class Role>
void HexahedralFEMBase<Role>::add_force(const MechParams& p) {
  if (this->state() != ComponentState::valid) return;
  follow_topology();
  if (this->state() != ComponentState::valid) return;
  MechanicalState& s = *this->mstate;
  fem_.add_force(as_vec3(s.read(p.x)), as_vec3(s.write(p.f)));
}

template <class Role>
void HexahedralFEMBase<Role>::add_dforce(const MechParams& p, double kfactor) {
  if (this->state() != ComponentState::valid) return;
  follow_topology();
  if (this->state() != ComponentState::valid) return;
  MechanicalState& s = *this->mstate;
  fem_.add_dforce(as_vec3(s.read(p.dx)), as_vec3(s.write(p.df)), kfactor);
}

template <class Role>
bool HexahedralFEMBase<Role>::build_stiffness(MatrixSink& sink) {
  if (this->state() != ComponentState::valid) return true;
  follow_topology();
  if (this->state() != ComponentState::valid) return true;
  const MechanicalState* s = this->mstate.get();
  // SOFA stores Q = Rᵀ (element → world) but assembles −Qᵀ·K_ij·Q as if Q
  // were R, i.e. −R·K_ij·Rᵀ, not the −Rᵀ·K_ij·R that add_dforce applies.
  // Summation order as SOFA's: t = R·K_ij first, then t·Rᵀ.
  for (std::size_t e = 0; e < fem_.size(); ++e) {
    if (!fem_.active[e]) continue;
    const Mat3& R = fem_.R[e];
    const fem::Mat24& K = fem_.K[e];
    const auto& h = fem_.hexa[e];
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        Mat3 t, b;
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 3; ++c)
            t(a, c) = R(a, 0) * K(3 * i, 3 * j + c) + R(a, 1) * K(3 * i + 1, 3 * j + c) +
                      R(a, 2) * K(3 * i + 2, 3 * j + c);
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 3; ++c) b(a, c) = -(t(a, 0) * R(c, 0) + t(a, 1) * R(c, 1) + t(a, 2) * R(c, 2));
        sink.add_block(s, 3 * h[i], s, 3 * h[j], b);
      }
  }
  return true;
}

template class HexahedralFEMBase<ForceField>;
template class HexahedralFEMBase<Mass>;

void HexahedralFEMForceFieldAndMass::init() {
  HexahedralFEMBase<Mass>::init();
  if (state() != ComponentState::valid) return;
  const std::size_t ne = fem_.size();
  const std::size_t np = mstate->size();
  // SOFA's integrateVolume with every corner sign squared (= 8/27), in its literal order.
  const double t1 = 1, t2 = 1, t3 = 1, t9 = t1 * t2;
  const double integral =
      t1 * t3 / 72.0 + t2 * t3 / 72.0 + t9 * t3 / 216.0 + t3 / 24.0 + 1.0 / 8.0 + t9 / 72.0 + t1 / 24.0 + t2 / 24.0;
  const double rho = density.value();
  element_mass_.assign(ne, 0.0);
  particle_mass_.assign(np, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& n = fem_.rest[e];  // the rotated rest element (SOFA's rotatedInitialElements)
    const double volume = fem::len3(n[1] - n[0]) * fem::len3(n[3] - n[0]) * fem::len3(n[4] - n[0]);
    const double total = volume * rho;
    element_mass_[e] = total * integral;
    const double corner = total * 0.125;
    for (int w = 0; w < 8; ++w) particle_mass_[fem_.hexa[e][w]] += corner;
  }
  lumped_.clear();
  if (lumped_mass.value()) {
    lumped_.assign(np, Vec3::Zero());
    for (std::size_t e = 0; e < ne; ++e)
      for (int w = 0; w < 8; ++w)
        for (int j = 0; j < 8; ++j)  // the 8 non-zero entries of each row of M_e
          for (int c = 0; c < 3; ++c) lumped_[fem_.hexa[e][w]][c] += element_mass_[e];
  }
}

void HexahedralFEMForceFieldAndMass::add_force(const MechParams& p) {
  HexahedralFEMBase<Mass>::add_force(p);
  if (state() != ComponentState::valid || separate_gravity.value()) return;
  auto f = as_vec3(mstate->write(p.f));
  const Vec3 g = node()->gravity.value();
  for (std::size_t i = 0; i < particle_mass_.size() && i < f.size(); ++i) f[i] += g * particle_mass_[i];
}

void HexahedralFEMForceFieldAndMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  if (state() != ComponentState::valid) return;
  auto f = as_vec3(mstate->write(res));
  const auto d = as_vec3(mstate->read(dx));
  if (lumped_mass.value()) {
    for (std::size_t i = 0; i < lumped_.size() && i < f.size(); ++i)
      for (int c = 0; c < 3; ++c) f[i][c] += lumped_[i][c] * d[i][c] * factor;
    return;
  }
  for (std::size_t e = 0; e < fem_.size(); ++e) {
    const auto& h = fem_.hexa[e];
    const double m = element_mass_[e];
    // Row (w, c) of M_e·dx: of its 24 products only the 8 on component c are
    // non-zero (adding the others' exact zeros changes nothing).
    Vec3 F;
    for (int c = 0; c < 3; ++c) {
      double s = 0.0;
      for (int j = 0; j < 8; ++j) s += m * d[h[j]][c];
      F[c] = s;
    }
    // Every row w of the element has the same sum.
    for (int w = 0; w < 8; ++w) f[h[w]] += F * factor;
  }
}

void HexahedralFEMForceFieldAndMass::acc_from_f(const MechParams&, int, int) {
  msg_warning("accFromF is not available (as in SOFA: the element mass matrices are not inverted); "
              "use an implicit solver");
}

void HexahedralFEMForceFieldAndMass::add_gravity_to_v(int v, double dt) {
  auto vv = as_vec3(mstate->write(v));
  const Vec3 dv = node()->gravity.value() * dt;
  for (std::size_t i = 0; i < particle_mass_.size() && i < vv.size(); ++i) vv[i] += dv;
}

bool HexahedralFEMForceFieldAndMass::build_mass(MatrixSink& M) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  for (std::size_t e = 0; e < fem_.size(); ++e) {
    const Mat3 block = Mat3::Identity() * element_mass_[e];
    for (int i = 0; i < 8; ++i) M.add_block(s, 3 * fem_.hexa[e][i], s, 3 * fem_.hexa[e][i], block);
  }
  return true;
}

double HexahedralFEMForceFieldAndMass::total() const {
  double t = 0;
  for (double m : particle_mass_) t += m;
  return t;
}

}  // namespace sinew

namespace sinew {

void register_hexahedral_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedralFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "corotational hexahedral finite elements (large, polar) on a topology container";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedralFEMForceField>();
  r.add(std::move(info));
}

void register_hexahedral_fem_force_field_and_mass(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedralFEMForceFieldAndMass";
  info.category = "ForceField/FEM";
  info.description = "HexahedralFEMForceField that is also the mass of its object (SOFA's element masses)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedralFEMForceFieldAndMass>();
  r.add(std::move(info));
}

}  // namespace sinew
