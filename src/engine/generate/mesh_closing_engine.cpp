#include "engine/generate/mesh_closing_engine.h"

#include <map>
#include <set>

#include "core/registry.h"

namespace sinew {

MeshClosingEngine::MeshClosingEngine() {
  add_input(&input_position);
  add_input(&input_triangles);
  add_input(&input_quads);
  for (BaseField* f : std::initializer_list<BaseField*>{&position, &triangles, &quads, &indices, &closing_position,
                                                        &closing_triangles})
    add_output(f);
}

void MeshClosingEngine::do_update() {
  const std::vector<Vec3>& x = input_position.get();
  const std::vector<Triangle>& tri = input_triangles.get();
  const std::vector<Quad>& qd = input_quads.get();
  std::vector<Vec3> opos = x;
  std::vector<Triangle> otri = tri;
  std::vector<std::vector<unsigned>> oind;
  std::vector<Vec3> clpos;
  std::vector<Triangle> cltri;
  quads.set(qd);

  auto publish = [&] {
    position.set(std::move(opos));
    triangles.set(std::move(otri));
    indices.set(std::move(oind));
    closing_position.set(std::move(clpos));
    closing_triangles.set(std::move(cltri));
  };
  for (const Triangle& t : tri)
    for (unsigned v : t)
      if (v >= x.size()) {
        msg_error("a triangle refers to vertex " + std::to_string(v) + ", beyond the " + std::to_string(x.size()) +
                  " input vertices: the mesh is not closed");
        publish();
        return;
      }
  for (const Quad& q : qd)
    for (unsigned v : q)
      if (v >= x.size()) {
        msg_error("a quad refers to vertex " + std::to_string(v) + ", beyond the " + std::to_string(x.size()) +
                  " input vertices: the mesh is not closed");
        publish();
        return;
      }

  // Oriented boundary edges: an edge cancels its reverse.
  std::set<std::pair<unsigned, unsigned>> border;
  auto add = [&](unsigned a, unsigned b) {
    auto it = border.find({b, a});
    if (it == border.end()) border.insert({a, b});
    else border.erase(it);
  };
  for (const Triangle& t : tri)
    for (int j = 0; j < 3; ++j) add(t[j == 0 ? 2 : j - 1], t[j]);
  for (const Quad& q : qd)
    for (int j = 0; j < 4; ++j) add(q[j == 0 ? 3 : j - 1], q[j]);
  if (border.empty()) {
    publish();
    return;
  }

  // Chain them into loops (SOFA's walk over an ordered map from start to end vertex).
  std::map<unsigned, unsigned> next;
  for (const auto& e : border) next[e.first] = e.second;
  auto it = next.begin();
  std::vector<std::vector<unsigned>> loops(1);
  loops.back().push_back(it->first);
  while (!next.empty()) {
    const unsigned i = it->second;
    loops.back().push_back(i);
    next.erase(it);
    if (!next.empty()) {
      if (i == loops.back().front()) loops.emplace_back();
      it = next.find(i);
      if (it == next.end()) {
        it = next.begin();
        loops.back().push_back(it->first);
      }
    }
  }

  for (const std::vector<unsigned>& loop : loops) {
    if (loop.size() <= 2) continue;
    std::vector<unsigned> ind;
    Vec3 centroid = Vec3::Zero();
    const auto u = [](std::size_t v) { return static_cast<unsigned>(v); };
    const std::size_t ic = clpos.size() + loop.size() - 1;
    for (std::size_t j = 0; j + 1 < loop.size(); ++j) {
      const unsigned p = loop[j];
      ind.push_back(p);
      clpos.push_back(x[p]);
      centroid += x[p];
      cltri.push_back({u(ic), u(clpos.size() - 1), u(j ? clpos.size() - 2 : ic - 1)});
      otri.push_back({u(opos.size()), p, j ? loop[j - 1] : loop[loop.size() - 2]});
    }
    centroid /= static_cast<double>(loop.size() - 1);
    clpos.push_back(centroid);
    ind.push_back(u(opos.size()));
    opos.push_back(centroid);
    oind.push_back(std::move(ind));
  }
  publish();
}

void register_mesh_closing_engine(Registry& r) {
  ComponentInfo info;
  info.name = "MeshClosingEngine";
  info.category = "Engine/Generate";
  info.description = "closes the holes of a surface mesh with a fan of triangles around each hole's centroid";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<MeshClosingEngine>(); };
  r.add(std::move(info));
}

}  // namespace sinew
