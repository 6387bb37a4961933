// ConstraintMatrix: the rows of the constraint Jacobian J on one state
// (SOFA's MatrixDeriv, spec/interaction.md §5.2).
//
// A row is identified by its constraint row id (global over the problem);
// its entries are (DOF, derivative) pairs, `width` scalars each (Vec3d: 3,
// Rigid3d: 6). Constraints and mappings append entries in any order;
// compress() sorts them by row id then DOF and sums duplicates, as SOFA's
// matrix keeps them, so compliance products can merge two rows in one pass.
// Storage is reused from step to step: no allocation once warm.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace sinew {

class ConstraintMatrix {
 public:
  struct Entry {
    int row;
    int dof;
  };
  // A compressed row: entries [begin, end) of entries()/values().
  struct Row {
    int id;
    int begin, end;
  };

  // Empties the matrix; entries get `width` scalars each.
  void clear(int width);
  int width() const { return width_; }
  bool empty() const { return entries_.empty(); }

  // Appends width() values for (row, dof); duplicates are summed by compress().
  void add(int row, int dof, const double* value);
  // Adds `value` to one scalar component of (row, dof).
  void add_component(int row, int dof, int component, double value);

  // Sorts entries by (row, dof) and merges duplicates; builds rows().
  void compress();
  // Valid after compress() (until the next add).
  std::span<const Row> rows() const { return rows_; }
  // The compressed row with id `id`, or null (SOFA's readLine(id) == end()).
  const Row* find_row(int id) const;
  std::span<const Entry> entries() const { return entries_; }
  const double* value(int entry) const { return &values_[static_cast<std::size_t>(entry) * width_]; }
  double* value(int entry) { return &values_[static_cast<std::size_t>(entry) * width_]; }

  // Sets to zero the given scalar components of every entry on `dof`
  // (projective constraints: fixed DOFs have no constraint response).
  void zero_dof(int dof, int first_component, int count);
  // Removes every entry (fixAll).
  void zero_all();

 private:
  int width_ = 3;
  bool sorted_ = true;
  std::vector<Entry> entries_;
  std::vector<double> values_;
  std::vector<Row> rows_;
  std::vector<int> row_of_id_;  // compress(): index in rows_ of each row id (−1: none), for find_row
  // compress() scratch
  std::vector<int> order_;
  std::vector<Entry> entries_tmp_;
  std::vector<double> values_tmp_;
};

}  // namespace sinew
