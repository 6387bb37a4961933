// Machinery shared by the role batteries of tests/conformance: the states a
// component acts on seen as one vector of derivatives, seeded random vectors,
// moves of coordinates (Rigid3d: world-frame exponential map, as solvers do),
// rigid-body motions of whole configurations, net force and torque, and the
// comparison of two vectors with a message naming the worst entry.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/roles.h"
#include "math/types.h"

namespace sinew::conformance {

// Seeded numbers in [-1, 1].
inline std::vector<double> random_vector(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = d(gen);
  return v;
}

inline double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

inline double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// Solver-style vector ids owned by the batteries (never used by the scenes).
inline int scratch_vec(int k) {
  static const std::array<int, 3> ids = {MechanicalOps::alloc_vec(), MechanicalOps::alloc_vec(),
                                         MechanicalOps::alloc_vec()};
  return ids.at(static_cast<std::size_t>(k));
}

// The rotation every "rigid motion" of the batteries uses: 0.4 rad about (1, 2, 2)/3
// in 3D, 0.4 rad about z in 2D; the translation is (0.3, −0.2, 0.5) times the scene size.
inline Mat3 battery_rotation() { return Eigen::AngleAxisd(0.4, Vec3(1, 2, 2) / 3.0).toRotationMatrix(); }
constexpr double kPlanarAngle = 0.4;

// A list of states addressed as one vector of derivatives, state after state.
class StateSet {
 public:
  using Coords = std::vector<std::vector<double>>;

  StateSet() = default;
  explicit StateSet(std::vector<MechanicalState*> states) : states_(std::move(states)) {
    std::size_t o = 0;
    for (MechanicalState* s : states_) {
      offset_.push_back(o);
      o += s->size() * s->info().deriv_width;
    }
    size_ = o;
  }

  const std::vector<MechanicalState*>& states() const { return states_; }
  std::size_t size() const { return size_; }
  std::size_t offset(std::size_t k) const { return offset_[k]; }
  // Index of `s` in the set, or -1.
  int index_of(const MechanicalState* s) const {
    for (std::size_t k = 0; k < states_.size(); ++k)
      if (states_[k] == s) return static_cast<int>(k);
    return -1;
  }

  Coords coords(int id = kPosition) const {
    Coords x;
    for (MechanicalState* s : states_) x.push_back(s->read(id));
    return x;
  }
  void set_coords(const Coords& x, int id = kPosition) const {
    for (std::size_t k = 0; k < states_.size(); ++k) states_[k]->write(id) = x[k];
  }
  std::vector<double> get(int id) const {
    std::vector<double> v;
    v.reserve(size_);
    for (MechanicalState* s : states_) {
      const auto& a = s->read(id);
      v.insert(v.end(), a.begin(), a.end());
    }
    return v;
  }
  void set(int id, const std::vector<double>& v) const {
    for (std::size_t k = 0; k < states_.size(); ++k) {
      auto& a = states_[k]->write(id);
      std::copy(v.begin() + static_cast<long>(offset_[k]), v.begin() + static_cast<long>(offset_[k] + a.size()),
                a.begin());
    }
  }
  void fill(int id, double value = 0.0) const {
    for (MechanicalState* s : states_) std::fill(s->write(id).begin(), s->write(id).end(), value);
  }

