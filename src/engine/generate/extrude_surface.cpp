#include "engine/generate/extrude_surface.h"

#include <limits>
#include <map>

#include "core/registry.h"
#include "math/sofa_vec.h"

namespace sinew {

ExtrudeSurface::ExtrudeSurface()
    : surface_vertices(this, "surfaceVertices", FlatVec{}, "vertices of the surface", "Inputs", "length"),
      extrusion_vertices(this, "extrusionVertices", FlatVec{}, "vertices of the extrusion", "Outputs", "length") {
  add_input(&surface_triangles);
  add_input(&surface_vertices);
  add_input(&triangles);
  add_output(&extrusion_vertices);
  add_output(&extrusion_triangles);
}

namespace {
// SOFA's Vec::normalize: divided by the norm only when it exceeds the double epsilon.
Vec3 normalized_as_sofa(Vec3 v) {
  const double n = sofa_norm(v);
  if (n > std::numeric_limits<double>::epsilon()) v /= n;
  return v;
}
}  // namespace

void ExtrudeSurface::do_update() {
  const std::vector<unsigned>& patch = surface_triangles.get();
  const FlatVec& sv = surface_vertices.get();
  if (sv.size() <= 1 && patch.size() <= 1) return;  // SOFA leaves the outputs as they are
  if (sv.width != 3) {
    msg_error("surfaceVertices must be 3D points");
    return;
  }
  const std::vector<Triangle>& tris = triangles.get();
  for (unsigned id : patch) {
    if (id >= tris.size()) {
      msg_error("surfaceTriangles names triangle " + std::to_string(id) + " of " + std::to_string(tris.size()));
      return;
    }
    for (unsigned k : tris[id])
      if (k >= sv.size()) {
        msg_error("triangle " + std::to_string(id) + " names vertex " + std::to_string(k) + " of " +
                  std::to_string(sv.size()));
        return;
      }
  }
  auto point = [&](unsigned k) { return Vec3(sv.data[3 * k], sv.data[3 * k + 1], sv.data[3 * k + 2]); };

  // Vertex normals: the sum of the unit normals of the patch triangles around each vertex.
  std::map<unsigned, Vec3> normals;
  for (unsigned id : patch) {
    const Triangle& t = tris[id];
    const Vec3 n = normalized_as_sofa(sofa_cross(point(t[1]) - point(t[0]), point(t[2]) - point(t[0])));
    for (unsigned k : t) {
      auto [it, fresh] = normals.try_emplace(k, Vec3::Zero());
      it->second += n;
    }
  }
  for (auto& [k, n] : normals) n = normalized_as_sofa(n);

  std::vector<double> out;
  std::vector<Triangle> faces;
  std::map<unsigned, unsigned> first_of;           // surface vertex → its bottom copy (even index)
  std::map<std::array<unsigned, 2>, bool> border;  // edge → used once so far
  const double h = height_factor.get();
  for (unsigned id : patch) {
    const Triangle& t = tris[id];
    Triangle bottom, top;
    for (int i = 0; i < 3; ++i) {
      auto it = first_of.find(t[i]);
      if (it == first_of.end()) {
        const Vec3 p = point(t[i]);
        const Vec3 q = p + normals[t[i]] * h;
        out.insert(out.end(), {p[0], p[1], p[2], q[0], q[1], q[2]});
        const unsigned k = static_cast<unsigned>(out.size() / 3 - 2);
        it = first_of.emplace(t[i], k).first;
      }
      bottom[i] = it->second;
      top[i] = it->second + 1;
    }
    // An edge seen in either direction before is inner; SOFA's bookkeeping, kept as is.
    const std::array<unsigned, 2> e[3] = {{bottom[0], bottom[1]}, {bottom[0], bottom[2]}, {bottom[1], bottom[2]}};
    const std::array<unsigned, 2> ei[3] = {{bottom[1], bottom[0]}, {bottom[2], bottom[0]}, {bottom[2], bottom[1]}};
    for (int i = 0; i < 3; ++i) {
      if (!border.contains(e[i])) {
        if (!border.contains(ei[i]))
          border[e[i]] = true;
        else
          border[ei[i]] = false;
      } else {
        border[e[i]] = false;
      }
    }
    std::swap(bottom[1], bottom[2]);  // the bottom faces away from the top
    faces.push_back(bottom);
    faces.push_back(top);
  }
  for (const auto& [e, once] : border) {
    if (!once) continue;
    faces.push_back({e[0], e[1], e[0] + 1});
    faces.push_back({e[1] + 1, e[0] + 1, e[1]});
  }
  FlatVec v;
  v.width = 3;
  v.data = std::move(out);
  extrusion_vertices.set(std::move(v));
  extrusion_triangles.set(std::move(faces));
}

void register_extrude_surface(Registry& r) {
  ComponentInfo info;
  info.name = "ExtrudeSurface";
  info.category = "Engine/Generate";
  info.description = "a closed shell extruded from a patch of a triangle surface along its vertex normals";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<ExtrudeSurface>();
  r.add(std::move(info));
}

}  // namespace sinew
