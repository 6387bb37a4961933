// TaitSurfacePressureForceField: the volume V enclosed by a closed surface (the topology's
// triangles, then its quads split as (0,1,2), (2,3,0)) under Tait's pressure law
//   P = p0 − B·((V/V0)^γ − 1),   dP/dV = −B·γ·(V/V0)^γ / V
// (B = 0, γ = 0 or V0 = 0: P = p0 and no stiffness; γ = 1: the ideal-gas line). Each vertex
// receives P·∂V/∂x, with ∂V/∂x_i = Σ_{triangles ∋ i} (x1−x0)×(x2−x0) / 6.
// V0 = initial volume (of the rest positions) + the injected volume; injectedVolume is
// reached at maxInjectionRate per second, one step at a time on AnimateBegin.
// Volumes are signed sums of tetrahedra from the mean of the points. After a topology
// change the rest volume is measured again and the current volume offset by the difference
// (SOFA's volumeAfterTC).
// Tangent: df = k·(dP/dV·(∂V/∂x·dx)·∂V/∂x + P·∂²V/∂x²·dx), as SOFA (addDForce, with the
// per-triangle term added to the three vertices; the assembled matrix leaves out the
// diagonal blocks of that term, which cancel on a closed surface, as SOFA's does).
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

class TaitSurfacePressureForceField final : public ForceField {
 public:
  Field<double> p0{this, "p0", 0.0, "rest pressure (when V = V0)", "Controls", "pressure (force/length²)"};
  Field<double> bulk{this, "B", 0.0, "bulk modulus (resistance to uniform compression)", "Controls",
                     "pressure (force/length²)"};
  Field<double> gamma{this, "gamma", 0.0, "exponent of Tait's law (1: ideal gas, 7: water)", "Controls"};
  Field<double> injected_volume{this, "injectedVolume", 0.0,
                                "volume injected (or extracted) since the start of the simulation", "Controls",
                                "volume"};
  Field<double> max_injection_rate{this, "maxInjectionRate", 1000.0, "maximum injection rate (volume per second)",
                                   "Controls", "volume/time"};
  Field<double> initial_volume{this, "initialVolume", 0.0, "initial volume, from the rest positions (output)",
                               "Results", "volume"};
  Field<double> current_injected_volume{this, "currentInjectedVolume", 0.0,
                                        "volume injected so far, limited by maxInjectionRate (output)", "Results",
                                        "volume"};
  Field<double> v0{this, "v0", 0.0, "rest volume: initialVolume + currentInjectedVolume (output)", "Results",
                   "volume"};
  Field<double> current_volume{this, "currentVolume", 0.0, "volume at the last positions (output)", "Results",
                               "volume"};
  Field<double> current_pressure{this, "currentPressure", 0.0, "pressure at the last positions (output)",
                                 "Results", "pressure (force/length²)"};
  Field<double> current_stiffness{this, "currentStiffness", 0.0, "dP/dV at the last positions (output)",
                                  "Results"};
  Field<std::vector<Triangle>> pressure_triangles{
      this, "pressureTriangles", {}, "triangles the pressure acts on: the mesh's and its split quads (output)",
      "Results"};
  Field<double> initial_surface_area{this, "initialSurfaceArea", 0.0, "surface area of the rest positions (output)",
                                     "Stats", "area"};
  Field<double> current_surface_area{this, "currentSurfaceArea", 0.0,
                                     "surface area at the last positions (output)", "Stats", "area"};
  Field<double> draw_force_scale{this, "drawForceScale", 0.001, "scale of the drawn force vectors (viewer)",
                                 "Visualization"};
  Field<std::string> draw_force_color{this, "drawForceColor", "0 1 1 1", "colour of the drawn forces (viewer)",
                                      "Visualization"};
  Field<double> volume_after_tc{this, "volumeAfterTC", 0.0, "rest volume after a topology change (output)",
                                "Results", "volume"};
  Field<double> surface_area_after_tc{this, "surfaceAreaAfterTC", 0.0,
                                      "rest surface area after a topology change (output)", "Results", "area"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the surface (default: the node's)"};

  void init() override {
    ForceField::init();
    if (state() != ComponentState::valid) return;
    if (!topology) topology.set(node()->get_mesh_topology_link());
    if (!topology) {
      msg_error("no topology found (a closed triangle or quad surface is required)");
      set_state(ComponentState::invalid);
      return;
    }
    if (mstate->state_type() != StateType::vec3) {
      msg_error(std::string("only Vec3d states are supported, not ") + mstate->info().name);
      set_state(ComponentState::invalid);
      return;
    }
    seen_ = false;
    update_from_topology();
    if (state() != ComponentState::valid) return;
    double area = 0;
    current_volume.set(volume_and_area(mstate->read(kPosition), area));
    current_surface_area.set(area);
    double p = 0, k = 0;
    pressure_and_stiffness(current_volume.get(), v0.get(), p, k);
    current_pressure.set(p);
    current_stiffness.set(k);
  }

  void store_reset_state() override {
    reset_injected_ = injected_volume.get();
    reset_current_injected_ = current_injected_volume.get();
  }

  void reset() override {
    injected_volume.set(reset_injected_);
    current_injected_volume.set(reset_current_injected_);
    update_from_topology();
  }

  bool wants_events() const override { return true; }

  void handle_event(Event& e) override {
    if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid) return;
    const double inj = injected_volume.get();
    double cur = current_injected_volume.get();
    if (inj == cur) return;
    const double max_step = max_injection_rate.get() * e.dt;
    if (std::abs(inj - cur) <= max_step) cur = inj;
    else if (inj < cur) cur -= max_step;
    else if (inj > cur) cur += max_step;
    current_injected_volume.set(cur);
    update_from_topology();
  }

  void add_force(const MechParams& p) override {
    if (state() != ComponentState::valid) return;
    update_from_topology();
    const std::vector<double>& x = mstate->read(p.x);
    std::vector<double>& f = mstate->write(p.f);
    double area = 0;
    double volume = volume_and_area(x, area);
    current_volume.set(volume);
    current_surface_area.set(area);
    if (tc_set_) volume -= volume_after_tc.get() - initial_volume.get();
    double pressure = 0, stiffness = 0;
    pressure_and_stiffness(volume, v0.get(), pressure, stiffness);
    current_pressure.set(pressure);
    current_stiffness.set(stiffness);

    const std::size_t n = x.size() / 3;
    grad_.assign(n, Vec3::Zero());
    for (const Triangle& t : tris_) {
      const Vec3 n3 = (at(x, t[1]) - at(x, t[0])).cross(at(x, t[2]) - at(x, t[0]));
      for (int k = 0; k < 3; ++k) grad_[t[k]] += n3;
    }
    for (Vec3& g : grad_) g /= 6.0;
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) f[3 * i + c] += grad_[i][c] * pressure;
  }

