#include "solver/system/mapped_assembly.h"

#include <algorithm>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

namespace {

std::size_t scalar_size(const MechanicalState* s) {
  return s->size() * static_cast<std::size_t>(s->info().deriv_width);
}

std::uint64_t key(std::uint32_t r, std::uint32_t c) { return (static_cast<std::uint64_t>(r) << 32) | c; }

// Mapping chains deeper than this are taken for a cycle.
constexpr int kMaxDepth = 64;

}  // namespace

void MappedAssembly::project(MechanicalOps& ops, const std::vector<Pair>& pairs, MatrixSink& sink,
                             const OffsetOf& offset_of, const std::vector<char>& constant) {
  if (!unchanged(pairs, sink) || constant != constant_) {
    constant_ = constant;
    build(ops, pairs, sink, offset_of);
    for (Product& p : products_)
      p.frozen = static_cast<std::size_t>(p.pair) < constant_.size() && constant_[static_cast<std::size_t>(p.pair)];
  }
  compute(sink);
  for (const Product& p : products_) {
    const auto oa = static_cast<std::uint32_t>(offset_of(p.state_a));
    const auto ob = static_cast<std::uint32_t>(offset_of(p.state_b));
    const Csr& R = p.R;
    for (int r = 0; r < R.rows; ++r)
      for (int q = R.ptr[r]; q < R.ptr[r + 1]; ++q)
        sink.add_raw(0, oa + static_cast<std::uint32_t>(r), ob + static_cast<std::uint32_t>(R.idx[q]), R.val[q]);
  }
}

// True when the patterns built last time still apply: same pairs, same
// sequence of mapped entries, same state sizes and same Jacobian entries
// (whose values are fetched here, for compute()).
bool MappedAssembly::unchanged(const std::vector<Pair>& pairs, const MatrixSink& sink) {
  if (!valid_ || pairs != pairs_) return false;
  std::size_t j = 0;
  for (const MatrixSink::Triplet& t : sink.triplets()) {
    if (t.target == 0) continue;
    if (j >= key_target_.size() || key_target_[j] != t.target || key_row_[j] != t.row || key_col_[j] != t.col)
      return false;
    ++j;
  }
  if (j != key_target_.size()) return false;
  for (const Chain& c : chains_)
    if (scalar_size(c.state) != c.size) return false;
  for (std::size_t p = 0; p < pairs.size(); ++p)  // states outside the system have no chain
    if (pairs[p].first && pairs[p].second &&
        pair_sizes_[p] != std::make_pair(scalar_size(pairs[p].first), scalar_size(pairs[p].second)))
      return false;
  for (MappingJacobian& m : jacobians_) {
    m.entries.clear();
    if (!m.mapping->jacobian(m.entries) || m.entries.size() != m.slot.size()) return false;
    for (std::size_t e = 0; e < m.entries.size(); ++e) {
      const JacobianEntry& x = m.entries[e];
      if (x.input != m.key_input[e] || x.row != m.key_row[e] || x.col != m.key_col[e]) return false;
    }
  }
  return true;
}

