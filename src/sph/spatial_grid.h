// SpatialGrid: the uniform hash grid of SofaSphFluid's SpatialGridContainer
// (spec/interaction.md §8), used to find every pair of particles closer than
// a distance in time linear in the particle count.
//
// Space is cut into cubic cells of width `cell_width`; cells are grouped in
// blocks of 8×8×8, and only blocks holding particles (and their six face
// neighbours) exist, found through a hash map keyed by block coordinates.
// A pair search visits every non-empty cell with a half stencil of 14 cells
// (itself and 13 forward neighbours), so each pair is met once; it is exact
// when cell_width is at least the search distance.
//
// Order matters for the digits of whatever sums over the pairs, so the grid
// reproduces SOFA's: blocks are visited in the iteration order of a
// std::unordered_map fed with the same keys, hash and insertion sequence
// (SOFA's SpatialGrid::getGrid), cells z-major then y then x, particles of a
// cell in insertion (index) order, stencil in SOFA's order. Cell coordinates
// use SOFA's rfloor (16.16 fixed-point rounding, see sofa_rfloor).
//
// Storage is flat: per-particle (cell, position) records sorted by cell with a
// counting sort, per-cell start offsets, a block array with face-neighbour
// indices (block 0 is the shared empty block). Map nodes come from a free
// list, so once the grid has seen its largest block count an update
// allocates nothing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace sinew::sph {

// SOFA's helper::rfloor: r + 1.5·2³⁶ puts r in 16.16 fixed point in the low
// word of the double (rounded to nearest), then an arithmetic shift floors it.
// Differs from std::floor within 2⁻¹⁷ below an integer (rounds up there).
inline int sofa_rfloor(double r) {
  const double d = r + 1.5 * static_cast<double>(1LL << 36);
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  const auto low = static_cast<std::int32_t>(static_cast<std::uint32_t>(bits & 0xffffffffu));
  return low >> 16;
}

// Fixed-size free list for the hash map's nodes (allocation of one object of
// the node size); bucket arrays go to the heap (they only grow).
struct NodePool {
  std::size_t node_size = 0;
  std::vector<void*> free_nodes;
  std::vector<void*> owned;
  NodePool() = default;
  NodePool(const NodePool&) = delete;
  NodePool& operator=(const NodePool&) = delete;
  ~NodePool();
};

template <class T>
struct PoolAllocator {
  using value_type = T;
  NodePool* pool = nullptr;
  explicit PoolAllocator(NodePool* p) : pool(p) {}
  template <class U>
  PoolAllocator(const PoolAllocator<U>& o) : pool(o.pool) {}  // NOLINT: rebinding
  T* allocate(std::size_t n) {
    if (n == 1 && pool) {
      if (pool->node_size == 0) pool->node_size = sizeof(T);
      if (pool->node_size == sizeof(T)) {
        if (!pool->free_nodes.empty()) {
          void* p = pool->free_nodes.back();
          pool->free_nodes.pop_back();
          return static_cast<T*>(p);
        }
        void* p = ::operator new(sizeof(T));
        pool->owned.push_back(p);
        return static_cast<T*>(p);
      }
    }
    return static_cast<T*>(::operator new(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) {
    if (n == 1 && pool && pool->node_size == sizeof(T)) {
      pool->free_nodes.push_back(p);
      return;
    }
    ::operator delete(p);
  }
  template <class U>
  bool operator==(const PoolAllocator<U>& o) const { return pool == o.pool; }
};

// Output of SpatialGrid::find_pairs: the pairs in the order found, in runs
// (one per searching point, possibly empty). Run k holds the pairs
// [run_end[k-1], run_end[k]) (run_end[-1] = 0), each pairing run_first[k] with
// second[e]. The vectors are scratch storage, longer than `size` and `runs`
// (a vector store writes a few lanes past the last pair).
//
// The squared distances are not kept: r² = ((x2 − x1)² + (y2 − y1)²) +
// (z2 − z1)² computed again from the points has the same bits in either
// order of the pair, because a − b = −(b − a) exactly and squares drop the
// sign. Not keeping them halves what the search and the row sort move.
struct PairBuffer {
  std::vector<std::uint32_t> second;
  std::vector<std::uint32_t> run_first, run_end;
  std::size_t size = 0;
  std::size_t runs = 0;
  // Scratch of the AVX-512 search: the candidates of the visited cell (its
  // stencil's entries, one range after the other).
  std::vector<double> cand_x, cand_y, cand_z;
  std::vector<std::uint32_t> cand_index;
};

// The search's kernels. All find the same pairs in the same order; `best` is
// the widest the processor runs, and asking for one it lacks gets the next narrower.
enum class PairKernel { scalar, avx2, avx512, best };

class SpatialGrid {
 public:
  static constexpr int kLog2 = 3;
  static constexpr int kDim = 1 << kLog2;  // cells per block side
  static constexpr int kCells = kDim * kDim * kDim;

  using Key = std::array<int, 3>;
  // SOFA's SpatialGrid::hash (32-bit products of large primes, xor-ed).
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      const unsigned p0 = 73856093u, p1 = 19349663u, p2 = 83492791u;
      return static_cast<std::size_t>((p0 * static_cast<unsigned>(k[0])) ^ (p1 * static_cast<unsigned>(k[1])) ^
                                      (p2 * static_cast<unsigned>(k[2])));
    }
  };