  void add_dforce(const MechParams& p, double kfactor) override {
    if (state() != ComponentState::valid) return;
    const std::vector<double>& dx = mstate->read(p.dx);
    const std::vector<double>& x = mstate->read(p.x);
    std::vector<double>& df = mstate->write(p.df);
    const double pressure = current_pressure.get(), stiffness = current_stiffness.get();
    double dv = 0;
    for (std::size_t i = 0; i < grad_.size(); ++i) dv += grad_[i].dot(at(dx, i));
    const double s1 = kfactor * stiffness * dv;
    const std::size_t n = std::min(grad_.size(), x.size() / 3);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) df[3 * i + c] += grad_[i][c] * s1;
    const double s2 = kfactor * pressure / 6.0;
    for (const Triangle& t : tris_) {
      const Vec3 d = ((at(dx, t[1]) - at(dx, t[0])).cross(at(x, t[2]) - at(x, t[0])) +
                      (at(x, t[1]) - at(x, t[0])).cross(at(dx, t[2]) - at(dx, t[0]))) *
                     s2;
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) df[3 * t[k] + c] += d[c];
    }
  }

  bool build_stiffness(MatrixSink& K) override {
    if (state() != ComponentState::valid) return true;
    const MechanicalState* s = mstate.get();
    const double pressure = current_pressure.get(), stiffness = current_stiffness.get();
    if (stiffness != 0) {
      for (std::size_t i = 0; i < grad_.size(); ++i) {
        const Vec3 di = grad_[i] * stiffness;
        for (std::size_t j = 0; j < grad_.size(); ++j) K.add_block(s, 3 * i, s, 3 * j, di * grad_[j].transpose());
      }
    }
    if (pressure != 0) {
      const std::vector<double>& x = s->read(kPosition);
      const double scale = pressure / 6.0;
      for (const Triangle& t : tris_) {
        const Mat3 mbc = cross_matrix((at(x, t[2]) - at(x, t[1])) * scale);
        const Mat3 mca = cross_matrix((at(x, t[0]) - at(x, t[2])) * scale);
        const Mat3 mab = cross_matrix((at(x, t[1]) - at(x, t[0])) * scale);
        K.add_block(s, 3 * t[0], s, 3 * t[1], mca);
        K.add_block(s, 3 * t[0], s, 3 * t[2], mab);
        K.add_block(s, 3 * t[1], s, 3 * t[0], mbc);
        K.add_block(s, 3 * t[1], s, 3 * t[2], mab);
        K.add_block(s, 3 * t[2], s, 3 * t[0], mbc);
        K.add_block(s, 3 * t[2], s, 3 * t[1], mca);
      }
    }
    return true;
  }

  // Last ∂V/∂x (tests).
  const std::vector<Vec3>& volume_gradient() const { return grad_; }

 private:
  static Vec3 at(const std::vector<double>& v, std::size_t i) { return Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]); }

  static Mat3 cross_matrix(const Vec3& u) {
    Mat3 m;
    m << 0, -u[2], u[1], u[2], 0, -u[0], -u[1], u[0], 0;
    return m;
  }

  // The pressure triangles, the rest volume and area when the topology's lists moved.
  void update_from_topology() {
    const auto tv = topology->elements_version(MeshTopologyBase::Elements::triangles);
    const auto qv = topology->elements_version(MeshTopologyBase::Elements::quads);
    if (!seen_ || tv != tri_version_ || qv != quad_version_) {
      if (seen_)
        msg_warning("the topology changed: the rest volume is measured again and the current volume corrected");
      tri_version_ = tv;
      quad_version_ = qv;
      tris_.clear();
      const std::size_t np = mstate->size();
      for (const Triangle& t : topology->triangles()) tris_.push_back(t);
      for (const Quad& q : topology->quads()) {
        tris_.push_back(Triangle{q[0], q[1], q[2]});
        tris_.push_back(Triangle{q[2], q[3], q[0]});
      }
      for (std::size_t e = 0; e < tris_.size(); ++e)
        for (int k = 0; k < 3; ++k)
          if (tris_[e][k] >= np) {
            msg_error("pressure triangle " + std::to_string(e) + " uses point " + std::to_string(tris_[e][k]) +
                      " but the state has " + std::to_string(np) + " points");
            set_state(ComponentState::invalid);
            tris_.clear();
            return;
          }
      if (tris_.empty()) msg_warning("the topology " + topology->describe() + " has no triangles or quads");
      pressure_triangles.set(tris_);
      double area = 0;
      volume_after_tc.set(volume_and_area(mstate->read(kRestPosition), area));
      surface_area_after_tc.set(area);
      tc_set_ = true;
      if (!seen_) {
        initial_volume.set(volume_after_tc.get());
        initial_surface_area.set(area);
      }
      seen_ = true;
    }
    v0.set(initial_volume.get() + current_injected_volume.get());
  }

  // Signed volume (Σ (a×b)·c / 6 from the points' mean) and area of the pressure triangles.
  double volume_and_area(const std::vector<double>& x, double& area) const {
    area = 0;
    const std::size_t n = x.size() / 3;
    if (n == 0) return 0;
    Vec3 center = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i) center += at(x, i);
    center /= static_cast<double>(n);
    double volume6 = 0, area2 = 0;
    for (const Triangle& t : tris_) {
      const Vec3 a = at(x, t[0]) - center, b = at(x, t[1]) - center, c = at(x, t[2]) - center;
      volume6 += a.cross(b).dot(c);
      area2 += (b - a).cross(c - a).norm();
    }
    area = area2 / 2.0;
    return volume6 / 6.0;
  }

  void pressure_and_stiffness(double volume, double rest, double& pressure, double& stiffness) {
    if (volume > 10 * rest || 10 * volume < rest) {
      if (!warned_variation_)
        msg_warning("the volume (" + std::to_string(volume) + ") is more than 10 times away from V0 (" +
                    std::to_string(rest) + ")");
      warned_variation_ = true;
    }
    const double B = bulk.get(), g = gamma.get(), p = p0.get();
    if (B == 0 || g == 0 || rest == 0) {
      stiffness = 0;
      pressure = p;
    } else if (g == 1) {
      stiffness = -B / rest;
      pressure = p - B * (volume / rest - 1);
    } else {
      const double r = std::pow(volume / rest, g);
      stiffness = volume == 0 ? 0 : -B * g * r / volume;
      pressure = p - B * (r - 1);
    }
  }

  std::vector<Triangle> tris_;
  std::vector<Vec3> grad_;
  std::uint64_t tri_version_ = 0, quad_version_ = 0;
  bool seen_ = false, tc_set_ = false, warned_variation_ = false;
  double reset_injected_ = 0, reset_current_injected_ = 0;
};

}  // namespace

void register_tait_surface_pressure_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TaitSurfacePressureForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "pressure of an enclosed volume following Tait's law on a closed surface";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TaitSurfacePressureForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
