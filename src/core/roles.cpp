#include "core/roles.h"

#include <algorithm>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/value_text.h"

namespace sinew {

const StateTypeInfo& state_type_info(StateType t) {
  static const StateTypeInfo infos[] = {
      {"Vec1d", 1, 1, 1}, {"Vec2d", 2, 2, 2}, {"Vec3d", 3, 3, 3},
      {"Vec6d", 6, 6, 6}, {"Rigid2d", 3, 3, 2}, {"Rigid3d", 7, 6, 3},
  };
  return infos[static_cast<int>(t)];
}

bool state_type_from_name(std::string_view name, StateType& out) {
  for (int i = 0; i <= static_cast<int>(StateType::rigid3); ++i) {
    if (name == state_type_info(static_cast<StateType>(i)).name) {
      out = static_cast<StateType>(i);
      return true;
    }
  }
  return false;
}

bool MechanicalState::independent() const { return !node() || node()->mechanical_mapping == nullptr; }

OdeSolver::OdeSolver() = default;
OdeSolver::~OdeSolver() = default;

MechanicalOps& OdeSolver::scope() {
  if (!scope_) scope_ = std::make_unique<MechanicalOps>(*node());
  scope_->sync();
  return *scope_;
}

void ForceField::init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

void ProjectiveConstraint::init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

// Rows of the output's constraint Jacobian mapped onto the inputs: each
// non-zero component k of an entry on output DOF d is spread over the J
// entries of scalar row d·w+k. J entries are grouped by output row with a
// counting sort (stable: the mapping's own order within a row); each mapped
// row is accumulated per input DoF and appended once per DoF in increasing
// DoF order, so an input fed by this mapping alone needs no sort to compress.
bool Mapping::apply_jt_constraints() {
  MechanicalState* out = output();
  if (!out) return true;
  ConstraintMatrix& c = out->constraint_jacobian();
  if (c.empty()) return true;
  c.compress();
  const std::vector<MechanicalState*> ins = inputs();
  auto& acc = constraint_sink_.acc_;
  if (acc.size() < ins.size()) acc.resize(ins.size());
  for (std::size_t k = 0; k < ins.size(); ++k) {
    acc[k].width = ins[k]->info().deriv_width;
    acc[k].slot.assign(ins[k]->size(), -1);
  }
  const int wo = out->info().deriv_width;
  const bool fast = has_jt_entry();
  std::size_t scalars = 0;
  if (!fast) {
    constraint_j_.clear();
    if (!jacobian(constraint_j_)) return false;
    scalars = out->size() * static_cast<std::size_t>(wo);
    constraint_row_start_.assign(scalars + 2, 0);
    for (const JacobianEntry& e : constraint_j_)
      if (e.row < scalars) ++constraint_row_start_[e.row + 2];
    for (std::size_t r = 2; r < constraint_row_start_.size(); ++r)
      constraint_row_start_[r] += constraint_row_start_[r - 1];
    constraint_sorted_.resize(constraint_j_.size());
    for (const JacobianEntry& e : constraint_j_)
      if (e.row < scalars) constraint_sorted_[constraint_row_start_[e.row + 1]++] = e;
    // constraint_row_start_[r] .. [r+1] now spans row r.
  }
  double one[8] = {};
  const auto entries = c.entries();
  for (const ConstraintMatrix::Row& row : c.rows()) {
    for (int e = row.begin; e < row.end; ++e) {
      const double* v = c.value(e);
      if (fast) {
        jt_entry(static_cast<unsigned>(entries[e].dof), v, constraint_sink_);
        continue;
      }
      for (int k = 0; k < wo; ++k) {
        if (v[k] == 0.0) continue;
        const std::size_t scalar = static_cast<std::size_t>(entries[e].dof) * wo + k;
        if (scalar >= scalars) continue;
        for (int j = constraint_row_start_[scalar]; j < constraint_row_start_[scalar + 1]; ++j) {
          const JacobianEntry& je = constraint_sorted_[j];
          if (je.input >= ins.size()) continue;
          const int wi = acc[je.input].width;
          std::fill(one, one + wi, 0.0);
          one[je.col % wi] = v[k] * je.value;
          constraint_sink_.add(je.input, je.col / wi, one);
        }
      }
    }
    // Flush the row: one entry per touched DoF, in DoF order.
    for (std::size_t k = 0; k < ins.size(); ++k) {
      ConstraintRowSink::Acc& a = acc[k];
      if (a.dofs.empty()) continue;
      std::sort(a.dofs.begin(), a.dofs.end());
      ConstraintMatrix& target = ins[k]->constraint_jacobian();
      for (int dof : a.dofs) {
        int& slot = a.slot[dof];
        target.add(row.id, dof, &a.values[static_cast<std::size_t>(slot) * a.width]);
        slot = -1;
      }
      a.dofs.clear();
      a.values.clear();
    }
  }
  return true;
}

void Mapping::parse(AttributeMap& attrs, Diagnostics& diag) {
  if (const std::string* v = attrs.take("isMechanical")) {
    if (!map_forces.read(*v) && !v->empty())
      diag.warning(where, describe() + ": could not read value for field 'isMechanical': " + quote_value(*v));
    map_masses.read(*v);
  }
  Component::parse(attrs, diag);
}

}  // namespace sinew

namespace sinew {

// ---------------------------------------------------------------- topology handlers

TopologyHandler::~TopologyHandler() { attach(nullptr); }

void TopologyHandler::attach(MeshTopologyBase* t) {
  if (topology_ == t) return;
  if (topology_) {
    auto& v = topology_->handlers_;
    v.erase(std::remove(v.begin(), v.end(), this), v.end());
  }
  topology_ = t;
  if (t) t->handlers_.push_back(this);
}

MeshTopologyBase::~MeshTopologyBase() {
  for (TopologyHandler* h : handlers_) h->topology_ = nullptr;
}

}  // namespace sinew
