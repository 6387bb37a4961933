#include "state/mechanical_object.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/node.h"
#include "core/alloc_check.h"
#include "core/pseudo_attribute.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "math/rigid.h"

namespace sinew {

namespace {
FlatVec one_element(int width, bool rigid_coord) {
  FlatVec v;
  v.width = width;
  v.data.assign(width, 0.0);
  if (rigid_coord && width == 7) v.data[6] = 1.0;  // identity quaternion (x, y, z, w)
  return v;
}
FlatVec empty_vec(int width) {
  FlatVec v;
  v.width = width;
  return v;
}
}  // namespace

MechanicalObject::MechanicalObject(StateType type)
    : position(this, "position", one_element(state_type_info(type).coord_width, true), "positions", "State"),
      velocity(this, "velocity", one_element(state_type_info(type).deriv_width, false), "velocities", "State"),
      force(this, "force", one_element(state_type_info(type).deriv_width, false), "forces (accumulator)", "State"),
      external_force(this, "externalForce", one_element(state_type_info(type).deriv_width, false),
                     "forces added from outside the solver; emptied every step", "State"),
      rest_position(this, "rest_position", empty_vec(state_type_info(type).coord_width), "rest positions", "State"),
      deriv_x(this, "derivX", empty_vec(state_type_info(type).deriv_width), "position variation (solver temporary)",
              "State"),
      free_position(this, "free_position", empty_vec(state_type_info(type).coord_width),
                    "free-motion positions", "State"),
      free_velocity(this, "free_velocity", empty_vec(state_type_info(type).deriv_width),
                    "free-motion velocities", "State"),
      reset_position(this, "reset_position", empty_vec(state_type_info(type).coord_width),
                     "positions restored by reset", "State"),
      reset_velocity(this, "reset_velocity", empty_vec(state_type_info(type).deriv_width),
                     "velocities restored by reset", "State"),
      lambda(this, "lambda", empty_vec(state_type_info(type).deriv_width),
             "constraint forces Jᵀλ of the last constraint solve (output)", "State"),
      type_(type) {
  // Transforms and names never propagate through src= links.
  for (BaseField* f : {static_cast<BaseField*>(&translation), static_cast<BaseField*>(&rotation),
                       static_cast<BaseField*>(&scale3d)})
    f->set_autolink(false);
}

Field<FlatVec>* MechanicalObject::standard(int id) {
  switch (id) {
    case kPosition: return &position;
    case kVelocity: return &velocity;
    case kForce: return &force;
    case kExternalForce: return &external_force;
    case kRestPosition: return &rest_position;
    case kDx: return &deriv_x;
    case kFreePosition: return &free_position;
    case kFreeVelocity: return &free_velocity;
    case kResetPosition: return &reset_position;
    case kResetVelocity: return &reset_velocity;
    default: return nullptr;
  }
}

bool MechanicalObject::has_vec(int id) const {
  if (Field<FlatVec>* f = const_cast<MechanicalObject*>(this)->standard(id)) return !f->value().data.empty();
  auto it = dynamic_.find(id);
  return it != dynamic_.end() && !it->second.empty();
}

void MechanicalObject::resize_vec(std::vector<double>& v, bool coord, std::size_t n) const {
  const auto& inf = info();
  const int w = coord ? inf.coord_width : inf.deriv_width;
  const std::size_t old = v.size() / w;
  v.resize(n * w, 0.0);
  if (coord && type_ == StateType::rigid3)
    for (std::size_t i = old; i < n; ++i) v[i * 7 + 6] = 1.0;
}

void MechanicalObject::resize(std::size_t n) {
  size_ = n;
  for (int id : {kPosition, kVelocity, kForce, kDx}) resize_vec(standard(id)->edit().data, is_coord_vec(id), n);
  for (int id : {kRestPosition, kFreePosition, kFreeVelocity})
    if (!standard(id)->value().data.empty()) resize_vec(standard(id)->edit().data, is_coord_vec(id), n);
  for (auto& [id, v] : dynamic_) resize_vec(v, is_coord_vec(id), n);
  if (!lambda.value().data.empty()) resize_vec(lambda.edit().data, false, n);
  size_field.set(static_cast<int>(n));
}

void MechanicalObject::remove_points(const std::vector<unsigned>& decreasing) {
  // SOFA's handleStateChange(POINTSREMOVED) → replaceValue(last, i) on every vector, then resize.
  const auto& inf = info();
  for (int id : {kPosition, kVelocity, kForce, kExternalForce, kRestPosition, kDx, kFreePosition, kFreeVelocity,
                 kResetPosition, kResetVelocity}) {
    Field<FlatVec>* f = standard(id);
    f->get();
    if (f->value().data.empty()) continue;
    if (f->parent()) f->set_parent(nullptr);  // the values now differ from the linked source
    remove_swap_last(f->edit().data, decreasing, is_coord_vec(id) ? inf.coord_width : inf.deriv_width);
  }
  for (auto& [id, v] : dynamic_) remove_swap_last(v, decreasing, is_coord_vec(id) ? inf.coord_width : inf.deriv_width);
  if (!lambda.value().data.empty()) remove_swap_last(lambda.edit().data, decreasing, inf.deriv_width);
  size_ = decreasing.size() < size_ ? size_ - decreasing.size() : 0;
  size_field.set(static_cast<int>(size_));
}

void MechanicalObject::add_points(std::size_t n, const std::vector<std::vector<unsigned>>& ancestors,
                                  const std::vector<std::vector<double>>& coefficients) {
  // SOFA: resize(prev + n) grows the allocated vectors (new entries zero), then
  // computeWeightedValue writes each new DoF as sum_j ancestor_j * coef_j, summed in ancestor
  // order from zero (DataTypes::interpolate), in every allocated vector.
  const auto& inf = info();
  const std::size_t prev = size_;
  const bool rigid = type_ == StateType::rigid2 || type_ == StateType::rigid3;
  struct Vec {
    std::vector<double>* data;
    int width;
  };
  std::vector<Vec> vecs;
  for (int id : {kPosition, kVelocity, kForce, kExternalForce, kRestPosition, kDx, kFreePosition, kFreeVelocity,
                 kResetPosition, kResetVelocity}) {
    Field<FlatVec>* f = standard(id);
    f->get();
    if (f->value().data.empty()) continue;
    if (f->parent()) f->set_parent(nullptr);  // the values now differ from the linked source
    const bool coord = is_coord_vec(id);
    std::vector<double>& d = f->edit().data;
    resize_vec(d, coord, prev + n);
    vecs.push_back({&d, coord ? inf.coord_width : inf.deriv_width});
  }
  for (auto& [id, v] : dynamic_) {
    resize_vec(v, is_coord_vec(id), prev + n);
    vecs.push_back({&v, is_coord_vec(id) ? inf.coord_width : inf.deriv_width});
  }
  if (!lambda.value().data.empty()) {
    resize_vec(lambda.edit().data, false, prev + n);
    vecs.push_back({&lambda.edit().data, inf.deriv_width});
  }
  size_ = prev + n;
  size_field.set(static_cast<int>(size_));
  if (ancestors.empty()) return;
  if (rigid) {
    msg_warning("point additions with ancestors on a rigid state: the new DoFs are not interpolated");
    return;
  }
  for (std::size_t i = 0; i < ancestors.size() && i < n; ++i) {
    const std::vector<unsigned>& anc = ancestors[i];
    const bool given = i < coefficients.size() && !coefficients[i].empty();
    for (const Vec& v : vecs) {
      double* out = v.data->data() + (prev + i) * v.width;
      for (int c = 0; c < v.width; ++c) out[c] = 0.0;
      for (std::size_t j = 0; j < anc.size(); ++j) {
        if (anc[j] >= prev + n) continue;  // checked by the modifier; never read out of range
        // SOFA's default is computed in float (1.0f / k), then widened.
        const double w = given ? (j < coefficients[i].size() ? coefficients[i][j] : 0.0)
                               : static_cast<double>(1.0f / static_cast<float>(anc.size()));
        const double* a = v.data->data() + static_cast<std::size_t>(anc[j]) * v.width;
        for (int c = 0; c < v.width; ++c) out[c] += a[c] * w;
      }
    }
  }
}

std::vector<double>& MechanicalObject::storage(int id) {
  if (Field<FlatVec>* f = standard(id)) {
    f->get();  // follows a data link (position="@loader.position") like every read
    std::vector<double>& d = f->raw().data;
    // Vectors other than externalForce always span all DOFs (allocated on demand).
    if (id != kExternalForce && d.size() != size_ * f->value().width) resize_vec(d, is_coord_vec(id), size_);
    return d;
  }
  const bool coord = is_coord_vec(id);
  auto it = dynamic_.find(id);
  if (it == dynamic_.end()) {
    it = dynamic_.emplace(id, std::vector<double>{}).first;
    resize_vec(it->second, coord, size_);
  } else if (it->second.size() != size_ * (coord ? info().coord_width : info().deriv_width)) {
    resize_vec(it->second, coord, size_);
  }
  return it->second;
}

const std::vector<double>& MechanicalObject::read(int id) const {
  // Sizing a vector on first use is not a change of value (an absent vector
  // reads as zeros), so a read may allocate without being a write.
  return const_cast<MechanicalObject*>(this)->storage(id);
}

std::vector<double>& MechanicalObject::write(int id) {
  std::vector<double>& d = storage(id);
  if (Field<FlatVec>* f = standard(id)) {
    f->mark_set();
    f->touch();
  }
  return d;
}

void MechanicalObject::touch(int id) {
  if (Field<FlatVec>* f = standard(id)) f->touch();
}

void MechanicalObject::add_deriv_to_coord(int x_out, int x_in, int v, double h) {
  const std::vector<double>& vv = read(v);
  const std::vector<double>* xi = &read(x_in);
  std::vector<double>& xo = write(x_out);
  if (type_ == StateType::rigid3) {
    for (std::size_t i = 0; i < size_; ++i) rigid3_add_deriv(&(*xi)[i * 7], &vv[i * 6], h, &xo[i * 7]);
  } else {
    for (std::size_t i = 0; i < xo.size(); ++i) xo[i] = (*xi)[i] + vv[i] * h;
  }
  touch(x_out);
}

void MechanicalObject::end_integration() { external_force.edit().data.clear(); }

void MechanicalObject::parse(AttributeMap& attrs, Diagnostics& diag) {
  // Pseudo-attributes (not fields), read as single-precision floats like SOFA.
  auto read_float = [&](const char* key, double& out) {
    if (const std::string* s = attrs.take(key)) {
      double d = 0;
      read_pseudo_number(*this, diag, key, *s, d);
      out = static_cast<double>(static_cast<float>(d));
      return true;
    }
    return false;
  };
  auto read3 = [&](const char* a, const char* b, const char* c, Field<Vec3>& f, double missing) {
    Vec3 v(missing, missing, missing);
    bool any = read_float(a, v.x());
    any = read_float(b, v.y()) || any;
    any = read_float(c, v.z()) || any;
    if (any) f.set(v);
  };
  double s = 1;
  if (read_float("scale", s)) scale3d.set(Vec3(s, s, s));
  read3("sx", "sy", "sz", scale3d, 1.0);
  read3("rx", "ry", "rz", rotation, 0.0);
  read3("dx", "dy", "dz", translation, 0.0);
  read3("rx2", "ry2", "rz2", rotation2, 0.0);
  read3("dx2", "dy2", "dz2", translation2, 0.0);
  Component::parse(attrs, diag);
  if (size_field.is_set()) {
    const int n = std::max(0, size_field.value());
    // x, v, f, dx, and the rest/free vectors solvers add: about 8 vectors per DoF.
    const double bytes = 8.0 * 8.0 * std::max(info().coord_width, info().deriv_width);
    if (check_allocation(*this, "size", std::to_string(size_field.value()), n, bytes))
      resize(static_cast<std::size_t>(n));
    else
      set_state(ComponentState::invalid);
  }
}

void MechanicalObject::apply_transform(std::vector<double>& x, const Vec3& scale, const Vec3& rot_deg,
                                       const Vec3& trans) const {
  const auto& inf = info();
  const int w = inf.coord_width;
  const int dim = std::min(3, inf.spatial_dim);
  const std::size_t n = x.size() / w;
  const bool scaled = scale != Vec3::Ones();
  const bool rotated = rot_deg != Vec3::Zero();
  const bool moved = trans != Vec3::Zero();
  const double to_rad = M_PI / 180.0;
  const Eigen::Quaterniond q = Eigen::AngleAxisd(rot_deg.z() * to_rad, Vec3::UnitZ()) *
                               Eigen::AngleAxisd(rot_deg.y() * to_rad, Vec3::UnitY()) *
                               Eigen::AngleAxisd(rot_deg.x() * to_rad, Vec3::UnitX());
  for (std::size_t i = 0; i < n; ++i) {
    double* c = &x[i * w];
    if (scaled)
      for (int k = 0; k < std::min(3, w); ++k) c[k] *= scale[k];
    if (rotated) {
      Vec3 p = Vec3::Zero();
      for (int k = 0; k < dim; ++k) p[k] = c[k];
      p = q * p;
      for (int k = 0; k < dim; ++k) c[k] = p[k];
      if (type_ == StateType::rigid3) {
        Eigen::Quaterniond o(c[6], c[3], c[4], c[5]);
        o = q * o;
        c[3] = o.x(), c[4] = o.y(), c[5] = o.z(), c[6] = o.w();
      } else if (type_ == StateType::rigid2) {
        c[2] += rot_deg.z() * to_rad;
      }
    }
    if (moved)
      for (int k = 0; k < dim; ++k) c[k] += trans[k];
  }
}

void MechanicalObject::init() {
  // 1. Topology: the first mesh topology of this node (not the node's slot).
  if (!topology && use_topology.value() && node()) topology.set(node()->find_local<MeshTopologyBase>());

  const int cw = info().coord_width, dw = info().deriv_width;
  std::vector<double> x = position.get().data;
  std::vector<double> v = velocity.get().data;
  const std::vector<double>& r = rest_position.get().data;
  // 2-3. Sizes from given vectors; rest_position wins when longer.
  const std::size_t nr_given = r.size() / cw;
  if (r.size() / cw > x.size() / cw) x = r;
  std::size_t nx = x.size() / cw, nv = v.size() / dw;
  // Mismatched sizes are accepted as SOFA does, but never silently.
  if (nv > 1 && nx != nv)
    msg_warning("velocity has " + std::to_string(nv) + " values but position has " + std::to_string(nx) +
                (nv < nx ? ": the last velocity is repeated for the other points"
                         : ": the missing positions are set to 0"));
  if (nx <= 1 && nv <= 1) {
    // 4. A single (or no) position is replaced by the topology's points.
    if (topology && topology->has_positions() && topology->nb_points() > 0) {
      const std::size_t n = topology->nb_points();
      x.assign(n * cw, 0.0);
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = topology->point(i);
        for (int k = 0; k < std::min(3, info().spatial_dim); ++k) x[i * cw + k] = p[k];
        if (type_ == StateType::rigid3) x[i * cw + 6] = 1.0;
      }
      std::vector<double> nvv(n * dw, 0.0);
      if (nv == 1)
        for (std::size_t i = 0; i < n; ++i)
          for (int k = 0; k < dw; ++k) nvv[i * dw + k] = v[k];
      v = std::move(nvv);
      nx = nv = n;
    } else if (nx == 0) {
      v.clear();
      nv = 0;
    }
  } else if (nx != nv) {
    if (nv >= 1 && nv < nx) {
      std::vector<double> last(v.end() - dw, v.end());
      for (std::size_t i = nv; i < nx; ++i) v.insert(v.end(), last.begin(), last.end());
      nv = nx;
    }
  }
  const std::size_t n = std::max(nx, nv);
  // A rest_position shorter than the state would be padded with zeros below: use the positions instead.
  const bool rest_short = nr_given > 0 && nr_given < n;
  if (rest_short)
    msg_warning("rest_position has " + std::to_string(nr_given) + " values but the state has " + std::to_string(n) +
                " points: rest_position is set to position");
  size_ = n;
  resize_vec(x, true, n);
  resize_vec(v, false, n);
  position.edit().data = std::move(x);
  velocity.edit().data = std::move(v);
  resize(n);
  // 5. Initial transform.
  reinit();
  // 6. Rest position := position (× restScale) unless given with the right size.
  if (rest_short || rest_position.value().data.size() != position.value().data.size()) {
    std::vector<double> rp = position.value().data;
    if (rest_scale.value() != 1.0)
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < std::min(3, cw); ++k) rp[i * cw + k] *= rest_scale.value();
    rest_position.edit().data = std::move(rp);
  }
  // 7. Second transform, on positions only.
  if (rotation2.value() != Vec3::Zero() || translation2.value() != Vec3::Zero())
    apply_transform(position.edit().data, Vec3::Ones(), rotation2.value(), translation2.value());
}

void MechanicalObject::reinit() {
  if (scale3d.value() != Vec3::Ones() || rotation.value() != Vec3::Zero() || translation.value() != Vec3::Zero())
    apply_transform(position.edit().data, scale3d.value(), rotation.value(), translation.value());
}

void MechanicalObject::store_reset_state() {
  if (!independent()) return;
  reset_position.edit().data = position.value().data;
  const auto& v = velocity.value().data;
  if (std::any_of(v.begin(), v.end(), [](double x) { return x != 0.0; })) reset_velocity.edit().data = v;
}

void MechanicalObject::reset() {
  std::vector<double>& f = write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  if (!reset_position.value().data.empty()) position.edit().data = reset_position.value().data;
  if (!reset_velocity.value().data.empty()) velocity.edit().data = reset_velocity.value().data;
  else std::fill(write(kVelocity).begin(), write(kVelocity).end(), 0.0);
}

void register_mechanical_object(Registry& r) {
  ComponentInfo info;
  info.name = "MechanicalObject";
  info.category = "StateContainer";
  info.description = "degrees of freedom: positions, velocities, forces";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<MechanicalObject>();
  r.add(std::move(info));
}

}  // namespace sinew
