#include "collision/cube_tree.h"

#include <algorithm>

namespace sinew {

void CubeTree::resize(std::size_t n) {
  const std::size_t n0 = leaves_.size();
  if (n == n0) return;
  levels_.clear();
  leaves_.resize(n);
  leaf_of_.resize(n);
  // New leaves bound their own element; existing ones keep their sorted place (SOFA).
  for (std::size_t i = n0; i < n; ++i) {
    leaves_[i].elem = static_cast<unsigned>(i);
    leaf_of_[i] = static_cast<unsigned>(i);
  }
  if (n < n0)  // elements gone: leaves now bound elements in order again
    for (std::size_t i = 0; i < n; ++i) {
      leaves_[i].elem = static_cast<unsigned>(i);
      leaf_of_[i] = static_cast<unsigned>(i);
    }
}

Aabb CubeTree::union_of(const Cube& c) const {
  Aabb box;
  if (c.first == c.last) return box;
  auto child = [&](unsigned k) -> const Aabb& {
    return c.child_level == kLeafLevel ? leaves_[k].box : levels_[c.child_level][k].box;
  };
  box = child(c.first);
  for (unsigned k = c.first + 1; k < c.last; ++k) {
    const Aabb& b = child(k);
    for (int j = 0; j < 3; ++j) {
      if (b.max[j] > box.max[j]) box.max[j] = b.max[j];
      if (b.min[j] < box.min[j]) box.min[j] = b.min[j];
    }
  }
  return box;
}

void CubeTree::build(int depth) {
  levels_.assign(static_cast<std::size_t>(depth) + 1, {});
  Cube root;
  root.first = 0;
  root.last = static_cast<unsigned>(leaves_.size());
  root.box = union_of(root);
  levels_[0].push_back(root);
  for (int k = 0; k < depth; ++k) {
    std::vector<Cube>& next = levels_[static_cast<std::size_t>(k) + 1];
    next.reserve(levels_[k].size() * 2);
    for (std::size_t ci = 0; ci < levels_[k].size(); ++ci) {
      Cube cell = levels_[k][ci];
      const unsigned n = cell.last - cell.first;
      if (n <= 4) continue;  // only cells with more than four leaves are split
      const Vec3 l = cell.box.max - cell.box.min;
      const int axis = l[0] > l[1] ? (l[0] > l[2] ? 0 : 2) : (l[1] > l[2] ? 1 : 2);
      // Stable, so equal centres keep their order (the tree SOFA builds).
      std::stable_sort(leaves_.begin() + cell.first, leaves_.begin() + cell.last, [axis](const Leaf& a, const Leaf& b) {
        return a.box.min[axis] + a.box.max[axis] < b.box.min[axis] + b.box.max[axis];
      });
      const unsigned middle = cell.first + (n + 1) / 2;
      Cube c1, c2;
      c1.first = cell.first;
      c1.last = middle;
      c2.first = middle;
      c2.last = cell.last;
      c1.box = union_of(c1);
      c2.box = union_of(c2);
      const auto i1 = static_cast<unsigned>(next.size());
      next.push_back(c1);
      next.push_back(c2);
      Cube& parent = levels_[k][ci];
      parent.first = i1;
      parent.last = i1 + 2;
      parent.child_level = k + 1;
    }
  }
  for (std::size_t i = 0; i < leaves_.size(); ++i) leaf_of_[leaves_[i].elem] = static_cast<unsigned>(i);
}

void CubeTree::update(int depth) {
  if (!built() || levels_.size() != static_cast<std::size_t>(depth) + 1) {
    build(depth);
    return;
  }
  for (std::size_t k = levels_.size(); k-- > 0;)
    for (Cube& c : levels_[k])
      if (c.first != c.last) c.box = union_of(c);
}

}  // namespace sinew
