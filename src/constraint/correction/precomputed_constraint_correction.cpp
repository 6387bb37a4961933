#include "constraint/correction/precomputed_constraint_correction.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <utility>

#include "constraint/correction/compliance_cache.h"
#include "core/node.h"
#include "core/interrupt.h"
#include "core/registry.h"
#include "core/rotation_finder.h"
#include "math/quat.h"
#include "math/rigid.h"
#include "solver/linear/cg_linear_solver.h"
#include "solver/ode/euler_implicit_solver.h"

namespace sinew {

namespace {

namespace fs = std::filesystem;

// Compliances shared by corrections with the same file name (SOFA's static
// map of inverses), per simulation: keyed by the root node as well, so two
// scenes run in one process never share one.
struct SharedCompliances {
  std::mutex mutex;
  std::map<std::pair<const Node*, std::string>, std::weak_ptr<const std::vector<double>>> map;
};
SharedCompliances& shared() {
  static SharedCompliances s;
  return s;
}

std::shared_ptr<const std::vector<double>> find_shared(const Node* root, const std::string& key, std::size_t size) {
  SharedCompliances& s = shared();
  std::lock_guard<std::mutex> lock(s.mutex);
  auto it = s.map.find({root, key});
  if (it == s.map.end()) return nullptr;
  auto c = it->second.lock();
  if (!c) {
    s.map.erase(it);
    return nullptr;
  }
  return c->size() == size ? c : nullptr;
}

void share(const Node* root, const std::string& key, const std::shared_ptr<const std::vector<double>>& c) {
  SharedCompliances& s = shared();
  std::lock_guard<std::mutex> lock(s.mutex);
  std::erase_if(s.map, [](const auto& e) { return e.second.expired(); });  // simulations that ended
  s.map[{root, key}] = c;
}

// SOFA's node->get<RotationFinder>(): this node, then its ancestors.
RotationFinder* find_rotation_finder(const Node* start) {
  for (const Node* n = start; n; n = n->parent())
    for (const auto& o : n->objects())
      if (auto* f = dynamic_cast<RotationFinder*>(o.get())) return f;
  return nullptr;
}

}  // namespace

PrecomputedConstraintCorrection::PrecomputedConstraintCorrection() {
  file_compliance.add_alias("filePrefix");
  file_compliance.set_file(true, /*required=*/false);  // missing: recomputed with a warning
}

void PrecomputedConstraintCorrection::init() {
  ConstraintCorrection::init();
  if (state() != ComponentState::valid) return;
  const StateType t = mstate->state_type();
  if (t != StateType::vec1 && t != StateType::vec3 && t != StateType::rigid3) {
    msg_error(std::string("template ") + mstate->info().name + " is not supported (Vec1d, Vec3d, Rigid3d)");
    set_state(ComponentState::invalid);
  }
}

double PrecomputedConstraintCorrection::dt() const { return node()->dt.value(); }

void PrecomputedConstraintCorrection::bwd_init() {
  if (state() != ComponentState::valid) return;
  dofs_ = mstate->size();
  if (dofs_ == 0) {
    msg_error("the state " + mstate->describe() + " has no degree of freedom: nothing to precompute");
    set_state(ComponentState::invalid);
    return;
  }
  w_ = mstate->info().deriv_width;
  n_ = dofs_ * static_cast<std::size_t>(w_);
  // n² doubles: 512 GiB and more is refused here; anything the allocator refuses
  // later is an error too (never an exception out of init).
  if (n_ > (std::size_t{1} << 18)) {
    msg_error("the compliance of " + std::to_string(n_) + " rows would need " +
              std::to_string(static_cast<double>(n_) * n_ * 8 / (1 << 30)) + " GiB: too large");
    set_state(ComponentState::invalid);
    return;
  }
}

void PrecomputedConstraintCorrection::handle_event(Event& e) {
  if (e.kind == Event::Kind::simulation_init_done) ensure_compliance();
}

bool PrecomputedConstraintCorrection::ensure_compliance() {
  if (c_) {
    if (mstate->size() == dofs_) return true;
    if (!warned_size_) {  // SOFA does not follow topology changes either
      warned_size_ = true;
      msg_error("the state now has " + std::to_string(mstate->size()) + " points, the compliance was computed for " +
                std::to_string(dofs_) + ": this correction stops acting");
    }
    return false;
  }
  if (attempted_ || state() != ComponentState::valid || n_ == 0) return false;
  attempted_ = true;
  if (obtain_compliance()) return true;
  set_state(ComponentState::invalid);
  return false;
}

// SOFA's bwdInit order: the file named by fileCompliance (its full path as the
// key), else the built name "<node>-<rows>-<dt>.comp"; memory first, then the
// file, then the computation, saved under the built name.
bool PrecomputedConstraintCorrection::obtain_compliance() {
  const Node* root = node()->root();
  const std::string built = compliance_cache::file_name(node()->name.value(), n_, dt());
  const std::string& given = file_compliance.value();
  if (!given.empty()) {
    if (auto c = find_shared(root, given, n_ * n_)) {
      c_ = std::move(c);
      source_ = Source::memory;
      return true;
    }
    // SOFA does not read fileCompliance with recompute set.
    if (!recompute.value()) {
      std::vector<double> buf;
      std::string why;
      const auto r = compliance_cache::read(given, n_, dt(), buf, why);
      if (r == compliance_cache::Read::ok) {
        auto c = std::make_shared<const std::vector<double>>(std::move(buf));
        share(root, given, c);
        c_ = std::move(c);
        cache_path_ = given;
        source_ = Source::file;
        msg_info("compliance read from " + given);
        return true;
      }
      msg_warning("fileCompliance " + given + " cannot be used (" +
                  (r == compliance_cache::Read::missing ? std::string("not found") : why) +
                  "): the compliance is recomputed and saved as " + built);
    } else {
      msg_warning("fileCompliance " + given + " is not read since recompute is set: the compliance is recomputed");
    }
  } else {
    if (auto c = find_shared(root, built, n_ * n_)) {
      c_ = std::move(c);
      source_ = Source::memory;
      return true;
    }
    if (load_from_files(built)) return true;
  }

  std::vector<double> computed;
  try {
    computed.reserve(n_ * n_);
  } catch (const std::bad_alloc&) {
    msg_error("cannot allocate the " + std::to_string(n_) + "×" + std::to_string(n_) + " compliance (" +
              std::to_string(n_ * n_ * 8 >> 20) + " MiB)");
    return false;
  }
  if (!precompute(computed)) return false;
  auto c = std::make_shared<const std::vector<double>>(std::move(computed));
  share(root, built, c);
  c_ = std::move(c);
  source_ = Source::computed;
  save(built);
  return true;
}

// fileDir/name (read even with recompute, as SOFA does), else without
// recompute the name in the working folder and the data folders (SOFA's
// findFile); in both cases Sinew's fallback folder last.
bool PrecomputedConstraintCorrection::load_from_files(const std::string& name) {
  std::vector<std::string> candidates;
  const std::string& dir = file_dir.value();
  if (!dir.empty()) {
    candidates.push_back((fs::path(dir) / name).string());
  } else if (!recompute.value()) {
    candidates.push_back(name);
    for (const std::string& d : node()->root()->data_dirs) candidates.push_back((fs::path(d) / name).string());
  } else {
    return false;
  }
  if (const std::string f = compliance_cache::fallback_dir(); !f.empty())
    candidates.push_back((fs::path(f) / name).string());
  for (const std::string& path : candidates) {
    std::vector<double> buf;
    std::string why;
    const auto r = compliance_cache::read(path, n_, dt(), buf, why);
    if (r == compliance_cache::Read::missing) continue;
    if (r == compliance_cache::Read::invalid) {
      msg_warning("the compliance cache " + path + " cannot be used (" + why + "): the compliance is recomputed");
      continue;
    }
    c_ = std::make_shared<const std::vector<double>>(std::move(buf));
    share(node()->root(), name, c_);
    cache_path_ = path;
    source_ = Source::file;
    msg_info("compliance read from " + path);
    return true;
  }
  return false;
}

// SOFA writes to fileDir, else to the first folder of its data repository;
// a folder that cannot be written is replaced by the temp fallback.
void PrecomputedConstraintCorrection::save(const std::string& name) {
  const std::vector<std::string>& data = node()->root()->data_dirs;
  const std::string dir = !file_dir.value().empty() ? file_dir.value() : (data.empty() ? std::string() : data[0]);
  bool fallback = false;
  const std::string path = compliance_cache::write_path(dir, name, fallback);
  std::string why;
  if (path.empty() || !compliance_cache::write(path, c_->data(), n_, dt(), why)) {
    msg_warning("the compliance could not be cached (" + (path.empty() ? std::string("no writable folder") : why) +
                "): it will be recomputed at the next start");
    return;
  }
  cache_path_ = path;
  msg_info("compliance saved in " + path +
           (fallback ? " (" + (dir.empty() ? std::string("no data folder") : dir + " is not writable") + ")"
                     : std::string()) +
           "; fileCompliance can name it to skip the precomputation");
}

// Unit force on every DoF component in turn, one implicit Euler step from rest
// each (SOFA's bwdInit). Only this state's x and v are restored afterwards,
// as in SOFA.
bool PrecomputedConstraintCorrection::precompute(std::vector<double>& c) {
  auto* ode = node()->find_up<EulerImplicitSolver>();
  if (!ode || ode->state() != ComponentState::valid) {
    msg_error("the precomputation needs a valid EulerImplicitSolver (with its linear solver) in this node or "
              "above: no compliance");
    return false;
  }
  const double h = dt();
  // Temporary values, given back afterwards with their "set in the scene" flag.
  auto push = [](auto& field, auto value) {
    auto saved = std::make_pair(field.value(), field.is_set());
    field.set(value);
    return saved;
  };
  auto pop = [](auto& field, const auto& saved) {
    field.set(saved.first);
    if (!saved.second) field.unset();
  };
  auto* cg = node()->find_up<CGLinearSolver>();
  std::pair<double, bool> cg_tolerance, cg_threshold;
  std::pair<unsigned, bool> cg_iterations;
  if (cg) {
    cg_tolerance = push(cg->tolerance, 1e-20);
    cg_iterations = push(cg->iterations, 5000u);
    cg_threshold = push(cg->threshold, 1e-35);
  }
  const auto gravity = push(node()->gravity, Vec3(Vec3::Zero()));

  const std::vector<double> x0 = mstate->read(kPosition);
  const std::vector<double> v0 = mstate->read(kVelocity);
  std::vector<double>& ext = mstate->write(kExternalForce);
  ext.assign(n_, 0.0);

  // SOFA integrates once first (its comment: avoids a first line of zeros).
  ode->solve(h, kPosition, kVelocity);

  double fact = 1.0 / h;  // the velocity is an admittance; this makes it a compliance
  fact *= ode->position_integration_factor(h);
  c.assign(n_ * n_, 0.0);
  bool interrupted = false;
  for (std::size_t f = 0; f < dofs_ && !interrupted; ++f) {
    interrupted = interrupt_requested();  // a long precomputation stops on Ctrl-C
    for (int i = 0; i < w_ && !interrupted; ++i) {
      const std::size_t col = f * w_ + i;
      {
        std::vector<double>& e = mstate->write(kExternalForce);
        for (int k = 0; k < w_; ++k) e[f * w_ + k] = k == i ? 1.0 : 0.0;
      }
      std::vector<double>& v = mstate->write(kVelocity);
      std::fill(v.begin(), v.end(), 0.0);
      mstate->write(kPosition) = x0;
      ode->solve(h, kPosition, kVelocity);
      const std::vector<double>& vel = mstate->read(kVelocity);
      for (std::size_t r = 0; r < n_; ++r) c[r * n_ + col] = fact * vel[r];
    }
    std::vector<double>& e = mstate->write(kExternalForce);
    for (int k = 0; k < w_; ++k) e[f * w_ + k] = 0.0;
  }

  pop(node()->gravity, gravity);
  if (cg) {
    pop(cg->tolerance, cg_tolerance);
    pop(cg->iterations, cg_iterations);
    pop(cg->threshold, cg_threshold);
  }
  mstate->write(kVelocity) = v0;
  mstate->write(kPosition) = x0;
  if (interrupted) {
    msg_warning("precomputation interrupted: no compliance");
    return false;
  }

  for (std::size_t k = 0; k < c.size(); ++k)
    if (!std::isfinite(c[k])) {
      msg_error("the precomputed compliance is not finite (row " + std::to_string(k / n_) + ", column " +
                std::to_string(k % n_) + "): is the system singular (no mass, no fixed point)?");
      return false;
    }
  msg_info("compliance precomputed (" + std::to_string(n_) + " unit forces)");
  return true;
}

// ------------------------------------------------------------------ role

void PrecomputedConstraintCorrection::add_compliance(const ConstraintParams& p, ConstraintProblem& problem) {
  if (!ensure_compliance()) return;
  const ConstraintMatrix& J = mstate->constraint_jacobian();
  if (J.empty()) return;
  const double factor =
      p.order == ConstraintOrder::pos || p.order == ConstraintOrder::pos_and_vel ? 1.0 : 1.0 / dt();
  if (rotations.value()) rotate_constraints();
  dense_compliance::prepare(J, c_->data(), dofs_, w_, work_);
  dense_compliance::add_jcjt(J, work_, w_, factor, regularization_term.value(), problem.W.data(), problem.n, true);
}

void PrecomputedConstraintCorrection::apply_correction(const ConstraintParams& p, const std::vector<double>& lambda,
                                                       int x_out, int v_out, int dx_out) {
  if (!ensure_compliance()) return;
  const ConstraintMatrix& J = mstate->constraint_jacobian();
  force_.assign(n_, 0.0);
  dense_compliance::jt_lambda(J, lambda, w_, /*skip_zero=*/false, force_, active_, mark_);
  dense_compliance::apply(c_->data(), dofs_, w_, active_, force_, corr_);
  // SOFA rotates the state's own dx vector here, not this correction: no
  // effect but its warning when no rotation finder exists.
  if (rotations.value()) rotate_constraints();
  const double inv_dt = 1.0 / dt();
  std::vector<double>& dx = mstate->write(dx_out);
  dx.resize(n_);
  if (p.order == ConstraintOrder::vel) {
    const std::vector<double>& vfree = mstate->read(p.v);
    std::vector<double>& v = mstate->write(v_out);
    for (std::size_t k = 0; k < n_; ++k) {
      dx[k] = corr_[k] * inv_dt;
      v[k] = vfree[k] + dx[k];
    }
    return;
  }
  for (std::size_t k = 0; k < n_; ++k) dx[k] = corr_[k];
  const std::vector<double>& xfree = mstate->read(p.x);
  std::vector<double>& x = mstate->write(x_out);
  if (mstate->state_type() == StateType::rigid3) {
    for (std::size_t i = 0; i < dofs_; ++i) rigid3_add_deriv(&xfree[i * 7], &corr_[i * 6], 1.0, &x[i * 7]);
  } else {
    for (std::size_t k = 0; k < n_; ++k) x[k] = xfree[k] + corr_[k];
  }
  if (p.order == ConstraintOrder::pos_and_vel) {
    const std::vector<double>& vfree = mstate->read(p.v);
    std::vector<double>& v = mstate->write(v_out);
    for (std::size_t k = 0; k < n_; ++k) v[k] = vfree[k] + corr_[k] * inv_dt;
  }
}

// ------------------------------------------------------------------ unbuilt

bool PrecomputedConstraintCorrection::has_constraint_row(int row) const {
  return row >= 0 && static_cast<std::size_t>(row) < id_to_local_.size() && id_to_local_[row] >= 0;
}

void PrecomputedConstraintCorrection::reset_for_unbuilt(const ConstraintParams&, const std::vector<double>& f,
                                                        std::vector<int>&) {
  unbuilt_force_ = &f;
  id_to_local_.clear();
  local_to_id_.clear();
  active_local_.clear();
  local_w_.clear();
  if (!ensure_compliance()) return;
  if (rotations.value()) rotate_constraints();
  const ConstraintMatrix& J = mstate->constraint_jacobian();
  const auto rows = J.rows();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const int id = rows[k].id;
    if (static_cast<std::size_t>(id) >= id_to_local_.size()) id_to_local_.resize(id + 1, -1);
    id_to_local_[id] = static_cast<int>(k);
    local_to_id_.push_back(id);
    if (static_cast<std::size_t>(id) < f.size() && std::fabs(f[id]) > std::numeric_limits<double>::epsilon())
      active_local_.push_back(static_cast<int>(k));
  }
  const int nr = static_cast<int>(rows.size());
  local_w_.assign(static_cast<std::size_t>(nr) * nr, 0.0);
  if (nr == 0) return;
  dense_compliance::prepare(J, c_->data(), dofs_, w_, work_);
  dense_compliance::add_jcjt(J, work_, w_, 1.0, 0.0, local_w_.data(), nr, /*by_id=*/false);
}

