// CubeTree: the bounding-volume hierarchy above one collision model, SOFA's
// chain of CubeCollisionModels (spec/interaction.md §1.4).
//
// Leaf cubes (one per element, each holding its element's box enlarged by the
// model's contactDistance) are stably sorted at the first build, level by
// level, by the centre of the cell being split; coarse levels 0 (the root,
// one cube) … depth hold cubes whose children are a range of cubes of the
// next level or, for cells of at most four leaves, a range of leaf cubes.
// Later calls only refit the boxes bottom-up: the tree's topology (and
// therefore the order contacts are found in) is frozen until the number of
// elements changes, exactly as in SOFA.
#pragma once

#include <cstdint>
#include <vector>

#include "math/types.h"

namespace sinew {

struct Aabb {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
};

class CubeTree {
 public:
  static constexpr int kLeafLevel = -1;  // child_level of cubes whose children are leaf cubes

  struct Leaf {
    Aabb box;
    unsigned elem = 0;  // the element this leaf cube bounds
  };
  struct Cube {
    Aabb box;
    unsigned first = 0, last = 0;  // children: [first, last) in level child_level (or the leaves)
    int child_level = kLeafLevel;
  };

  // Number of elements; a change empties the coarse levels (rebuilt by update()).
  void resize(std::size_t n);
  std::size_t size() const { return leaves_.size(); }
  bool built() const { return !levels_.empty() && !levels_[0].empty(); }
  // Drops the coarse levels so that the next update() rebuilds (topology changed).
  void invalidate() { levels_.clear(); }
  // Box of element `elem` (through the element → leaf map).
  void set_box(unsigned elem, const Aabb& box) { leaves_[leaf_of_[elem]].box = box; }

  // Builds the levels when needed (first call, size or depth changed), else
  // refits every cube to its children, deepest level first.
  void update(int depth);

  const std::vector<Leaf>& leaves() const { return leaves_; }
  const std::vector<std::vector<Cube>>& levels() const { return levels_; }
  const Cube& root() const { return levels_[0][0]; }

 private:
  void build(int depth);
  Aabb union_of(const Cube& c) const;

  std::vector<Leaf> leaves_;
  std::vector<unsigned> leaf_of_;  // element → leaf cube (SOFA's parentOf)
  std::vector<std::vector<Cube>> levels_;
};

// Whether two boxes overlap once each is enlarged by `margin` on every side
// (one test for the pair, as SOFA's proximity cube–cube test: reject when
// min1 > max2 + margin or min2 > max1 + margin on an axis).
inline bool boxes_overlap(const Aabb& a, const Aabb& b, double margin) {
  for (int i = 0; i < 3; ++i)
    if (a.min[i] > b.max[i] + margin || b.min[i] > a.max[i] + margin) return false;
  return true;
}

}  // namespace sinew