  // std::array's == calls memcmp; three int compares inline.
  struct KeyEqual {
    bool operator()(const Key& a, const Key& b) const { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
  };

  // Precondition: cell_width > 0 (length).
  explicit SpatialGrid(double cell_width);
  SpatialGrid(const SpatialGrid&) = delete;
  SpatialGrid& operator=(const SpatialGrid&) = delete;

  double cell_width() const { return cell_width_; }

  // Rebuilds the grid from n points stored flat (3 doubles each), in index order.
  void update(const double* x, std::size_t n);

  // Calls f(i1, i2, r2) once for every pair of points of the last update with
  // squared distance r2 < dist², in SOFA's order (i1 is the point of the
  // visited cell; either may be the larger index). Exact when dist <= cell_width.
  template <class F>
  void for_each_pair(double dist, F&& f) const;

  // The pairs of for_each_pair, in the same order, written to flat arrays:
  // pair e of run k is (out.run_first[k], out.second[e]), the indices (i1, i2)
  // for_each_pair would pass. The arrays only grow (allocation-free once
  // warm); out.size counts the pairs.
  void find_pairs(double dist, PairBuffer& out, PairKernel kernel = PairKernel::best) const;

  // Number of blocks created by the last update (non-empty ones and their face neighbours).
  std::size_t block_count() const { return blocks_.size() - 1; }
  std::size_t non_empty_block_count() const;
  // Block coordinates of a created block, 0-based, in map iteration order (drawing, tests).
  std::vector<Key> block_keys() const;

  // Sorts the points cell by cell (SOFA's reorderIndices): new2old[k] is the
  // point that goes to index k. Blocks in map order, cells of a block in the
  // Morton order SOFA uses, points of a cell in index order.
  void reorder(std::vector<unsigned>& new2old) const;

 private:
  struct Block {
    Key key{};
    bool empty = true;
    std::uint32_t nb[6] = {0, 0, 0, 0, 0, 0};  // -x +x -y +y -z +z; 0 = the empty block
  };
  using Map = std::unordered_map<Key, std::uint32_t, KeyHash, KeyEqual,
                                 PoolAllocator<std::pair<const Key, std::uint32_t>>>;

  std::uint32_t get_block(const Key& k);
  // Calls f(cells) for every non-empty cell in SOFA's order (blocks in map order, cells
  // z-major), cells[0] being that cell and cells[1..13] its forward stencil (global ids).
  template <class F>
  void for_each_cell(F&& f) const;
  // Global cell id of cell (x, y, z) of block b; coordinates may step one block out.
  std::uint32_t cell_of(std::uint32_t b, int x, int y, int z) const {
    if (x < 0) { b = blocks_[b].nb[0]; x += kDim; }
    else if (x >= kDim) { b = blocks_[b].nb[1]; x -= kDim; }
    if (y < 0) { b = blocks_[b].nb[2]; y += kDim; }
    else if (y >= kDim) { b = blocks_[b].nb[3]; y -= kDim; }
    if (z < 0) { b = blocks_[b].nb[4]; z += kDim; }
    else if (z >= kDim) { b = blocks_[b].nb[5]; z -= kDim; }
    return cell_base_[b] + static_cast<std::uint32_t>(x + kDim * y + kDim * kDim * z);
  }