void MappedAssembly::build(MechanicalOps& ops, const std::vector<Pair>& pairs, const MatrixSink& sink,
                           const OffsetOf& offset_of) {
  pairs_ = pairs;
  jacobians_.clear();
  chains_.clear();
  products_.clear();
  missing_.clear();

  // K of each pair, from the recorded sequence of mapped entries.
  key_target_.clear();
  key_row_.clear();
  key_col_.clear();
  std::vector<std::vector<std::uint64_t>> keys(pairs.size());
  std::vector<std::vector<std::size_t>> where(pairs.size());  // position in the sequence
  for (const MatrixSink::Triplet& t : sink.triplets()) {
    if (t.target == 0) continue;
    const std::size_t p = static_cast<std::size_t>(t.target - 1);
    if (p < pairs.size()) {
      keys[p].push_back(key(t.row, t.col));
      where[p].push_back(key_target_.size());
    }
    key_target_.push_back(t.target);
    key_row_.push_back(t.row);
    key_col_.push_back(t.col);
  }
  slot_.assign(key_target_.size(), -1);
  K_.assign(pairs.size(), Csr{});
  std::vector<int> slots;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [a, b] = pairs[p];
    if (!a || !b) continue;
    csr_pattern(static_cast<int>(scalar_size(a)), static_cast<int>(scalar_size(b)), keys[p], K_[p], slots);
    for (std::size_t i = 0; i < slots.size(); ++i) slot_[where[p][i]] = slots[i];
  }

  // Chains of Jacobians and the products J_aᵀ·(K·J_b), by SOFA's rule
  // (MatrixProjectionMethod::addMappedMatrixToGlobalMatrixEigen): one product
  // for every ordered pair (a, b) of the independent states either side
  // reaches, landing at (offset a, offset b). A side that does not reach a
  // (or reaches nothing: a state outside this system, such as an obstacle's
  // contact points) takes no Jacobian, i.e. its K rows or columns stay in that
  // state's own indices. For one body this is the exact Jᵀ·K·J; otherwise
  // SOFA adds these extra terms, and its results (BeamFEMForceField.scn:
  // contacts with the floor) depend on them.
  identities_.clear();
  pair_sizes_.assign(pairs.size(), {0, 0});
  std::vector<const MechanicalState*> tops;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (!pairs[p].first || !pairs[p].second) continue;
    pair_sizes_[p] = {scalar_size(pairs[p].first), scalar_size(pairs[p].second)};
    const std::size_t missing_before = missing_.size();
    const int ca = chain_of(ops, pairs[p].first, offset_of, 0);
    const int cb = chain_of(ops, pairs[p].second, offset_of, 0);
    if (missing_.size() != missing_before) continue;  // a mapping without Jacobian: not assembled
    tops.clear();
    for (int c : {ca, cb})
      if (c >= 0)
        for (const TopJacobian& t : chains_[c].tops)
          if (std::find(tops.begin(), tops.end(), t.top) == tops.end()) tops.push_back(t.top);
    for (const MechanicalState* a : tops)
      for (const MechanicalState* b : tops) {
        Product prod{static_cast<int>(p), ca, top_index(ca, a), cb, top_index(cb, b), {}, {}, false, false, {}, {}};
        prod.state_a = a;
        prod.state_b = b;
        if (prod.top_a < 0) prod.identity_a = identity(static_cast<int>(pair_sizes_[p].first));
        if (prod.top_b < 0) prod.identity_b = identity(static_cast<int>(pair_sizes_[p].second));
        csr_multiply_pattern(K_[p], jacobian_b(prod), prod.KJ);
        csr_multiply_pattern(jacobian_a_transposed(prod), prod.KJ, prod.R);
        products_.push_back(std::move(prod));
      }
  }
  valid_ = true;
  ++pattern_builds_;
}

const Csr* MappedAssembly::identity(int n) {
  for (const Csr& c : identities_)
    if (c.rows == n) return &c;
  identities_.emplace_back();
  csr_identity(n, identities_.back());
  return &identities_.back();
}

int MappedAssembly::top_index(int chain, const MechanicalState* top) const {
  if (chain < 0) return -1;
  const std::vector<TopJacobian>& tops = chains_[static_cast<std::size_t>(chain)].tops;
  for (std::size_t t = 0; t < tops.size(); ++t)
    if (tops[t].top == top) return static_cast<int>(t);
  return -1;
}

const Csr& MappedAssembly::jacobian_b(const Product& p) const {
  return p.top_b < 0 ? *p.identity_b : chains_[p.chain_b].tops[p.top_b].J;
}

const Csr& MappedAssembly::jacobian_a_transposed(const Product& p) const {
  return p.top_a < 0 ? *p.identity_a : chains_[p.chain_a].tops[p.top_a].Jt;
}

int MappedAssembly::jacobian_of(Mapping* mapping) {
  for (std::size_t i = 0; i < jacobians_.size(); ++i)
    if (jacobians_[i].mapping == mapping) return static_cast<int>(i);
  MappingJacobian m;
  m.mapping = mapping;
  if (!mapping->jacobian(m.entries)) {
    missing_.push_back(mapping);
    return -1;
  }
  m.inputs = mapping->inputs();
  const MechanicalState* out = mapping->output();
  const std::size_t n = m.entries.size();
  m.key_input.resize(n);
  m.key_row.resize(n);
  m.key_col.resize(n);
  m.slot.assign(n, -1);
  m.per_input.resize(m.inputs.size());
  std::vector<int> slots;
  for (std::size_t k = 0; k < m.inputs.size(); ++k) {
    std::vector<std::uint64_t> keys;
    std::vector<std::size_t> where;
    for (std::size_t e = 0; e < n; ++e)
      if (m.entries[e].input == k) {
        keys.push_back(key(m.entries[e].row, m.entries[e].col));
        where.push_back(e);
      }
    const int nin = m.inputs[k] ? static_cast<int>(scalar_size(m.inputs[k])) : 0;
    csr_pattern(static_cast<int>(scalar_size(out)), nin, keys, m.per_input[k], slots);
    for (std::size_t i = 0; i < where.size(); ++i) m.slot[where[i]] = slots[i];
  }
  for (std::size_t e = 0; e < n; ++e) {
    m.key_input[e] = m.entries[e].input;
    m.key_row[e] = m.entries[e].row;
    m.key_col[e] = m.entries[e].col;
  }
  jacobians_.push_back(std::move(m));
  return static_cast<int>(jacobians_.size() - 1);
}

