#include "solver/preconditioner/precomputed_warp_preconditioner.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/node.h"
#include "core/registry.h"
#include "core/rotation_finder.h"
#include "solver/ode/euler_implicit_solver.h"
#include "solver/system/precomputed_matrix_system.h"

namespace sinew {

namespace {
// Inverses shared by file name (share_matrix), as SOFA's static map.
std::map<std::string, std::shared_ptr<PrecomputedWarpPreconditioner::Dense>>& shared_inverses() {
  static std::map<std::string, std::shared_ptr<PrecomputedWarpPreconditioner::Dense>> m;
  return m;
}
}  // namespace

void PrecomputedWarpPreconditioner::init() {
  MechanicalState* s = node()->get_mechanical_state();
  if (!s || s->state_type() != StateType::vec3) {
    msg_error("PrecomputedWarpPreconditioner needs a Vec3d MechanicalObject in its context");
    set_state(ComponentState::invalid);
    return;
  }
  if (!linear_system) {
    PrecomputedMatrixSystem* found = nullptr;
    for (Node* n = node(); n && !found; n = n->parent())
      for (const auto& o : n->objects())
        if (auto* sys = dynamic_cast<PrecomputedMatrixSystem*>(o.get()); sys && !sys->user) {
          found = sys;
          break;
        }
    if (!found) {
      msg_info("no linear system found; a PrecomputedMatrixSystem is created");
      auto sys = std::make_unique<PrecomputedMatrixSystem>();
      sys->set_type("PrecomputedMatrixSystem", "CompressedRowSparseMatrixd");
      sys->name.set("PrecomputedMatrixSystem" + std::to_string(node()->next_default_index("PrecomputedMatrixSystem")));
      sys->where = where;
      found = static_cast<PrecomputedMatrixSystem*>(node()->add_object(std::move(sys)));
    }
    linear_system.set(found);
  }
  MatrixLinearSolver::init();
  first_ = true;
}

void PrecomputedWarpPreconditioner::load_matrix(const BlockCsrMatrix& A) {
  // The size is the system's matrixSize: 0 for a PrecomputedMatrixSystem, which never assembles.
  system_size_ = linear_system ? static_cast<std::size_t>(std::max(0, linear_system->matrix_size.value()[0])) : 0;
  nb_dofs_ = system_size_ / 3;
  const Eigen::Index n = static_cast<Eigen::Index>(nb_dofs_ * 3);
  rot_.assign(nb_dofs_, Mat3::Identity());
  t_.setZero(n);
  tmp_.setZero(n);
  double fact_int = 1.0;
  if (node()->find_up<EulerImplicitSolver>()) fact_int = node()->dt.value();  // position integration factor

  std::ostringstream file;
  file << node()->name.value() << "-" << system_size_ << "-" << node()->dt.value() << ".comp";
  const std::string fname = file.str();
  if (share_matrix.value()) {
    auto& slot = shared_inverses()[fname];
    if (!slot) slot = std::make_shared<Dense>();
    minv_ = slot;
    if (minv_->rows() == static_cast<Eigen::Index>(system_size_) && system_size_ > 0) {
      msg_info("shared matrix: " + fname + " is already built");
      return;
    }
  } else {
    minv_ = std::make_shared<Dense>();
  }
  minv_->setZero(n, n);
  if (n == 0) return;  // nothing to precompute (and no file written)

  bool loaded = false;
  if (use_file.value() && std::filesystem::exists(fname)) {
    std::ifstream in(fname, std::ios::binary);
    in.read(reinterpret_cast<char*>(minv_->data()), static_cast<std::streamsize>(n * n * sizeof(double)));
    loaded = static_cast<bool>(in);
    if (loaded) msg_info("file open: " + fname + " compliance being loaded");
  }
  if (!loaded) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n), col(n);
    auto* inner = dynamic_cast<MatrixLinearSolver*>(linear_solver.get());
    if (inner && inner->system() && inner->system()->assembled() &&
        static_cast<Eigen::Index>(inner->system()->size()) == n) {
      // Unit solves with the linked solver on its own (assembled) system.
      for (Eigen::Index j = 0; j < n; ++j) {
        e[j] = 1.0;
        col.setZero();
        inner->solve_global(col, e);
        e[j] = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) (*minv_)(j, i) = col[i] * fact_int;
      }
    } else {
      if (linear_solver)
        msg_warning("the linked solver " + linear_solver->describe() +
                    " has no assembled system of the right size; the inverse is computed with a simplicial LLT");
      std::vector<int> rb, ci;
      std::vector<double> v;
      A.to_filtered_csr(rb, ci, v);
      if (static_cast<Eigen::Index>(A.size()) != n) {
        msg_error("the system matrix has size " + std::to_string(A.size()) + ", expected " + std::to_string(n) +
                  "; the preconditioner is zero");
        return;
      }
      Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> map(
          static_cast<int>(n), static_cast<int>(n), static_cast<int>(v.size()), rb.data(), ci.data(), v.data());
      const Eigen::SparseMatrix<double, Eigen::ColMajor, int> M = map;
      Eigen::SimplicialLLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int>> llt;
      llt.compute(M);
      if (llt.info() != Eigen::Success) {
        msg_error("Solver cannot factorize: the system matrix is singular or not positive definite; the "
                  "preconditioner is zero");
        return;
      }
      for (Eigen::Index j = 0; j < n; ++j) {
        e[j] = 1.0;
        col = llt.solve(e);
        e[j] = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) (*minv_)(j, i) = col[i] * fact_int;
      }
    }
    if (use_file.value()) {
      std::ofstream out(fname, std::ios::binary);
      out.write(reinterpret_cast<const char*>(minv_->data()), static_cast<std::streamsize>(n * n * sizeof(double)));
    }
  }
  *minv_ /= fact_int;
}

