#include "engine/generate/mesh_barycentric_mapper_engine.h"

#include <algorithm>
#include <cmath>
#include <Eigen/Geometry>
#include <limits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

MeshBarycentricMapperEngine::MeshBarycentricMapperEngine() {
  add_input(&input_positions);
  add_input(&mapped_positions);
  add_input(&compute_linear_interpolation);
  add_output(&barycentric_positions);
  add_output(&table_elements);
  add_output(&interpolation_indices);
  add_output(&interpolation_values);
}

void MeshBarycentricMapperEngine::init() {
  if (!topology) {
    topology.set(node()->find_local<MeshTopologyBase>());
    if (!topology) {
      msg_error("no topology: set 'topology' or put one in the node");
      set_state(ComponentState::invalid);
      return;
    }
    msg_warning("no topology given: the node's is used (SOFA recommends naming it)");
  }
  set_dirty();
}

namespace {
// SOFA's Mat3 inverse (adjugate over the determinant); false when singular.
bool invert3(const Mat3& m, Mat3& r) {
  const double det = m(0, 0) * m(1, 1) * m(2, 2) + m(1, 0) * m(2, 1) * m(0, 2) + m(2, 0) * m(0, 1) * m(1, 2) -
                     m(0, 0) * m(2, 1) * m(1, 2) - m(1, 0) * m(0, 1) * m(2, 2) - m(2, 0) * m(1, 1) * m(0, 2);
  if (std::fabs(det) < std::numeric_limits<double>::epsilon()) return false;
  r(0, 0) = (m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2)) / det;
  r(1, 0) = (m(1, 2) * m(2, 0) - m(2, 2) * m(1, 0)) / det;
  r(2, 0) = (m(1, 0) * m(2, 1) - m(2, 0) * m(1, 1)) / det;
  r(0, 1) = (m(2, 1) * m(0, 2) - m(0, 1) * m(2, 2)) / det;
  r(1, 1) = (m(2, 2) * m(0, 0) - m(0, 2) * m(2, 0)) / det;
  r(2, 1) = (m(2, 0) * m(0, 1) - m(0, 0) * m(2, 1)) / det;
  r(0, 2) = (m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2)) / det;
  r(1, 2) = (m(0, 2) * m(1, 0) - m(1, 2) * m(0, 0)) / det;
  r(2, 2) = (m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1)) / det;
  return true;
}
// Inverse of the matrix whose columns are a, b, c.
bool basis(const Vec3& a, const Vec3& b, const Vec3& c, Mat3& inv) {
  Mat3 m;
  m.col(0) = a;
  m.col(1) = b;
  m.col(2) = c;
  return invert3(m, inv);
}
Vec3 mul(const Mat3& m, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = m(i, 0) * v[0] + m(i, 1) * v[1] + m(i, 2) * v[2];
  return r;
}
Vec3 cross3(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
}  // namespace

