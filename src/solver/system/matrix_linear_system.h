// MatrixLinearSystem: the assembled linear system A·x = b of a matrix linear
// solver (spec/solvers.md §2.1, §2.4). The template names the global matrix
// type: CompressedRowSparseMatrixd (default, scalar entries),
// CompressedRowSparseMatrixMat{2x2,3x3,4x4,6x6,8x8}d (blocks), FullMatrix,
// SparseMatrix, DiagonalMatrix, BlockDiagonalMatrixMat3x3d, BTDMatrix6d
// (blocks (i,i−1), (i,i), (i,i+1) of 6×6 only). Storage is a
// BlockCsrMatrix whose pattern is built on the first assembly and refilled
// in place afterwards; Diagonal types keep only their structure.
//
// Created automatically by a matrix linear solver that has none (§2.2).
#pragma once

#include <Eigen/Core>

#include "core/mechanical_ops.h"
#include "core/roles.h"
#include "math/block_csr.h"
#include "solver/system/system_assembler.h"

namespace sinew {

class MatrixLinearSystem : public Component {
 public:
  Field<VecNi<2>> matrix_size{this, "matrixSize", VecNi<2>(0, 0), "size of the assembled matrix (output)",
                              "LinearSystem"};
  Field<bool> enable_assembly{this, "enableAssembly", true, "assemble the matrix", "LinearSystem"};
  Field<bool> factorization_invalidation{this, "factorizationInvalidation", false,
                                         "change counter used to refresh the factorisation (internal)", "LinearSystem"};
  Field<bool> assemble_stiffness{this, "assembleStiffness", true, "include stiffness contributions", "LinearSystem"};
  Field<bool> assemble_mass{this, "assembleMass", true, "include mass contributions", "LinearSystem"};
  Field<bool> assemble_damping{this, "assembleDamping", true, "include damping contributions", "LinearSystem"};
  Field<bool> assemble_geometric_stiffness{this, "assembleGeometricStiffness", true,
                                           "include the mappings' geometric stiffness", "LinearSystem"};
  Field<bool> apply_projective_constraints{this, "applyProjectiveConstraints", true,
                                           "project the matrix with the projective constraints", "LinearSystem"};
  Field<bool> apply_mapped_components{this, "applyMappedComponents", true, "include components below mappings",
                                      "LinearSystem"};
  Field<bool> check_indices{this, "checkIndices", false, "bounds-check entries while assembling (slower)",
                            "LinearSystem"};
  Field<bool> parallel_assembly_independent_matrices{this, "parallelAssemblyIndependentMatrices", false,
                                                     "assemble the main and mapped matrices concurrently",
                                                     "LinearSystem"};

  void init() override;

  // Assembles A = m·M + b·B + k·K over the scope of `ops` (nothing when
  // enableAssembly is false) and flags the matrix as changed.
  virtual void build_system_matrix(MechanicalOps& ops, double m, double b, double k);
  // Copies state vectors (independent states) into the global vectors and back.
  void set_rhs(MechanicalOps& ops, int id);
  void set_system_solution(MechanicalOps& ops, int id);
  void dispatch_system_solution(MechanicalOps& ops, int id);

  BlockCsrMatrix& matrix() { return assembler_.matrix(); }
  const BlockCsrMatrix& matrix() const { return assembler_.matrix(); }
  Eigen::VectorXd& rhs() { return rhs_; }
  Eigen::VectorXd& solution() { return solution_; }
  std::size_t size() const { return assembler_.size(); }
  const SystemAssembler& assembler() const { return assembler_; }
  bool assembled() const { return assembled_once_; }

  // "Matrix changed since the last factorization" (set by assembly, cleared by the solver).
  bool matrix_changed() const { return factorization_invalidation.value(); }
  void clear_matrix_changed() { factorization_invalidation.set(false); }

  // The solver that uses this system (automatic linking takes unused systems only).
  Component* user = nullptr;

  // Matrix template → storage block size and structure.
  static int block_size_of(const std::string& tmpl);
  static BlockCsrMatrix::Structure structure_of(const std::string& tmpl);
  // Templates a MatrixLinearSystem can be created with.
  static const std::vector<std::string>& matrix_templates();

 protected:
  SystemAssembler assembler_;
  Eigen::VectorXd rhs_, solution_;
  bool configured_ = false, assembled_once_ = false;
  void configure();
};

}  // namespace sinew
