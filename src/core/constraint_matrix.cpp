#include "core/constraint_matrix.h"

#include <algorithm>
#include <numeric>

#include "core/constraint_matrix_field.h"
#include "core/roles.h"

namespace sinew {

void ConstraintMatrix::clear(int width) {
  width_ = width;
  sorted_ = true;
  entries_.clear();
  values_.clear();
  rows_.clear();
}

void ConstraintMatrix::add(int row, int dof, const double* value) {
  if (!entries_.empty()) {
    const Entry& last = entries_.back();
    if (row < last.row || (row == last.row && dof <= last.dof)) sorted_ = false;
  }
  entries_.push_back({row, dof});
  values_.insert(values_.end(), value, value + width_);
  rows_.clear();
}

void ConstraintMatrix::add_component(int row, int dof, int component, double value) {
  double v[8] = {};
  v[component] = value;
  add(row, dof, v);
}

void ConstraintMatrix::compress() {
  const std::size_t n = entries_.size();
  const std::size_t w = static_cast<std::size_t>(width_);
  if (!sorted_) {
    // Stable: duplicates are summed in the order they were added.
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) {
      const Entry& ea = entries_[a];
      const Entry& eb = entries_[b];
      return ea.row != eb.row ? ea.row < eb.row : ea.dof < eb.dof;
    });
    entries_tmp_.clear();
    values_tmp_.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const int i = order_[k];
      const Entry e = entries_[i];
      const double* v = &values_[static_cast<std::size_t>(i) * w];
      if (!entries_tmp_.empty() && entries_tmp_.back().row == e.row && entries_tmp_.back().dof == e.dof) {
        double* acc = &values_tmp_[values_tmp_.size() - w];
        for (std::size_t c = 0; c < w; ++c) acc[c] += v[c];
      } else {
        entries_tmp_.push_back(e);
        values_tmp_.insert(values_tmp_.end(), v, v + w);
      }
    }
    entries_.swap(entries_tmp_);
    values_.swap(values_tmp_);
    sorted_ = true;
  }
  rows_.clear();
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const int e = static_cast<int>(i);
    if (rows_.empty() || rows_.back().id != entries_[i].row) rows_.push_back({entries_[i].row, e, e + 1});
    else rows_.back().end = e + 1;
  }
  // Unbuilt solvers look rows up by id at every iteration: a direct table.
  row_of_id_.assign(rows_.empty() ? 0 : static_cast<std::size_t>(rows_.back().id) + 1, -1);
  for (std::size_t r = 0; r < rows_.size(); ++r)
    if (rows_[r].id >= 0) row_of_id_[static_cast<std::size_t>(rows_[r].id)] = static_cast<int>(r);
}

const ConstraintMatrix::Row* ConstraintMatrix::find_row(int id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= row_of_id_.size() || rows_.empty()) return nullptr;
  const int r = row_of_id_[static_cast<std::size_t>(id)];
  return r < 0 ? nullptr : &rows_[static_cast<std::size_t>(r)];
}

void ConstraintMatrix::zero_dof(int dof, int first_component, int count) {
  for (std::size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].dof == dof)
      for (int c = first_component; c < first_component + count && c < width_; ++c) values_[i * width_ + c] = 0.0;
}

void ConstraintMatrix::zero_all() {
  for (double& v : values_) v = 0.0;
}

std::string ConstraintMatrixField::text() const {
  ConstraintMatrix& J = state_->constraint_jacobian();
  J.compress();
  std::string out;
  for (const ConstraintMatrix::Row& r : J.rows()) {
    if (!out.empty()) out += '\n';
    out += std::to_string(r.id) + ' ' + std::to_string(r.end - r.begin);
    for (int e = r.begin; e < r.end; ++e) {
      out += ' ' + std::to_string(J.entries()[e].dof);
      for (int c = 0; c < J.width(); ++c) out += ' ' + parse::format_double(J.value(e)[c]);
    }
  }
  return out;
}

}  // namespace sinew