// Without the velocity-order factor, with the regularisation (SOFA).
void PrecomputedConstraintCorrection::add_block_diagonal_compliance(ConstraintProblem& problem, int begin, int end) {
  const int nr = static_cast<int>(local_to_id_.size());
  const double reg = regularization_term.value();
  for (int id1 = begin; id1 < end; ++id1) {
    if (!has_constraint_row(id1)) continue;
    const int c1 = id_to_local_[id1];
    for (int id2 = id1; id2 < end; ++id2) {
      if (!has_constraint_row(id2)) continue;
      const double w = local_w_[static_cast<std::size_t>(c1) * nr + id_to_local_[id2]];
      problem.w(id1, id2) += w;
      if (id1 != id2) problem.w(id2, id1) += w;
      else problem.w(id1, id1) += reg;
    }
  }
}

// d_i += Σ over this body's rows with a force (ascending) of W_ik·f_k, with
// the solver's current forces.
void PrecomputedConstraintCorrection::add_constraint_displacement(std::vector<double>& d, int begin, int end) {
  if (!unbuilt_force_ || local_w_.empty()) return;
  const std::vector<double>& f = *unbuilt_force_;
  const std::size_t nr = local_to_id_.size();
  for (int i = begin; i < end; ++i) {
    if (!has_constraint_row(i)) continue;
    const std::size_t c = static_cast<std::size_t>(id_to_local_[i]);
    double dc = d[i];
    for (int k : active_local_) dc += local_w_[c * nr + k] * f[local_to_id_[k]];
    d[i] = dc;
  }
}

