#include "solver/system/rotation_matrix_system.h"

#include <vector>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
RotationFinder* find_rotation_finder(const Node* start) {
  for (const Node* n = start; n; n = n->parent())
    for (const auto& o : n->objects())
      if (auto* f = dynamic_cast<RotationFinder*>(o.get())) return f;
  return nullptr;
}
}  // namespace

void RotationMatrixSystem::init() {
  // R is stored as 3×3 diagonal blocks.
  assembler_.configure(3, BlockCsrMatrix::Structure::block_diagonal);
  configured_ = true;
  MatrixLinearSystem::init();

  finder_ = nullptr;
  if (rotation_finder) {
    finder_ = dynamic_cast<RotationFinder*>(rotation_finder.get());
    if (!finder_) {
      msg_error(rotation_finder->describe() + " is not a rotation finder (a corotational FEM force field)");
      set_state(ComponentState::invalid);
      return;
    }
  } else {
    finder_ = find_rotation_finder(node());
    if (!finder_) {
      msg_error("A RotationFinder is required by RotationMatrixSystem but has not been found. The available "
                "rotation finders are: HexahedronFEMForceField, TetrahedronFEMForceField");
      set_state(ComponentState::invalid);
      return;
    }
    rotation_finder.set(dynamic_cast<Component*>(finder_));
  }

  if (!main_system) {
    for (const auto& o : node()->objects()) {
      auto* s = dynamic_cast<MatrixLinearSystem*>(o.get());
      if (s && s != this && s->template_name() != "GraphScattered") {
        main_system.set(s);
        break;
      }
    }
  }
  if (!main_system) {
    msg_error("No linear system component found at path '" + main_system.path() + "', nor in the current context " +
              node()->describe());
    set_state(ComponentState::invalid);
    return;
  }
  counter_ = assembling_rate.value();  // assemble at the first build
}

const double* RotationMatrixSystem::block(std::size_t k) const {
  const BlockCsrMatrix& R = matrix();
  if (R.block_size() != 3 || !R.has_pattern() || k >= R.block_rows()) return nullptr;
  // Block-diagonal pattern: one block per block row.
  return &R.values()[static_cast<std::size_t>(R.row_begin()[k]) * 9];
}

void RotationMatrixSystem::set_identity() {
  BlockCsrMatrix& R = matrix();
  auto& v = R.values();
  if (R.block_size() != 3) {
    std::fill(v.begin(), v.end(), 0.0);
    for (std::size_t i = 0; i < R.size(); ++i)
      if (std::int64_t s = R.slot(i, i); s >= 0) v[s] = 1.0;
    return;
  }
  for (std::size_t k = 0; k < R.block_rows(); ++k) {
    double* b = &v[static_cast<std::size_t>(R.row_begin()[k]) * 9];
    for (int i = 0; i < 9; ++i) b[i] = (i % 4 == 0) ? 1.0 : 0.0;
  }
}

void RotationMatrixSystem::fill_rotations() {
  if (!finder_) return;
  MechanicalState* s = finder_->rotation_state();
  BlockCsrMatrix& R = matrix();
  if (!s || R.block_size() != 3) return;
  for (const auto& blk : assembler_.layout()) {
    if (blk.state != s || blk.offset % 3 != 0) continue;
    std::vector<Mat3> rot(s->size(), Mat3::Identity());
    finder_->node_rotations(rot);
    const std::size_t first = blk.offset / 3;
    for (std::size_t p = 0; p < rot.size() && first + p < R.block_rows(); ++p) {
      double* b = &R.values()[static_cast<std::size_t>(R.row_begin()[first + p]) * 9];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b[i * 3 + j] = rot[p](i, j);
    }
  }
}

void RotationMatrixSystem::build_system_matrix(MechanicalOps& ops, double m, double b, double k) {
  if (state() == ComponentState::invalid) return;
  main_assembled_last_ = false;
  if (main_system && ++counter_ >= assembling_rate.value()) {
    main_system->build_system_matrix(ops, m, b, k);
    counter_ = 0;
    main_assembled_last_ = true;
  }
  assembler_.update_layout(ops);
  BlockCsrMatrix& R = matrix();
  const bool fresh = !R.has_pattern();
  if (fresh) R.build_pattern({});
  if (main_assembled_last_ || fresh) set_identity();
  if (!main_assembled_last_) fill_rotations();
  const int n = static_cast<int>(assembler_.size());
  if (matrix_size.value() != VecNi<2>(n, n)) matrix_size.set(VecNi<2>(n, n));
  rhs_.setZero(n);
  solution_.setZero(n);
  factorization_invalidation.set(true);
  assembled_once_ = true;
}

void register_rotation_matrix_system(Registry& r) {
  ComponentInfo info;
  info.name = "RotationMatrixSystem";
  info.category = "LinearSystem";
  info.description = "block-diagonal rotation matrix of WarpPreconditioner; assembles the main system every assemblingRate steps";
  info.templates = {"RotationMatrixd"};
  info.default_template = "RotationMatrixd";
  info.create = creator<RotationMatrixSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
