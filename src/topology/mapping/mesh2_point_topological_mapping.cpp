#include "topology/mapping/mesh2_point_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

void Mesh2PointTopologicalMapping::init() {
  if (!check_links(false, ElementType::point, ElementType::point)) return;
  const MeshTopologyBase& in = *input;
  MeshContainer& out = *output;
  // Copies: the output may be read while it is rebuilt.
  const std::size_t n_in = in.nb_points();
  const std::vector<Edge> edges = in.edges();
  const std::vector<Triangle> tris = in.triangles();
  const std::vector<Quad> quads = in.quads();
  const std::vector<Tetra> tets = in.tetrahedra();
  const std::vector<Hexa> hexas = in.hexahedra();
  out.clear_topology();
  point_source_.clear();

  // With a point modifier in the output node, points are only counted (no coordinates).
  bool has_modifier = false;
  if (Node* n = out.node())
    for (const auto& o : n->objects()) has_modifier = has_modifier || dynamic_cast<PointSetTopologyModifier*>(o.get());

  const auto& pb = point_bary_coords.get();
  bool copy_e = copy_edges.value(), copy_t = copy_triangles.value(), copy_te = copy_tetrahedra.value();
  for (auto [flag, what] : {std::pair{&copy_e, "copyEdges"}, {&copy_t, "copyTriangles"}, {&copy_te, "copyTetrahedra"}})
    if (*flag && pb.empty()) {
      msg_error(std::string(what) + " requires at least one item in pointBaryCoords");
      *flag = false;
    }

  std::vector<Vec3> positions;
  std::size_t count = 0;
  auto add_point = [&](const Vec3& p, int kind, std::size_t i) {
    if (!has_modifier) positions.push_back(p);
    ++count;
    point_source_.push_back({kind, static_cast<unsigned>(i)});
  };
  auto P = [&](unsigned i) { return in.point(i); };

  std::vector<unsigned> first_of_point(n_in, 0);
  if (!pb.empty())
    for (std::size_t i = 0; i < n_in; ++i) {
      first_of_point[i] = static_cast<unsigned>(count);
      const Vec3 p = P(static_cast<unsigned>(i));
      for (const Vec3& b : pb) add_point(Vec3(p[0] + b[0], p[1] + b[1], p[2] + b[2]), 0, i);
    }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Vec3 p0 = P(edges[i][0]), p1 = P(edges[i][1]);
    for (const Vec3& b : edge_bary_coords.get()) {
      const double fx = b[0];
      add_point(p0 * (1 - fx) + p1 * fx, 1, i);
    }
  }
  if (copy_e) {
    auto& e = out.edges_f.edit();
    for (const Edge& ed : edges) e.push_back({first_of_point[ed[0]], first_of_point[ed[1]]});
  }
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Vec3 p0 = P(tris[i][0]), p1 = P(tris[i][1]), p2 = P(tris[i][2]);
    for (const Vec3& b : triangle_bary_coords.get()) {
      const double fx = b[0], fy = b[1];
      add_point(p0 * (1 - fx - fy) + p1 * fx + p2 * fy, 2, i);
    }
  }
  if (copy_t) {
    auto& t = out.triangles_f.edit();
    for (const Triangle& tr : tris) t.push_back({first_of_point[tr[0]], first_of_point[tr[1]], first_of_point[tr[2]]});
  }
  for (std::size_t i = 0; i < quads.size(); ++i) {
    const Quad& q = quads[i];
    for (const Vec3& b : quad_bary_coords.get()) {
      const double fx = b[0], fy = b[1];
      // SOFA pairs p2 with (1-fx)·fy and p3 with fx·fy.
      add_point(P(q[0]) * ((1 - fx) * (1 - fy)) + P(q[1]) * ((fx) * (1 - fy)) + P(q[2]) * ((1 - fx) * (fy)) +
                    P(q[3]) * ((fx) * (fy)),
                3, i);
    }
  }
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Vec3 p0 = P(tets[i][0]), p1 = P(tets[i][1]), p2 = P(tets[i][2]), p3 = P(tets[i][3]);
    for (const Vec3& b : tetra_bary_coords.get()) {
      const double fx = b[0], fy = b[1], fz = b[2];
      add_point(p0 * (1 - fx - fy - fz) + p1 * fx + p2 * fy + p3 * fz, 4, i);
    }
  }
  if (copy_te) {
    auto& t = out.tetrahedra_f.edit();
    for (const Tetra& te : tets)
      t.push_back({first_of_point[te[0]], first_of_point[te[1]], first_of_point[te[2]], first_of_point[te[3]]});
  }
  for (std::size_t i = 0; i < hexas.size(); ++i) {
    const Hexa& h = hexas[i];
    for (const Vec3& b : hexa_bary_coords.get()) {
      const double fx = b[0], fy = b[1], fz = b[2];
      add_point(P(h[0]) * ((1 - fx) * (1 - fy) * (1 - fz)) + P(h[1]) * ((fx) * (1 - fy) * (1 - fz)) +
                    P(h[3]) * ((1 - fx) * (fy) * (1 - fz)) + P(h[2]) * ((fx) * (fy) * (1 - fz)) +
                    P(h[4]) * ((1 - fx) * (1 - fy) * (fz)) + P(h[5]) * ((fx) * (1 - fy) * (fz)) +
                    P(h[7]) * ((1 - fx) * (fy) * (fz)) + P(h[6]) * ((fx) * (fy) * (fz)),
                5, i);
    }
  }
  if (!has_modifier) out.position.set(std::move(positions));
  out.set_nb_points(count);
}

void register_mesh2_point_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Mesh2PointTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "This class maps any mesh primitive (point, edge, triangle...) into a point using a relative "
                     "position from the primitive";
  info.create = creator<Mesh2PointTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