// The rows of [begin, end) now have a force: they join the active list.
void PrecomputedConstraintCorrection::set_constraint_dforce(const std::vector<double>&, int begin, int end) {
  for (int i = begin; i < end; ++i) {
    if (!has_constraint_row(i)) continue;
    const int c = id_to_local_[i];
    auto it = std::lower_bound(active_local_.begin(), active_local_.end(), c);
    if (it == active_local_.end() || *it != c) active_local_.insert(it, c);
  }
}

// ------------------------------------------------------------------ LCP path

void PrecomputedConstraintCorrection::reset_contact_force() {
  std::vector<double>& f = mstate->write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
}

// SOFA's applyContactForce: force = Jᵀf over the rows with a force, the
// state's dx = C·force (rotated with `rotations`), x = xf ⊕ dx, v = vf + dx/dt.
void PrecomputedConstraintCorrection::apply_contact_force(const ConstraintParams&, const std::vector<double>& f) {
  if (!ensure_compliance()) return;
  const ConstraintMatrix& J = mstate->constraint_jacobian();
  std::vector<double>& force = mstate->write(kForce);
  force.assign(n_, 0.0);
  dense_compliance::jt_lambda(J, f, w_, /*skip_zero=*/true, force, active_, mark_);
  std::vector<double>& dx = mstate->write(kDx);
  dense_compliance::apply(c_->data(), dofs_, w_, active_, force, dx);
  std::fill(force.begin(), force.end(), 0.0);
  if (rotations.value()) rotate_response(dx);
  const std::vector<double>& xfree = mstate->read(kFreePosition);
  const std::vector<double>& vfree = mstate->read(kFreeVelocity);
  std::vector<double>& x = mstate->write(kPosition);
  std::vector<double>& v = mstate->write(kVelocity);
  if (mstate->state_type() == StateType::rigid3) {
    for (std::size_t i = 0; i < dofs_; ++i) rigid3_add_deriv(&xfree[i * 7], &dx[i * 6], 1.0, &x[i * 7]);
  } else {
    for (std::size_t k = 0; k < n_; ++k) x[k] = xfree[k] + dx[k];
  }
  const double inv_dt = 1 / dt();
  for (std::size_t k = 0; k < n_; ++k) v[k] = vfree[k] + dx[k] * inv_dt;
}

