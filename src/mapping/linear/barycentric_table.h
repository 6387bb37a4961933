// BaryTable: what a BarycentricMapping knows once initialised — for each output
// point, the input vertices it depends on and their weights, as flat arrays, and
// the input element they came from — and the loops that apply it. The map is linear, so the same table serves
// positions, velocities, Jᵀ and the assembled J, whatever kind of element the
// weights came from (barycentric_coords.h computes them).
#pragma once

#include <cstdint>
#include <vector>

#include "core/matrix_sink.h"

namespace sinew {

class BaryTable {
 public:
  // Element of a point located without one (regular grid cells are not numbered).
  static constexpr unsigned kNoElement = ~0u;

  std::size_t points() const { return start_.size() - 1; }
  void clear();

  // Building, one output point at a time: its terms in summation order, then end_point().
  void add(unsigned vertex, double weight) {
    idx_.push_back(vertex);
    w_.push_back(weight);
  }
  // `element`: index of the input element in its list (tetrahedra, hexahedra, ...; the mesh
  // mapper numbers its second kind after the first), kept for checks and messages.
  void end_point(unsigned element = kNoElement) {
    start_.push_back(static_cast<std::uint32_t>(idx_.size()));
    element_.push_back(element);
  }

  // out_i = Σ_k w_k · in[idx_k] (Vec3 per point), summed in insertion order; out is resized.
  void gather(const std::vector<double>& in, std::vector<double>& out) const;
  // in[idx_k] += w_k · out_i (Jᵀ), for the output points out holds.
  void scatter_add(const std::vector<double>& out, std::vector<double>& in) const;
  // J as entries on input 0: by output point, then term, then coordinate.
  void jacobian(std::vector<JacobianEntry>& out) const;
  // Terms [begin, end) of output point i: vertex(k), weight(k).
  std::uint32_t begin(std::size_t i) const { return start_[i]; }
  std::uint32_t end(std::size_t i) const { return start_[i + 1]; }
  unsigned vertex(std::uint32_t k) const { return idx_[k]; }
  double weight(std::uint32_t k) const { return w_[k]; }
  unsigned element(std::size_t i) const { return element_[i]; }
  // Largest input vertex index used + 1 (0 when empty): the input must have at least this many points.
  std::size_t vertices_needed() const;

 private:
  // Output point i owns terms [start_[i], start_[i + 1]).
  std::vector<std::uint32_t> start_{0};
  std::vector<unsigned> idx_;
  std::vector<double> w_;
  std::vector<unsigned> element_;  // per output point
};

}  // namespace sinew
