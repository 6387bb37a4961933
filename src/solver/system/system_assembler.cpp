#include "solver/system/system_assembler.h"

#include <algorithm>

#include "core/component.h"
#include "core/node.h"
#include "solver/system/matrix_projection_method.h"

namespace sinew {

void SystemAssembler::configure(int block_size, BlockCsrMatrix::Structure structure) {
  bs_ = block_size;
  structure_ = structure;
  n_ = 0;
  layout_.clear();
  pattern_valid_ = false;
}

bool SystemAssembler::update_layout(MechanicalOps& ops) {
  bool changed = false;
  std::size_t offset = 0, i = 0;
  const auto& states = ops.independent_states();
  if (states.size() != layout_.size()) {
    layout_.resize(states.size());
    changed = true;
  }
  for (MechanicalState* s : states) {
    const std::size_t size = s->size() * static_cast<std::size_t>(s->info().deriv_width);
    StateBlock& b = layout_[i++];
    if (b.state != s || b.offset != offset || b.size != size) changed = true;
    b = {s, offset, size};
    offset += size;
  }
  if (offset != n_) changed = true;
  n_ = offset;
  if (changed || !matrix_.has_pattern()) {
    matrix_.reset(n_, bs_, structure_);
    pattern_valid_ = false;
  }
  return changed;
}

const SystemAssembler::StateBlock* SystemAssembler::find_block(const MechanicalState* s) const {
  for (const StateBlock& b : layout_)
    if (b.state == s) return &b;
  return nullptr;
}

MatrixSink::Binding SystemAssembler::bind(const MechanicalState* rs, const MechanicalState* cs) {
  const StateBlock* r = find_block(rs);
  const StateBlock* c = find_block(cs);
  if (r && c) return {0, static_cast<std::uint32_t>(r->offset), static_cast<std::uint32_t>(c->offset)};
  // At least one mapped state: a matrix per state pair, local indices.
  const auto key = std::make_pair(rs, cs);
  auto it = std::find(mapped_pairs_.begin(), mapped_pairs_.end(), key);
  if (it == mapped_pairs_.end()) {
    mapped_pairs_.push_back(key);
    it = mapped_pairs_.end() - 1;
  }
  return {1 + static_cast<int>(it - mapped_pairs_.begin()), 0, 0};
}

void SystemAssembler::report_once(const Component& owner, const void* who, const std::string& text) {
  if (reported_.insert(who).second) owner.msg_error(text);
}

void SystemAssembler::assemble(MechanicalOps& ops, double m, double b, double k, const Options& o,
                               const Component& owner) {
  update_layout(ops);
  // Steady state: replay the recorded sequence straight into the values.
  if (pattern_valid_) {
    matrix_.set_zero();
    sink_.begin_replay(this, keys_.data(), slots_.data(), block_slots_.data(), keys_.size(), matrix_.values().data());
    add_contributions(ops, m, b, k, o, owner);
    if (!sink_.replay_ok()) pattern_valid_ = false;
  }
  // First assembly, or the sequence of entries changed: record, new pattern.
  if (!pattern_valid_) {
    sink_.begin(this);
    add_contributions(ops, m, b, k, o, owner);
    build_pattern();
  }

  if (o.projective)
    for (ProjectiveConstraint* c : ops.projective_constraints()) {
      const StateBlock* blk = find_block(c->mstate.get());
      if (!blk) continue;  // constraints on mapped states have no meaningful global position
      dirichlet_.clear();
      if (!c->dirichlet_indices(dirichlet_)) {
        // As SOFA's default applyConstraint(ZeroDirichletCondition): nothing applied, one warning.
        if (reported_.insert(c).second)
          owner.msg_warning(c->describe() + " provides no Dirichlet indices; it is not applied on the assembled matrix");
        continue;
      }
      for (std::size_t i : dirichlet_)
        if (i < blk->size) matrix_.clear_row_col_set_diag(blk->offset + i, 1.0);
    }
}

void SystemAssembler::add_contributions(MechanicalOps& ops, double m, double b, double k, const Options& o,
                                        const Component& owner) {
  mapped_pairs_.clear();
  const auto& ffs = ops.force_fields();
  if (o.stiffness)
    for (ForceField* ff : ffs) {
      const double f = k + b * ff->rayleigh_stiffness.value();
      if (f == 0.0) continue;
      sink_.set_factor(f);
      if (!ff->build_stiffness(sink_))
        report_once(owner, ff, ff->describe() + " cannot assemble its stiffness matrix; it is missing from the system");
    }
  if (o.mass)
    for (ForceField* ff : ffs)
      if (auto* mass = dynamic_cast<Mass*>(ff)) {
        const double f = m - b * mass->rayleigh_mass.value();
        if (f == 0.0) continue;
        sink_.set_factor(f);
        if (!mass->build_mass(sink_))
          report_once(owner, mass, mass->describe() + " cannot assemble its mass matrix; it is missing from the system");
      }
  if (o.damping && b != 0.0)
    for (ForceField* ff : ffs) {
      sink_.set_factor(b);
      if (!ff->build_damping(sink_))
        report_once(owner, ff, ff->describe() + " cannot assemble its damping matrix; it is missing from the system");
    }
  if (o.geometric && k != 0.0)
    for (Mapping* mp : ops.mappings()) {
      sink_.set_factor(k);
      if (!mp->build_geometric_stiffness(sink_))
        report_once(owner, mp, mp->describe() + " cannot assemble its geometric stiffness; it is missing from the system");
    }
  if (o.mapped && !mapped_pairs_.empty()) assemble_mapped(ops, owner);
}

// Builds the pattern from the recorded target-0 entries, keeps their key
// sequence and slots for the replays, and adds their values.
void SystemAssembler::build_pattern() {
  const auto& t = sink_.triplets();
  auto key_of = [](const MatrixSink::Triplet& e) { return (static_cast<std::uint64_t>(e.row) << 32) | e.col; };
  keys_.clear();
  for (const auto& e : t)
    if (e.target == 0) keys_.push_back(key_of(e));  // the matrix keeps those of its structure
  matrix_.reset(n_, bs_, structure_);
  matrix_.build_pattern(keys_);
  keys_.clear();
  slots_.clear();
  for (const auto& e : t) {
    if (e.target != 0) continue;
    keys_.push_back(key_of(e));
    slots_.push_back(matrix_.slot(e.row, e.col));
  }
  // Runs of nine keys forming a 3×3 block stored contiguously (block CSR with
  // 3×3 blocks, block-aligned): replayed with one key check (MatrixSink::add_block).
  block_slots_.assign(keys_.size(), -1);
  for (std::size_t i = 0; i + 9 <= keys_.size(); ++i) {
    const std::int64_t s0 = slots_[i];
    if (s0 < 0) continue;
    const std::uint64_t r0 = keys_[i] >> 32, c0 = keys_[i] & 0xffffffffu;
    bool block = true;
    for (int a = 0; a < 3 && block; ++a)
      for (int b = 0; b < 3 && block; ++b) {
        const std::size_t k = i + static_cast<std::size_t>(3 * a + b);
        block = keys_[k] == (((r0 + a) << 32) | (c0 + b)) && slots_[k] == s0 + 3 * a + b;
      }
    if (block) block_slots_[i] = s0;
  }
  auto& vals = matrix_.values();
  std::size_t j = 0;
  for (const auto& e : t) {
    if (e.target != 0) continue;
    const std::int64_t s = slots_[j++];
    if (s >= 0) vals[s] += e.value;
  }
  pattern_valid_ = true;
  ++pattern_builds_;
}

void SystemAssembler::assemble_mapped(MechanicalOps& ops, const Component& owner) {
  // Pairs named by a MatrixProjectionMethod with areJacobiansConstant (the first one in the
  // graph naming the pair, as SOFA searches from the root).
  // The graph is searched again only when its structure changed.
  constant_jacobians_.assign(mapped_pairs_.size(), 0);
  if (Node* n = owner.node()) {
    if (projection_methods_version_ != n->structure_version()) {
      projection_methods_.clear();
      n->root()->collect_down(projection_methods_);
      projection_methods_version_ = n->structure_version();
    }
    for (std::size_t p = 0; p < mapped_pairs_.size(); ++p)
      for (const MatrixProjectionMethod* m : projection_methods_)
        if (m->has_pair(mapped_pairs_[p].first, mapped_pairs_[p].second)) {
          constant_jacobians_[p] = m->are_jacobians_constant.value();
          break;
        }
  }
  mapped_.project(
      ops, mapped_pairs_, sink_,
      [this](const MechanicalState* s) -> std::ptrdiff_t {
        const StateBlock* b = find_block(s);
        return b ? static_cast<std::ptrdiff_t>(b->offset) : -1;
      },
      constant_jacobians_);
  for (Mapping* m : mapped_.missing())
    report_once(owner, m, m->describe() + " provides no Jacobian; contributions on its output are not assembled");
}

void SystemAssembler::gather(int id, Eigen::VectorXd& out) const {
  if (static_cast<std::size_t>(out.size()) != n_) out.setZero(static_cast<Eigen::Index>(n_));
  for (const StateBlock& b : layout_) {
    const auto& v = b.state->read(id);
    const std::size_t m = std::min(v.size(), b.size);
    for (std::size_t i = 0; i < m; ++i) out[static_cast<Eigen::Index>(b.offset + i)] = v[i];
    for (std::size_t i = m; i < b.size; ++i) out[static_cast<Eigen::Index>(b.offset + i)] = 0.0;
  }
}

void SystemAssembler::scatter(const Eigen::VectorXd& in, int id) const {
  for (const StateBlock& b : layout_) {
    auto& v = b.state->write(id);
    if (v.size() < b.size) v.resize(b.size, 0.0);
    for (std::size_t i = 0; i < b.size && b.offset + i < static_cast<std::size_t>(in.size()); ++i)
      v[i] = in[static_cast<Eigen::Index>(b.offset + i)];
  }
}

}  // namespace sinew
