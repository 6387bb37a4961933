#include "mapping/nonlinear/edge_kernels.h"

#include <algorithm>

#include "core/node.h"
#include "core/value_text.h"

namespace sinew::edge {

void append_edge_row(std::vector<JacobianEntry>& out, std::uint32_t row, std::uint32_t col0, std::uint32_t col1,
                     const double* g) {
  for (std::uint32_t k = 0; k < 3; ++k) {
    out.push_back({0, row, col0 + k, -g[k]});
    out.push_back({0, row, col1 + k, g[k]});
  }
}

void add_edge_block(MatrixSink& K, const MechanicalState* s0, std::size_t i0, const MechanicalState* s1,
                    std::size_t i1, const double b[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) {
      K.add(s0, i0 + j, s0, i0 + c, b[j][c]);
      K.add(s0, i0 + j, s1, i1 + c, -b[j][c]);
      K.add(s1, i1 + j, s0, i0 + c, -b[j][c]);
      K.add(s1, i1 + j, s1, i1 + c, b[j][c]);
    }
}

void apply_rows(const std::vector<Edge>& edges, const std::vector<double>& rows, const std::vector<double>& in,
                int dw, std::vector<double>& out) {
  out.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const unsigned i0 = edges[e][0], i1 = edges[e][1];
    out[e] = row_dot(&rows[e * 3], &in[i0 * dw], &in[i1 * dw], i1 < i0);
  }
}

void apply_rows_transposed(const std::vector<Edge>& edges, const std::vector<double>& rows,
                           const std::vector<double>& out, int dw, std::vector<double>& in) {
  const std::size_t n = std::min(edges.size(), out.size());
  for (std::size_t e = 0; e < n; ++e) {
    add_end_force(&in[edges[e][0] * dw], -1.0, &rows[e * 3], out[e]);
    add_end_force(&in[edges[e][1] * dw], 1.0, &rows[e * 3], out[e]);
  }
}

bool init_edges(MappingBase& m, const std::string& geometric_stiffness, Link<MeshTopologyBase>& topology,
                std::size_t n_in, int& gs, std::vector<Edge>& edges) {
  gs = geometric_stiffness_id(geometric_stiffness, 2);
  if (gs < 0) {
    m.msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
                quote_value(geometric_stiffness));
    return false;
  }
  if (!topology && m.node()) topology.set(m.node()->get_mesh_topology_link());
  if (!topology) {
    m.msg_error("no topology found (set topology=\"@...\" to a container with edges)");
    return false;
  }
  edges = topology->edges();
  if (edges.empty()) {
    m.msg_error("the topology " + topology->describe() + " has no edges");
    return false;
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (unsigned v : edges[e])
      if (v >= n_in) {
        m.msg_error("edge " + std::to_string(e) + " uses point " + std::to_string(v) + " but the input has " +
                    std::to_string(n_in) + " points");
        return false;
      }
  return true;
}

}  // namespace sinew::edge