void MeshBarycentricMapperEngine::do_update() {
  if (state() != ComponentState::valid || !topology) return;
  const std::vector<Vec3>& in = input_positions.get();
  const std::vector<Vec3>& out = mapped_positions.get();
  const bool interp = compute_linear_interpolation.get();
  std::vector<Vec3> bary(out.size(), Vec3::Zero());
  std::vector<unsigned> table(out.size(), 0);
  std::vector<std::vector<unsigned>> iidx(interp ? out.size() : 0);
  std::vector<std::vector<double>> ival(interp ? out.size() : 0);
  auto publish = [&] {
    barycentric_positions.set(std::move(bary));
    table_elements.set(std::move(table));
    if (interp) {
      std::vector<double> flat;
      for (const auto& v : ival) flat.insert(flat.end(), v.begin(), v.end());
      interpolation_indices.set(std::move(iidx));
      interpolation_values.set(std::move(flat));
    }
  };
  const MeshTopologyBase& topo = *topology;
  const std::vector<Tetra>& tets = topo.tetrahedra();
  const std::vector<Hexa>& cubes = topo.hexahedra();
  const std::vector<Triangle>& tris = topo.triangles();
  const std::vector<Quad>& quads = topo.quads();
  auto check = [&](const auto& elems) {
    for (const auto& e : elems)
      for (unsigned v : e)
        if (v >= in.size()) return false;
    return true;
  };
  if (!check(tets) || !check(cubes) || !check(tris) || !check(quads) || !check(topo.edges())) {
    msg_error("the topology refers to points beyond the " + std::to_string(in.size()) + " inputPositions");
    publish();
    return;
  }
  bool singular = false;
  if (tets.empty() && cubes.empty()) {
    if (tris.empty() && quads.empty()) {
      const std::vector<Edge>& edges = topo.edges();
      if (edges.empty()) {
        publish();
        return;
      }
      // SOFA finds the edge, then reports mapping into lines as not implemented.
      if (!out.empty()) msg_error("mapping points into edges is not implemented (as in SOFA)");
      publish();
      return;
    }
    const std::size_t c0 = tris.size();
    std::vector<Mat3> bases(tris.size() + quads.size(), Mat3::Zero());
    std::vector<Vec3> centers(tris.size() + quads.size(), Vec3::Zero());
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const Vec3 a = in[tris[t][1]] - in[tris[t][0]], b = in[tris[t][2]] - in[tris[t][0]];
      singular |= !basis(a, b, cross3(a, b), bases[t]);
      centers[t] = (in[tris[t][0]] + in[tris[t][1]] + in[tris[t][2]]) / 3;
    }
    for (std::size_t c = 0; c < quads.size(); ++c) {
      const Vec3 a = in[quads[c][1]] - in[quads[c][0]], b = in[quads[c][3]] - in[quads[c][0]];
      singular |= !basis(a, b, cross3(a, b), bases[c0 + c]);
      centers[c0 + c] = (in[quads[c][0]] + in[quads[c][1]] + in[quads[c][2]] + in[quads[c][3]]) * 0.25;
    }
    bool in_quad = false;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Vec3& pos = out[i];
      Vec3 coefs = Vec3::Zero();
      long index = -1;
      double distance = 1e10;
      for (std::size_t t = 0; t < tris.size(); ++t) {
        const Vec3 v = mul(bases[t], pos - in[tris[t][0]]);
        double d = std::max(std::max(-v[0], -v[1]), std::max(std::fabs(v[2]) - 0.01, v[0] + v[1] - 1));
        if (d > 0) d = (pos - centers[t]).squaredNorm();
        if (d < distance) {
          coefs = v;
          distance = d;
          index = static_cast<long>(t);
        }
      }
      for (std::size_t c = 0; c < quads.size(); ++c) {
        const Vec3 v = mul(bases[c0 + c], pos - in[quads[c][0]]);
        double d = std::max(std::max(-v[0], -v[1]),
                            std::max(std::max(v[1] - 1, v[0] - 1), std::max(v[2] - 0.01, -v[2] - 0.01)));
        if (d > 0) d = (pos - centers[c0 + c]).squaredNorm();
        if (d < distance) {
          coefs = v;
          distance = d;
          index = static_cast<long>(c0 + c);
        }
      }
      if (index < 0) continue;
      if (static_cast<std::size_t>(index) >= c0) {
        in_quad = true;
        continue;
      }
      table[i] = static_cast<unsigned>(index);
      bary[i] = Vec3(coefs[0], coefs[1], 0);
      if (interp) {
        const Triangle& t = tris[static_cast<std::size_t>(index)];
        iidx[i] = {t[0], t[1], t[2]};
        ival[i] = {1.0 - (coefs[0] - coefs[1]), coefs[0], coefs[1]};
      }
    }
    if (in_quad) msg_error("mapping points into quads is not implemented (as in SOFA)");
  } else {
    const std::size_t c0 = tets.size();
    std::vector<Mat3> bases(tets.size() + cubes.size(), Mat3::Zero());
    std::vector<Vec3> centers(tets.size() + cubes.size(), Vec3::Zero());
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const Tetra& e = tets[t];
      singular |= !basis(in[e[1]] - in[e[0]], in[e[2]] - in[e[0]], in[e[3]] - in[e[0]], bases[t]);
      centers[t] = (in[e[0]] + in[e[1]] + in[e[2]] + in[e[3]]) * 0.25;
    }
    for (std::size_t c = 0; c < cubes.size(); ++c) {
      const Hexa& h = cubes[c];
      singular |= !basis(in[h[1]] - in[h[0]], in[h[3]] - in[h[0]], in[h[4]] - in[h[0]], bases[c0 + c]);
      Vec3 s = in[h[0]];
      for (int k = 1; k < 8; ++k) s = s + in[h[k]];
      centers[c0 + c] = s * 0.125;
    }
    bool in_cube = false;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Vec3& pos = out[i];
      Vec3 coefs = Vec3::Zero();
      long index = -1;
      double distance = 1e10;
      for (std::size_t t = 0; t < tets.size(); ++t) {
        const Vec3 v = mul(bases[t], pos - in[tets[t][0]]);
        double d = std::max(std::max(-v[0], -v[1]), std::max(-v[2], v[0] + v[1] + v[2] - 1));
        if (d > 0) d = (pos - centers[t]).squaredNorm();
        if (d < distance) {
          coefs = v;
          distance = d;
          index = static_cast<long>(t);
        }
      }
      for (std::size_t c = 0; c < cubes.size(); ++c) {
        const Vec3 v = mul(bases[c0 + c], pos - in[cubes[c][0]]);
        double d = std::max(std::max(-v[0], -v[1]), std::max(std::max(-v[2], v[0] - 1), std::max(v[1] - 1, v[2] - 1)));
        if (d > 0) d = (pos - centers[c0 + c]).squaredNorm();
        if (d < distance) {
          coefs = v;
          distance = d;
          index = static_cast<long>(c0 + c);
        }
      }
      if (index < 0) continue;
      if (static_cast<std::size_t>(index) >= c0) {
        in_cube = true;
        continue;
      }
      table[i] = static_cast<unsigned>(index);
      bary[i] = coefs;
      if (interp) {
        const Tetra& t = tets[static_cast<std::size_t>(index)];
        iidx[i] = {t[0], t[1], t[2], t[3]};
        ival[i] = {1.0 - (coefs[0] - coefs[1] - coefs[2]), coefs[0], coefs[1], coefs[2]};
      }
    }
    if (in_cube) msg_error("mapping points into hexahedra is not implemented (as in SOFA)");
  }
  if (singular) msg_warning("a degenerate element has no barycentric frame (its points get zero coordinates)");
  publish();
}

void register_mesh_barycentric_mapper_engine(Registry& r) {
  ComponentInfo info;
  info.name = "MeshBarycentricMapperEngine";
  info.category = "Engine/Generate";
  info.description = "the element holding each point and the point's barycentric coordinates in it";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<MeshBarycentricMapperEngine>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