void PrecomputedWarpPreconditioner::rotate() {
  rotated_ = true;
  if (!use_rotations.value()) return;
  RotationFinder* finder = nullptr;
  for (const auto& o : node()->objects())
    if ((finder = dynamic_cast<RotationFinder*>(o.get()))) break;
  if (!finder) {
    if (!warned_rotation_) {
      warned_rotation_ = true;
      msg_error("No rotation defined: only applicable for components implementing RotationFinder; using the identity");
    }
    rot_.assign(nb_dofs_, Mat3::Identity());
    return;
  }
  std::vector<Mat3> r(finder->rotation_state() ? finder->rotation_state()->size() : 0, Mat3::Identity());
  finder->node_rotations(r);
  for (std::size_t k = 0; k < nb_dofs_; ++k) rot_[k] = k < r.size() ? r[k] : Mat3::Identity();
}

void PrecomputedWarpPreconditioner::invert(const BlockCsrMatrix& A) {
  if (state() == ComponentState::invalid) return;
  if (first_) {
    first_ = false;
    load_matrix(A);
  }
  rotate();
}

void PrecomputedWarpPreconditioner::solve(const BlockCsrMatrix&, Eigen::VectorXd& z, const Eigen::VectorXd& r) {
  // With an empty inverse (size 0) z is left untouched, as SOFA.
  const Eigen::Index n = static_cast<Eigen::Index>(nb_dofs_ * 3);
  if (n == 0 || !minv_ || minv_->rows() != n || r.size() < n) return;
  if (z.size() < n) z.conservativeResize(n);
  if (!use_rotations.value()) {
    z.head(n) = (*minv_) * r.head(n);
    return;
  }
  for (std::size_t k = 0; k < nb_dofs_; ++k) {  // z = Rᵀ·r
    const Mat3& R = rot_[k];
    const Eigen::Index l = static_cast<Eigen::Index>(3 * k);
    for (int c = 0; c < 3; ++c) z[l + c] = R(0, c) * r[l] + R(1, c) * r[l + 1] + R(2, c) * r[l + 2];
  }
  t_ = (*minv_) * z.head(n);
  for (std::size_t k = 0; k < nb_dofs_; ++k) {  // z = R·t
    const Mat3& R = rot_[k];
    const Eigen::Index l = static_cast<Eigen::Index>(3 * k);
    for (int c = 0; c < 3; ++c) z[l + c] = R(c, 0) * t_[l] + R(c, 1) * t_[l + 1] + R(c, 2) * t_[l + 2];
  }
}

void PrecomputedWarpPreconditioner::add_jminvjt(Eigen::MatrixXd& result,
                                                const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                                                double fact) {
  if (!rotated_) rotate();  // already rotated when used as a preconditioner this step
  rotated_ = false;
  if (J.cols() == 0 || J.rows() == 0) return;
  const Eigen::Index n = static_cast<Eigen::Index>(nb_dofs_ * 3);
  if (!minv_ || minv_->rows() != n || n == 0) return;
  const Eigen::Index m = J.rows();
  if (result.rows() < m || result.cols() < m) result.conservativeResize(std::max(result.rows(), m),
                                                                        std::max(result.cols(), m));
  const double f = static_cast<double>(static_cast<float>(fact));  // SOFA passes the factor as float
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = 0; r < m; ++r)
    if (J.outerIndexPtr()[r] != J.outerIndexPtr()[r + 1]) rows.push_back(r);
  for (Eigen::Index a : rows) {
    // jr = J_a·R (dense row), then jrm = jr·Minv.
    Eigen::RowVectorXd jr = Eigen::RowVectorXd::Zero(n);
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, a); it; ++it) {
      const Eigen::Index c = it.col();
      if (c >= n) continue;
      if (!use_rotations.value()) {
        jr[c] += it.value();
        continue;
      }
      const Mat3& R = rot_[static_cast<std::size_t>(c / 3)];
      const Eigen::Index base = (c / 3) * 3;
      for (int e = 0; e < 3; ++e) jr[base + e] += it.value() * R(c % 3, e);
    }
    const Eigen::RowVectorXd jrm = jr * (*minv_);
    for (Eigen::Index b : rows) {
      double res = 0;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, b); it; ++it)
        if (it.col() < n) res += jrm[it.col()] * it.value();
      result(a, b) += res * f;
    }
  }
}

void register_precomputed_warp_preconditioner(Registry& r) {
  ComponentInfo info;
  info.name = "PrecomputedWarpPreconditioner";
  info.category = "LinearSolver/Preconditioner";
  info.description = "precomputed dense inverse of the first system matrix, rotated by the current per-point rotations";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<PrecomputedWarpPreconditioner>();
  r.add(std::move(info));
}

}  // namespace sinew