  double cell_width_, inv_cell_width_;
  NodePool pool_;  // before map_: outlives it
  Map map_;
  std::vector<Block> blocks_;               // [0] = the empty block
  // Only non-empty blocks own cells: an empty block (SOFA creates the six face
  // neighbours of every occupied one) shares block 0's empty cells.
  std::vector<std::uint32_t> cell_base_;    // per block: its first global cell
  std::vector<std::uint32_t> cell_start_;   // per global cell, +1 sentinel (block 0's cells are empty)
  std::vector<std::uint32_t> point_cell_;   // per point: its global cell
  // Points sorted by cell (stable), and their coordinates (one array per axis).
  // Each array has kPad entries more than points, so that an 8-wide load
  // starting at any entry stays inside it (the extra lanes are masked).
  static constexpr std::size_t kPad = 8;
  std::vector<std::uint32_t> entry_index_;
  std::vector<double> entry_x_, entry_y_, entry_z_;
};

// SOFA's stencil: the cell, then 13 forward neighbours, in this order.
inline constexpr int kPairStencil[14][3] = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {1, 1, 0},   {0, 0, 1},
                                            {1, 0, 1},  {0, 1, 1},  {1, 1, 1},  {-1, 1, 0},  {-1, 0, 1},
                                            {-1, 1, 1}, {-1, -1, 1}, {0, -1, 1}, {1, -1, 1}};

template <class F>
void SpatialGrid::for_each_cell(F&& f) const {
  const std::uint32_t* start = cell_start_.data();
  for (const auto& kv : map_) {
    const std::uint32_t b = kv.second;
    if (blocks_[b].empty) continue;
    for (int z = 0; z < kDim; ++z)
      for (int y = 0; y < kDim; ++y)
        for (int x = 0; x < kDim; ++x) {
          const std::uint32_t c0 = cell_base_[b] + static_cast<std::uint32_t>(x + kDim * y + kDim * kDim * z);
          if (start[c0] == start[c0 + 1]) continue;
          std::uint32_t cells[14];
          for (int s = 0; s < 14; ++s)
            cells[s] = cell_of(b, x + kPairStencil[s][0], y + kPairStencil[s][1], z + kPairStencil[s][2]);
          f(cells);
        }
  }
}

template <class F>
void SpatialGrid::for_each_pair(double dist, F&& f) const {
  const double dist2 = dist * dist;
  const std::uint32_t* start = cell_start_.data();
  const double* px = entry_x_.data();
  const double* py = entry_y_.data();
  const double* pz = entry_z_.data();
  const std::uint32_t* idx = entry_index_.data();
  for_each_cell([&](const std::uint32_t* cells) {
    const std::uint32_t b0 = start[cells[0]], e0 = start[cells[0] + 1];
    for (std::uint32_t p = b0; p < e0; ++p) {
      const double x1 = px[p], y1 = py[p], z1 = pz[p];
      for (std::uint32_t q = p + 1; q < e0; ++q) {
        const double dx = px[q] - x1, dy = py[q] - y1, dz = pz[q] - z1;
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < dist2) f(idx[p], idx[q], r2);
      }
      for (int s = 1; s < 14; ++s) {
        for (std::uint32_t q = start[cells[s]], qe = start[cells[s] + 1]; q < qe; ++q) {
          const double dx = px[q] - x1, dy = py[q] - y1, dz = pz[q] - z1;
          const double r2 = dx * dx + dy * dy + dz * dz;
          if (r2 < dist2) f(idx[p], idx[q], r2);
        }
      }
    }
  });
}

}  // namespace sinew::sph
