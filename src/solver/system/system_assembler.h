// SystemAssembler: builds A = mFact·M + bFact·B + kFact·K over the scope of
// a MechanicalOps into a BlockCsrMatrix (spec/solvers.md §2.1, §2.4).
//
// * Global layout: independent states in scope order, state s at
//   [offset_s, offset_s + nDofs·derivWidth).
// * Contributions, in SOFA's order: stiffness (factor kFact + bFact·rayleighStiffness),
//   mass (mFact − bFact·rayleighMass), damping (bFact), geometric stiffness of
//   mappings (kFact); a factor exactly 0 skips the component.
// * Entries on mapped states are collected per state pair and brought to the
//   independent states as Jᵀ·(K·J), J the chained mapping Jacobians.
// * Projective constraints: Dirichlet rows/columns cleared, diagonal set to 1.
// The pattern is built on the first assembly (and whenever the sequence of
// insertions changes); later assemblies replay the recorded sequence of
// entries straight into the values (MatrixSink replay mode).
#pragma once

#include <Eigen/Core>
#include <set>
#include <vector>

#include "core/matrix_sink.h"
#include "core/mechanical_ops.h"
#include "math/block_csr.h"
#include "solver/system/mapped_assembly.h"

namespace sinew {

class MatrixProjectionMethod;

class SystemAssembler final : public MatrixSink::Layout {
 public:
  struct Options {
    bool stiffness = true, mass = true, damping = true, geometric = true;
    bool projective = true, mapped = true;
  };
  struct StateBlock {
    MechanicalState* state;
    std::size_t offset, size;
  };

  // Block size of the storage (1: scalar CRS, 3: Mat3x3 blocks) and kept structure.
  void configure(int block_size, BlockCsrMatrix::Structure structure);
  // Recomputes the global layout from the scope; true when it changed.
  bool update_layout(MechanicalOps& ops);
  // Assembles the matrix; messages about components that cannot assemble go to `owner`.
  void assemble(MechanicalOps& ops, double m, double b, double k, const Options& o, const Component& owner);

  BlockCsrMatrix& matrix() { return matrix_; }
  const BlockCsrMatrix& matrix() const { return matrix_; }
  std::size_t size() const { return n_; }
  const std::vector<StateBlock>& layout() const { return layout_; }
  // Number of times the pattern of the global matrix, and of the mapped
  // products, was (re)built.
  long pattern_builds() const { return pattern_builds_; }
  long mapped_pattern_builds() const { return mapped_.pattern_builds(); }

  // Copies vector `id` of the independent states into `out` (resized to size()), and back.
  void gather(int id, Eigen::VectorXd& out) const;
  void scatter(const Eigen::VectorXd& in, int id) const;

  MatrixSink::Binding bind(const MechanicalState* rs, const MechanicalState* cs) override;

 private:
  const StateBlock* find_block(const MechanicalState* s) const;
  void assemble_mapped(MechanicalOps& ops, const Component& owner);
  void add_contributions(MechanicalOps& ops, double m, double b, double k, const Options& o, const Component& owner);
  void build_pattern();
  void report_once(const Component& owner, const void* who, const std::string& text);

  int bs_ = 1;
  BlockCsrMatrix::Structure structure_ = BlockCsrMatrix::Structure::general;
  std::vector<StateBlock> layout_;
  std::size_t n_ = 0;
  BlockCsrMatrix matrix_;
  MatrixSink sink_;
  std::vector<MappedAssembly::Pair> mapped_pairs_;
  std::vector<char> constant_jacobians_;  // per mapped pair: MatrixProjectionMethod's areJacobiansConstant
  std::vector<MatrixProjectionMethod*> projection_methods_;  // of the graph, in pre-order
  std::uint64_t projection_methods_version_ = ~std::uint64_t{0};
  MappedAssembly mapped_;
  // Recorded insertion sequence of the global target and its value slots.
  std::vector<std::uint64_t> keys_;
  std::vector<std::int64_t> slots_;
  std::vector<std::int64_t> block_slots_;  // ≥ 0 where a whole contiguous 3×3 block starts (replay fast path)
  bool pattern_valid_ = false;
  long pattern_builds_ = 0;
  std::vector<std::size_t> dirichlet_;
  std::set<const void*> reported_;
};

}  // namespace sinew