  // Whether scalar i of the derivative vector is a rotation (Rigid3d ω, Rigid2d θ̇).
  bool is_rotation(std::size_t i) const {
    const auto [k, local] = locate(i);
    const StateType t = states_[k]->state_type();
    const int c = static_cast<int>(local % states_[k]->info().deriv_width);
    return (t == StateType::rigid3 && c >= 3) || (t == StateType::rigid2 && c == 2);
  }
  // Positions x0 ⊕ h·u on kPosition: x0 + h·u, Rigid3d orientations rotated by exp(h·ω).
  void move(const Coords& x0, const std::vector<double>& u, double h) const {
    const int tmp = scratch_vec(0);
    set_coords(x0);
    set(tmp, u);
    for (MechanicalState* s : states_) s->add_deriv_to_coord(kPosition, kPosition, tmp, h);
  }
  // A random direction of derivatives: translations scaled by `length`, rotations in radians.
  std::vector<double> random_direction(unsigned seed, double length) const {
    std::vector<double> u = random_vector(size_, seed);
    for (std::size_t i = 0; i < u.size(); ++i)
      if (!is_rotation(i)) u[i] *= length;
    return u;
  }
  // Whether rigid_motion() moves states of this kind (Vec1d and Vec6d are left alone).
  bool all_spatial() const {
    for (MechanicalState* s : states_) {
      const StateType t = s->state_type();
      if (t == StateType::vec1 || t == StateType::vec6) return false;
    }
    return true;
  }
  // The coordinates moved as one rigid body by the battery rotation and translation·length.
  Coords rigid_motion(const Coords& x, double length) const {
    const Mat3 R = battery_rotation();
    const Eigen::Quaterniond qR(R);
    const Vec3 t = Vec3(0.3, -0.2, 0.5) * length;
    const double c = std::cos(kPlanarAngle), sn = std::sin(kPlanarAngle);
    Coords out = x;
    for (std::size_t k = 0; k < states_.size(); ++k) {
      const StateType type = states_[k]->state_type();
      const int w = states_[k]->info().coord_width;
      auto& o = out[k];
      for (std::size_t b = 0; b + static_cast<std::size_t>(w) <= o.size(); b += static_cast<std::size_t>(w)) {
        double* p = &o[b];
        if (type == StateType::vec3 || type == StateType::rigid3) {
          const Vec3 q = R * Vec3(p[0], p[1], p[2]) + t;
          for (int i = 0; i < 3; ++i) p[i] = q[i];
          if (type == StateType::rigid3) {
            const Eigen::Quaterniond r = qR * Eigen::Quaterniond(p[6], p[3], p[4], p[5]);
            p[3] = r.x(), p[4] = r.y(), p[5] = r.z(), p[6] = r.w();
          }
        } else if (type == StateType::vec2 || type == StateType::rigid2) {
          const double x0 = p[0], y0 = p[1];
          p[0] = c * x0 - sn * y0 + t[0];
          p[1] = sn * x0 + c * y0 + t[1];
          if (type == StateType::rigid2) p[2] += kPlanarAngle;
        }
      }
    }
    return out;
  }
  // Diagonal of the bounding box of the points (1 when they all coincide).
  double length_scale() const {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (MechanicalState* s : states_) {
      const int w = s->info().coord_width, d = std::min(3, std::min(w, s->info().spatial_dim));
      const auto& x = s->read(kPosition);
      for (std::size_t b = 0; b + static_cast<std::size_t>(w) <= x.size(); b += static_cast<std::size_t>(w))
        for (int c = 0; c < d; ++c) {
          lo[c] = std::min(lo[c], x[b + c]);
          hi[c] = std::max(hi[c], x[b + c]);
        }
    }
    double l2 = 0;
    for (int c = 0; c < 3; ++c)
      if (hi[c] >= lo[c]) l2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    return l2 > 0 ? std::sqrt(l2) : 1.0;
  }
  // "'dofs' point 3 y" for scalar i of the derivative vector.
  std::string describe(std::size_t i) const {
    if (i >= size_) return "scalar " + std::to_string(i);
    const auto [k, local] = locate(i);
    const MechanicalState& s = *states_[k];
    const int w = s.info().deriv_width;
    static const char* kXyz[] = {"x", "y", "z"};
    const int c = static_cast<int>(local % w);
    std::string comp;
    if (s.state_type() == StateType::rigid3) comp = (c < 3 ? std::string("v") : std::string("ω")) + kXyz[c % 3];
    else if (s.state_type() == StateType::rigid2) comp = c < 2 ? kXyz[c] : "θ";
    else comp = c < 3 ? kXyz[c] : std::to_string(c);
    return "'" + s.name.value() + "' point " + std::to_string(local / w) + " " + comp;
  }

 private:
  std::pair<std::size_t, std::size_t> locate(std::size_t i) const {
    std::size_t k = 0;
    while (k + 1 < states_.size() && i >= offset_[k + 1]) ++k;
    return {k, i - offset_[k]};
  }
  std::vector<MechanicalState*> states_;
  std::vector<std::size_t> offset_;
  std::size_t size_ = 0;
};

// Σ forces and Σ torques about the origin of a derivative vector `f` at positions `x`
// (translations of Rigid3d carry their torque; 2D torques on z), with the sums of
// magnitudes they are compared with.
struct Wrench {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double force_scale = 0, torque_scale = 0;
};
inline Wrench net_wrench(const StateSet& set, const StateSet::Coords& x, const std::vector<double>& f) {
  Wrench w;
  for (std::size_t k = 0; k < set.states().size(); ++k) {
    const MechanicalState& s = *set.states()[k];
    const int cw = s.info().coord_width, dw = s.info().deriv_width;
    const StateType t = s.state_type();
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double* p = &x[k][i * cw];
      const double* fi = &f[set.offset(k) + i * dw];
      Vec3 P = Vec3::Zero(), F = Vec3::Zero(), T = Vec3::Zero();
      if (t == StateType::vec3 || t == StateType::rigid3) {
        P = Vec3(p[0], p[1], p[2]);
        F = Vec3(fi[0], fi[1], fi[2]);
        if (t == StateType::rigid3) T = Vec3(fi[3], fi[4], fi[5]);
      } else if (t == StateType::vec2 || t == StateType::rigid2) {
        P = Vec3(p[0], p[1], 0);
        F = Vec3(fi[0], fi[1], 0);
        if (t == StateType::rigid2) T = Vec3(0, 0, fi[2]);
      } else if (t == StateType::vec1) {
        F = Vec3(fi[0], 0, 0);
      }
      w.force += F;
      w.torque += P.cross(F) + T;
      w.force_scale += F.norm();
      w.torque_scale += P.norm() * F.norm() + T.norm();
    }
  }
  return w;
}

// |a_i − b_i| ≤ tol · max(max|a|, max|b|) for every i. The message gives the
// worst entry (named through `labels` when given) and both scales.
inline ::testing::AssertionResult near_rel(const std::vector<double>& a, const std::vector<double>& b, double tol,
                                           const std::string& a_name, const std::string& b_name,
                                           const StateSet* labels = nullptr) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << a_name << " has " << a.size() << " entries but " << b_name << " has "
                                         << b.size();
  const double scale = std::max(max_abs(a), max_abs(b));
  std::size_t worst = 0;
  double err = -1;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double e = std::fabs(a[i] - b[i]);
    if (!(e <= err)) {  // also catches NaN
      err = e;
      worst = i;
    }
  }
  if (a.empty() || err <= tol * scale) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os.precision(10);
  os << a_name << " differs from " << b_name << ": worst at "
     << (labels ? labels->describe(worst) : "entry " + std::to_string(worst)) << ": " << a[worst] << " vs "
     << b[worst] << " (difference " << err << " > " << tol << " × largest entry " << scale << ")";
  return ::testing::AssertionFailure() << os.str();
}

}  // namespace sinew::conformance
