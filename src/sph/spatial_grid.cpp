#include "sph/spatial_grid.h"

#include <algorithm>

namespace sinew::sph {

NodePool::~NodePool() {
  for (void* p : owned) ::operator delete(p);
}

SpatialGrid::SpatialGrid(double cell_width)
    : cell_width_(cell_width), inv_cell_width_(1 / cell_width), map_(0, KeyHash{}, KeyEqual{},
                                                                    PoolAllocator<std::pair<const Key, std::uint32_t>>(&pool_)) {
  blocks_.emplace_back();  // the empty block: its neighbours are itself
}

// SOFA's getGrid: `map[k]` inserts the key if absent; a new block links to its
// existing face neighbours both ways (in the order -x +x -y +y -z +z).
std::uint32_t SpatialGrid::get_block(const Key& k) {
  std::uint32_t& slot = map_[k];
  if (slot != 0) return slot;
  const auto b = static_cast<std::uint32_t>(blocks_.size());
  slot = b;
  blocks_.emplace_back();
  blocks_[b].key = k;
  static constexpr int kDir[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (int d = 0; d < 6; ++d) {
    const Key kn{k[0] + kDir[d][0], k[1] + kDir[d][1], k[2] + kDir[d][2]};
    const auto it = map_.find(kn);
    if (it != map_.end() && it->second != 0) {
      blocks_[b].nb[d] = it->second;
      blocks_[it->second].nb[d ^ 1] = b;
    }
  }
  return b;
}

void SpatialGrid::update(const double* x, std::size_t n) {
  // SOFA's begin(): every block goes (the bucket count stays, as map.clear() keeps it).
  map_.clear();
  blocks_.resize(1);
  point_cell_.resize(n);
  static constexpr int kDir[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  // Points of consecutive indices are often in the same block: the last
  // block is reused without the map (looking an existing key up again changes
  // nothing in the map, so the iteration order stays SOFA's).
  Key last{};
  std::uint32_t last_b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int ix = sofa_rfloor(x[3 * i] * inv_cell_width_);
    int iy = sofa_rfloor(x[3 * i + 1] * inv_cell_width_);
    int iz = sofa_rfloor(x[3 * i + 2] * inv_cell_width_);
    const Key k{ix >> kLog2, iy >> kLog2, iz >> kLog2};
    ix &= kDim - 1;
    iy &= kDim - 1;
    iz &= kDim - 1;
    const std::uint32_t b = last_b != 0 && KeyEqual{}(k, last) ? last_b : get_block(k);
    last = k;
    last_b = b;
    if (blocks_[b].empty) {
      blocks_[b].empty = false;
      // Create the six face neighbours (SOFA's add(), allNeighbors = false).
      for (int d = 0; d < 6; ++d)
        if (blocks_[b].nb[d] == 0) get_block(Key{k[0] + kDir[d][0], k[1] + kDir[d][1], k[2] + kDir[d][2]});
    }
    point_cell_[i] = b * kCells + static_cast<std::uint32_t>(ix + kDim * iy + kDim * kDim * iz);
  }
  // Cells for block 0 and the occupied blocks only; point_cell_ moves to them.
  cell_base_.resize(blocks_.size());
  std::uint32_t cells = kCells;  // block 0's
  cell_base_[0] = 0;
  for (std::size_t b = 1; b < blocks_.size(); ++b) {
    cell_base_[b] = blocks_[b].empty ? 0 : cells;
    cells += blocks_[b].empty ? 0 : kCells;
  }
  for (std::size_t i = 0; i < n; ++i)
    point_cell_[i] = cell_base_[point_cell_[i] / kCells] + point_cell_[i] % kCells;
  // Counting sort of the points by cell (stable: index order inside a cell).
  const std::size_t ncell = cells;
  cell_start_.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[point_cell_[i] + 1];
  std::uint32_t sum = 0;
  for (std::size_t c = 1; c <= ncell; ++c) cell_start_[c] = sum += cell_start_[c];
  entry_index_.resize(n + kPad, 0);
  entry_x_.resize(n + kPad, 0.0);
  entry_y_.resize(n + kPad, 0.0);
  entry_z_.resize(n + kPad, 0.0);
  // point_cell_ becomes the fill cursor's target slot per point.
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t slot = cell_start_[point_cell_[i]]++;
    entry_index_[slot] = static_cast<std::uint32_t>(i);
    entry_x_[slot] = x[3 * i];
    entry_y_[slot] = x[3 * i + 1];
    entry_z_[slot] = x[3 * i + 2];
  }
  // The cursors now hold each cell's end: shift back to starts.
  for (std::size_t c = ncell; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

std::size_t SpatialGrid::non_empty_block_count() const {
  std::size_t c = 0;
  for (std::size_t b = 1; b < blocks_.size(); ++b) c += blocks_[b].empty ? 0 : 1;
  return c;
}

std::vector<SpatialGrid::Key> SpatialGrid::block_keys() const {
  std::vector<Key> out;
  out.reserve(map_.size());
  for (const auto& kv : map_) out.push_back(kv.first);
  return out;
}

void SpatialGrid::reorder(std::vector<unsigned>& new2old) const {
  new2old.clear();
  for (const auto& kv : map_) {
    const std::uint32_t b = kv.second;
    if (blocks_[b].empty) continue;
    for (int i = 0; i < kCells; ++i) {
      // SOFA's interleaving: bit (3s + c) of i goes to bit (3c + s) of the cell index.
      int j = 0;
      for (int s = 0; s < kLog2; ++s)
        for (int c = 0; c < 3; ++c) j += ((i >> (3 * s + c)) & 1) << (kLog2 * c + s);
      const std::uint32_t cell = cell_base_[b] + static_cast<std::uint32_t>(j);
      for (std::uint32_t q = cell_start_[cell]; q < cell_start_[cell + 1]; ++q) new2old.push_back(entry_index_[q]);
    }
  }
}

}  // namespace sinew::sph
