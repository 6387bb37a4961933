// Small 3-vector helpers shared by AreaMapping and VolumeMapping, written out
// so that each expression keeps SOFA's operation order (results are compared
// with SOFA's to round-off): components in x, y, z order, no fused forms.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/node.h"
#include "mapping/mapping_base.h"

namespace sinew::measure {

inline void sub(const double* a, const double* b, double* r) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Row-major [v]× (v × w = [v]× w).
inline void cross_matrix(const double* v, double* m) {
  m[0] = 0, m[1] = -v[2], m[2] = v[1];
  m[3] = v[2], m[4] = 0, m[5] = -v[0];
  m[6] = -v[1], m[7] = v[0], m[8] = 0;
}

// f += ((k·B)·d)·lambda for a row-major 3×3 block B (SOFA's order of products).
inline void add_scaled_block_product(double k, const double* b, const double* d, double lambda, double* f) {
  for (int r = 0; r < 3; ++r) {
    double s = (k * b[r * 3]) * d[0];
    s += (k * b[r * 3 + 1]) * d[1];
    s += (k * b[r * 3 + 2]) * d[2];
    f[r] += s * lambda;
  }
}

// The element list of a measure mapping: the linked topology, else the node's (SOFA warns).
// False after an error on `m`.
inline MeshTopologyBase* resolve_topology(MappingBase& m, Link<MeshTopologyBase>& topology) {
  if (!topology.is_set() && m.node()) {
    m.msg_warning(
        "link to Topology container should be set to ensure right behavior. First Topology found in current "
        "context will be used.");
  }
  if (!topology && m.node()) topology.set(m.node()->get_mesh_topology_link());
  if (!topology) m.msg_error("no topology found (set topology=\"@...\")");
  return topology.get();
}

// Element vertices against the n_in input points; false after an error naming the element.
template <class Element>
bool check_elements(MappingBase& m, const std::vector<Element>& elements, std::size_t n_in, const char* kind) {
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (unsigned v : elements[e])
      if (v >= n_in) {
        m.msg_error(std::string(kind) + " " + std::to_string(e) + " uses point " + std::to_string(v) +
                    " but the input has " + std::to_string(n_in) + " points");
        return false;
      }
  return true;
}

// Vertex order of a Jacobian row: SOFA sorts the entries by vertex (std::sort, so equal
// vertices of a degenerate element come in an unspecified order; Sinew keeps theirs).
template <std::size_t N>
std::array<unsigned, N> sorted_order(const std::array<unsigned, N>& element) {
  std::array<unsigned, N> order;
  for (unsigned i = 0; i < N; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](unsigned a, unsigned b) { return element[a] < element[b]; });
  return order;
}

}  // namespace sinew::measure