// ------------------------------------------------------------------ rotations

void PrecomputedConstraintCorrection::rotate_constraints() {
  if (mstate->state_type() != StateType::vec3 || warned_rotation_) return;
  if (!find_rotation_finder(node())) {
    warned_rotation_ = true;
    msg_warning("rotations is set but no rotation finder (TetrahedronFEMForceField, HexahedronFEMForceField) is "
                "in this node or above: no rotation is applied (warned once)");
  }
}

void PrecomputedConstraintCorrection::rotate_response(std::vector<double>& dx) {
  const StateType t = mstate->state_type();
  if (t == StateType::vec3) {
    RotationFinder* finder = find_rotation_finder(node());
    if (!finder) {
      rotate_constraints();  // warns once
      return;
    }
    rot_.assign(finder->rotation_state() ? finder->rotation_state()->size() : 0, Mat3::Identity());
    finder->node_rotations(rot_);
    for (std::size_t j = 0; j < dofs_ && j < rot_.size(); ++j) {
      const Mat3& R = rot_[j];
      double* d = &dx[j * 3];
      const double a = d[0], b = d[1], c = d[2];
      for (int r = 0; r < 3; ++r) d[r] = R(r, 0) * a + R(r, 1) * b + R(r, 2) * c;
    }
  } else if (t == StateType::rigid3) {
    const std::vector<double>& x = mstate->read(kPosition);
    const std::vector<double>& x0 = mstate->read(kRestPosition);
    for (std::size_t j = 0; j < dofs_; ++j) {
      Quat q = Quat::from(&x[j * 7 + 3]);
      if (rest_deformations.value()) q = quat_mul(q, quat_inverse(Quat::from(&x0[j * 7 + 3])));
      double* d = &dx[j * 6];
      const Vec3 lin = quat_rotate(q, Vec3(d[0], d[1], d[2]));
      const Vec3 ang = quat_rotate(q, Vec3(d[3], d[4], d[5]));
      for (int k = 0; k < 3; ++k) d[k] = lin[k], d[3 + k] = ang[k];
    }
  }
}

void register_precomputed_constraint_correction(Registry& r) {
  ComponentInfo info;
  info.name = "PrecomputedConstraintCorrection";
  info.category = "Constraint/Lagrangian/Correction";
  info.description = "dense compliance precomputed from unit forces at init and cached in a file";
  info.templates = {"Vec3d", "Vec1d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<PrecomputedConstraintCorrection>();
  r.add(std::move(info));
}

}  // namespace sinew
