// MappedAssembly: brings matrix contributions recorded on mapped states
// (a force field or mass below a mapping) to the independent states of an
// assembled system as Jᵀ·K·J (spec/solvers.md §2.1), J being the chain of
// mapping Jacobians from the independent states down to the mapped state.
//
// Every pattern involved (each mapping Jacobian, each chained J and its
// transpose, each K, each product) is computed on the first assembly and
// again only when the sequence of recorded entries or Jacobian entries
// changes; later assemblies recompute values in place, so a steady
// assembly does not allocate (issue 4).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "core/matrix_sink.h"
#include "math/csr.h"

namespace sinew {

class MechanicalOps;
class MechanicalState;
class Mapping;

class MappedAssembly {
 public:
  using Pair = std::pair<const MechanicalState*, const MechanicalState*>;
  // Global scalar offset of an independent state, -1 for any other state.
  using OffsetOf = std::function<std::ptrdiff_t(const MechanicalState*)>;

  // Reads the triplets of `sink` whose target is 1 + p (the entries of
  // pairs[p], local scalar indices) and appends Jᵀ·K·J as target-0 triplets
  // in global indices, by SOFA's rule for states reaching different (or no)
  // independent states (see build()). Pairs behind a mapping without Jacobian
  // are skipped; those mappings are listed in missing().
  // `constant[p]` (when given): the Jacobians of pairs[p] are taken at the first assembly
  // after a pattern build and reused until the next one (MatrixProjectionMethod's
  // areJacobiansConstant).
  void project(MechanicalOps& ops, const std::vector<Pair>& pairs, MatrixSink& sink, const OffsetOf& offset_of,
               const std::vector<char>& constant = {});

  const std::vector<Mapping*>& missing() const { return missing_; }
  // Number of times the patterns were (re)built.
  long pattern_builds() const { return pattern_builds_; }

 private:
  // The Jacobian of one mapping, one matrix per input.
  struct MappingJacobian {
    Mapping* mapping = nullptr;
    std::vector<MechanicalState*> inputs;  // cached: Mapping::inputs() allocates
    std::vector<JacobianEntry> entries;    // refilled each assembly (capacity kept)
    std::vector<std::uint32_t> key_input, key_row, key_col;
    std::vector<int> slot;
    std::vector<Csr> per_input;
  };
  // J from one independent state (`top`) to a state, as a sum of terms
  // J_k · J(input k → top) over the mapping inputs reaching `top`.
  struct TopJacobian {
    const MechanicalState* top = nullptr;
    std::vector<int> term_input, term_chain_top;  // (mapping input k, top index in that input's chain)
    std::vector<Csr> terms;
    std::vector<const Csr*> term_ptrs;
    Csr J, Jt;
    std::vector<int> jt_src;
  };
  struct Chain {
    const MechanicalState* state = nullptr;
    std::size_t size = 0;           // scalar size when the pattern was built
    int jacobian = -1;              // index into jacobians_, -1 for an independent state (J = I)
    std::vector<int> input_chain;   // chain index of each mapping input (-1: unreachable)
    std::vector<TopJacobian> tops;
  };
  struct Product {
    int pair, chain_a, top_a, chain_b, top_b;
    Csr KJ, R;  // K·J_b and J_aᵀ·K·J_b
    bool frozen = false;    // Jacobians taken once (constant[pair])
    bool captured = false;  // Jb, Jat hold them
    Csr Jb, Jat;
    const MechanicalState* state_a = nullptr;  // the product lands at (offset of state_a, offset of state_b)
    const MechanicalState* state_b = nullptr;
    const Csr* identity_a = nullptr;  // J_a when top_a < 0 (that side does not reach state_a)
    const Csr* identity_b = nullptr;
  };

  bool unchanged(const std::vector<Pair>& pairs, const MatrixSink& sink);
  void build(MechanicalOps& ops, const std::vector<Pair>& pairs, const MatrixSink& sink, const OffsetOf& offset_of);
  int chain_of(MechanicalOps& ops, const MechanicalState* s, const OffsetOf& offset_of, int depth);
  int jacobian_of(Mapping* m);
  int top_index(int chain, const MechanicalState* top) const;  // -1: not reached (or chain < 0)
  const Csr& jacobian_b(const Product& p) const;
  const Csr& jacobian_a_transposed(const Product& p) const;
  const Csr* identity(int n);
  void compute(const MatrixSink& sink);

  std::vector<Pair> pairs_;
  std::vector<char> constant_;  // per pair, as given to the last pattern build
  std::vector<MappingJacobian> jacobians_;
  std::vector<Chain> chains_;  // children before parents: values are computed in this order
  std::vector<Csr> K_;         // one per pair
  // Recorded sequence of the mapped triplets (target ≠ 0) and their slots in K_.
  std::vector<int> key_target_, slot_;
  std::vector<std::uint32_t> key_row_, key_col_;
  std::vector<Product> products_;
  std::deque<Csr> identities_;  // one per size (stable addresses)
  std::vector<std::pair<std::size_t, std::size_t>> pair_sizes_;  // scalar sizes of each pair's states at the build
  std::vector<double> work_;
  std::vector<Mapping*> missing_;
  bool valid_ = false;
  long pattern_builds_ = 0;
};

}  // namespace sinew
