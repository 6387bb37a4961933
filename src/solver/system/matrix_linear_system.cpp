#include "solver/system/matrix_linear_system.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

const std::vector<std::string>& MatrixLinearSystem::matrix_templates() {
  static const std::vector<std::string> t = {
      "CompressedRowSparseMatrixd",        "CompressedRowSparseMatrixMat2x2d", "CompressedRowSparseMatrixMat3x3d",
      "CompressedRowSparseMatrixMat4x4d",  "CompressedRowSparseMatrixMat6x6d", "CompressedRowSparseMatrixMat8x8d",
      "FullMatrix",                        "SparseMatrix",                     "DiagonalMatrix",
      "BlockDiagonalMatrixMat3x3d",        "BTDMatrix6d"};
  return t;
}

int MatrixLinearSystem::block_size_of(const std::string& tmpl) {
  static const std::string prefix = "CompressedRowSparseMatrixMat";
  if (tmpl.rfind(prefix, 0) == 0 && tmpl.size() > prefix.size()) return tmpl[prefix.size()] - '0';
  if (tmpl == "BlockDiagonalMatrixMat3x3d") return 3;
  if (tmpl == "BTDMatrix6d") return 6;
  return 1;
}

BlockCsrMatrix::Structure MatrixLinearSystem::structure_of(const std::string& tmpl) {
  if (tmpl == "DiagonalMatrix") return BlockCsrMatrix::Structure::diagonal;
  if (tmpl == "BlockDiagonalMatrixMat3x3d") return BlockCsrMatrix::Structure::block_diagonal;
  if (tmpl == "BTDMatrix6d") return BlockCsrMatrix::Structure::block_tridiagonal;
  return BlockCsrMatrix::Structure::general;
}

void MatrixLinearSystem::configure() {
  if (configured_) return;
  const std::string& t = template_name().empty() ? matrix_templates()[0] : template_name();
  assembler_.configure(block_size_of(t), structure_of(t));
  configured_ = true;
}

void MatrixLinearSystem::init() { configure(); }

void MatrixLinearSystem::build_system_matrix(MechanicalOps& ops, double m, double b, double k) {
  if (!enable_assembly.value()) return;
  configure();
  SystemAssembler::Options o;
  o.stiffness = assemble_stiffness.value();
  o.mass = assemble_mass.value();
  o.damping = assemble_damping.value();
  o.geometric = assemble_geometric_stiffness.value();
  o.projective = apply_projective_constraints.value();
  o.mapped = apply_mapped_components.value();
  assembler_.assemble(ops, m, b, k, o, *this);
  const int n = static_cast<int>(assembler_.size());
  if (matrix_size.value() != VecNi<2>(n, n)) matrix_size.set(VecNi<2>(n, n));
  rhs_.setZero(n);
  solution_.setZero(n);
  factorization_invalidation.set(true);
  assembled_once_ = true;
}

void MatrixLinearSystem::set_rhs(MechanicalOps& ops, int id) {
  configure();
  assembler_.update_layout(ops);
  assembler_.gather(id, rhs_);
}

void MatrixLinearSystem::set_system_solution(MechanicalOps& ops, int id) {
  configure();
  assembler_.update_layout(ops);
  assembler_.gather(id, solution_);
}

void MatrixLinearSystem::dispatch_system_solution(MechanicalOps& ops, int id) { assembler_.scatter(solution_, id); }

void register_matrix_linear_system(Registry& r) {
  ComponentInfo info;
  info.name = "MatrixLinearSystem";
  info.category = "LinearSystem";
  info.description = "assembled linear system A = mM + bB + kK with projective constraints and mapped components";
  info.templates = MatrixLinearSystem::matrix_templates();
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<MatrixLinearSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