// Index of the chain of `s` in chains_ (built on demand, inputs first), -1
// when `s` cannot be reached from the independent states.
int MappedAssembly::chain_of(MechanicalOps& ops, const MechanicalState* s, const OffsetOf& offset_of, int depth) {
  if (!s || depth > kMaxDepth) return -1;
  for (std::size_t i = 0; i < chains_.size(); ++i)
    if (chains_[i].state == s) return static_cast<int>(i);

  Chain chain;
  chain.state = s;
  chain.size = scalar_size(s);
  if (offset_of(s) >= 0) {
    TopJacobian top;
    top.top = s;
    csr_identity(static_cast<int>(chain.size), top.J);
    csr_identity(static_cast<int>(chain.size), top.Jt);
    chain.tops.push_back(std::move(top));
    chains_.push_back(std::move(chain));
    return static_cast<int>(chains_.size() - 1);
  }
  Mapping* mapping = nullptr;
  for (Mapping* mp : ops.mappings())
    if (mp->output() == s) mapping = mp;
  if (!mapping) return -1;
  chain.jacobian = jacobian_of(mapping);
  if (chain.jacobian < 0) return -1;

  const std::size_t ninputs = jacobians_[chain.jacobian].inputs.size();
  chain.input_chain.assign(ninputs, -1);
  for (std::size_t k = 0; k < ninputs; ++k) {
    const MechanicalState* in = jacobians_[chain.jacobian].inputs[k];
    if (!in) continue;
    chain.input_chain[k] = chain_of(ops, in, offset_of, depth + 1);
    if (chain.input_chain[k] < 0) return -1;
  }
  // One term J_k · J(input k → top) per (input, top of that input's chain).
  for (std::size_t k = 0; k < ninputs; ++k) {
    if (chain.input_chain[k] < 0) continue;
    const Chain& in = chains_[chain.input_chain[k]];
    for (std::size_t t = 0; t < in.tops.size(); ++t) {
      auto it = std::find_if(chain.tops.begin(), chain.tops.end(),
                             [&](const TopJacobian& x) { return x.top == in.tops[t].top; });
      if (it == chain.tops.end()) {
        chain.tops.emplace_back();
        it = chain.tops.end() - 1;
        it->top = in.tops[t].top;
      }
      it->term_input.push_back(static_cast<int>(k));
      it->term_chain_top.push_back(static_cast<int>(t));
      it->terms.emplace_back();
      csr_multiply_pattern(jacobians_[chain.jacobian].per_input[k], in.tops[t].J, it->terms.back());
    }
  }
  for (TopJacobian& top : chain.tops) {
    for (const Csr& term : top.terms) top.term_ptrs.push_back(&term);
    csr_sum_pattern(top.term_ptrs, top.J);
    csr_transpose_pattern(top.J, top.Jt, top.jt_src);
  }
  chains_.push_back(std::move(chain));
  return static_cast<int>(chains_.size() - 1);
}

void MappedAssembly::compute(const MatrixSink& sink) {
  for (MappingJacobian& m : jacobians_) {
    for (Csr& J : m.per_input) J.set_zero();
    for (std::size_t e = 0; e < m.entries.size(); ++e)
      if (m.slot[e] >= 0) m.per_input[m.entries[e].input].val[m.slot[e]] += m.entries[e].value;
  }
  // chains_ lists inputs before the states they map to.
  for (Chain& c : chains_) {
    if (c.jacobian < 0) continue;  // identity
    const MappingJacobian& m = jacobians_[c.jacobian];
    for (TopJacobian& top : c.tops) {
      for (std::size_t i = 0; i < top.terms.size(); ++i) {
        const int k = top.term_input[i];
        csr_multiply_values(m.per_input[k], chains_[c.input_chain[k]].tops[top.term_chain_top[i]].J, top.terms[i],
                            work_);
      }
      csr_sum_values(top.term_ptrs, top.J, work_);
      csr_transpose_values(top.J, top.jt_src, top.Jt);
    }
  }
  for (Csr& K : K_) K.set_zero();
  std::size_t j = 0;
  for (const MatrixSink::Triplet& t : sink.triplets()) {
    if (t.target == 0) continue;
    if (slot_[j] >= 0) K_[t.target - 1].val[slot_[j]] += t.value;
    ++j;
  }
  for (Product& p : products_) {
    const Csr* Jb = &jacobian_b(p);
    const Csr* Jat = &jacobian_a_transposed(p);
    if (p.frozen) {  // the Jacobians of the first assembly since the pattern was built
      if (!p.captured) {
        p.Jb = *Jb;
        p.Jat = *Jat;
        p.captured = true;
      }
      Jb = &p.Jb;
      Jat = &p.Jat;
    }
    csr_multiply_values(K_[p.pair], *Jb, p.KJ, work_);
    csr_multiply_values(*Jat, p.KJ, p.R, work_);
  }
}

}  // namespace sinew
