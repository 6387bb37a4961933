#include "topology/mesh_topology.h"

#include <algorithm>
#include <functional>
#include <map>

#include "core/engine.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "io/mesh_readers.h"

namespace sinew {

// ---------------------------------------------------------------- derivations

namespace topo {

namespace {
Edge sorted_edge(unsigned a, unsigned b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Rotates v left until v[0] is the smallest entry (SOFA's "while (v0 > any) rotate").
template <std::size_t N>
void rotate_smallest_first(std::array<unsigned, N>& v) {
  auto greater_than_some = [&] {
    for (std::size_t k = 1; k < N; ++k)
      if (v[0] > v[k]) return true;
    return false;
  };
  while (greater_than_some()) std::rotate(v.begin(), v.begin() + 1, v.end());
}
}  // namespace

std::vector<Edge> edges_of_volumes(const std::vector<Tetra>& tetras, const std::vector<Hexa>& hexas) {
  std::vector<Edge> out;
  std::map<Edge, unsigned> seen;
  auto add = [&](unsigned a, unsigned b) {
    const Edge e = sorted_edge(a, b);
    if (seen.emplace(e, static_cast<unsigned>(out.size())).second) out.push_back(e);
  };
  for (const Tetra& t : tetras)
    for (const auto& le : kEdgesInTetra) add(t[le[0]], t[le[1]]);
  for (const Hexa& h : hexas)
    for (const auto& le : kEdgesInHexa) add(h[le[0]], h[le[1]]);
  return out;
}

std::vector<Edge> edges_of_surfaces(const std::vector<Triangle>& triangles, const std::vector<Quad>& quads) {
  std::vector<Edge> out;
  std::map<Edge, unsigned> seen;
  for (const Triangle& t : triangles)
    for (unsigned j = 0; j < 3; ++j) {
      const unsigned a = t[(j + 1) % 3], b = t[(j + 2) % 3];
      if (seen.emplace(sorted_edge(a, b), static_cast<unsigned>(out.size())).second) out.push_back({a, b});
    }
  for (const Quad& q : quads)
    for (unsigned j = 0; j < 4; ++j) {
      const Edge e = sorted_edge(q[(j + 1) % 4], q[(j + 2) % 4]);
      if (seen.emplace(e, static_cast<unsigned>(out.size())).second) out.push_back(e);
    }
  return out;
}

std::vector<Triangle> triangles_of_tetrahedra(const std::vector<Tetra>& tetras, bool skip_same) {
  std::vector<Triangle> out;
  std::map<Triangle, unsigned> seen;
  for (const Tetra& t : tetras)
    for (const auto& f : kTrianglesInTetra) {
      Triangle v{t[f[0]], t[f[1]], t[f[2]]};
      rotate_smallest_first(v);
      if (seen.count(Triangle{v[0], v[2], v[1]})) continue;  // reverse orientation exists
      if (skip_same && seen.count(v)) continue;                 // duplicate face (SOFA reports an error)
      seen[v] = static_cast<unsigned>(out.size());
      out.push_back(v);
    }
  return out;
}

std::vector<Quad> quads_of_hexahedra(const std::vector<Hexa>& hexas) {
  std::vector<Quad> out;
  std::map<Quad, unsigned> seen;
  for (const Hexa& h : hexas)
    for (const auto& f : kQuadsInHexa) {
      Quad v{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
      rotate_smallest_first(v);
      if (seen.count(Quad{v[0], v[3], v[2], v[1]})) continue;
      const auto idx = static_cast<unsigned>(out.size());
      seen[Quad{v[0], v[3], v[2], v[1]}] = idx;
      seen[v] = idx;
      out.push_back(v);
    }
  return out;
}

}  // namespace topo

// ---------------------------------------------------------------- neighbourhood cache

struct MeshContainer::Cache {
  std::uint64_t versions[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t nb_points = 0;
  bool has_eav = false, has_tav = false, has_tae = false, has_qav = false, has_qae = false;
  bool has_teav = false, has_teae = false, has_teat = false, has_hav = false, has_hae = false, has_haq = false;
  bool has_eit = false, has_eiq = false, has_eite = false, has_tite = false, has_eih = false, has_qih = false;
  std::vector<IndexList> eav, tav, tae, qav, qae, teav, teae, teat, hav, hae, haq;
  std::vector<std::array<unsigned, 3>> eit;
  std::vector<std::array<unsigned, 4>> eiq;
  std::vector<std::array<unsigned, 6>> eite;
  std::vector<std::array<unsigned, 4>> tite;
  std::vector<std::array<unsigned, 12>> eih;
  std::vector<std::array<unsigned, 6>> qih;
};

MeshContainer::MeshContainer() {
  position.add_alias("points");
  edges_f.add_alias("lines");
  tetrahedra_f.add_alias("tetras");
  hexahedra_f.add_alias("hexas");
  filename.add_alias("fileTopology");
  filename.set_file(true);
  filename.set_autolink(false);
}

MeshContainer::~MeshContainer() = default;

void MeshContainer::ensure() const {
  if (generated_) return;
  generated_ = true;
  const_cast<MeshContainer*>(this)->generate();
}

void MeshContainer::init() {
  ensure();
  if (!filename.value().empty()) load_file(filename.value());
}

bool MeshContainer::load_file(const std::string& file) {
  // SOFA's BaseMeshTopology::load with its MeshTopologyLoader: the container is cleared, then
  // receives the file's points and elements (OBJ faces: 2 vertices → edge, 4 → quad, else a
  // triangle fan).
  auto ends_with = [&](const char* suffix) {
    const std::string sx(suffix);
    return file.size() > sx.size() && file.compare(file.size() - sx.size(), sx.size(), sx) == 0;
  };
  std::string err;
  std::optional<io::MeshData> mesh;
  if (ends_with(".obj")) mesh = io::read_obj(file, &err);
  else if (ends_with(".msh")) mesh = io::read_gmsh(file, &err);
  else if (ends_with(".vtk") || ends_with(".vtu")) mesh = io::read_vtk(file, &err);
  else err = "this file format is not supported";
  if (!mesh) {
    msg_error("Unable to load Mesh " + quote_value(file) + ": " + err);
    set_state(ComponentState::invalid);
    return false;
  }
  clear_topology();
  if (ends_with(".obj")) {
    position.set(mesh->positions_definition.empty() ? mesh->positions : mesh->positions_definition);
    auto& edges = edges_f.edit();
    auto& tris = triangles_f.edit();
    auto& quads = quads_f.edit();
    for (const auto& f : mesh->face_positions) {
      std::vector<unsigned> v;
      for (int i : f)
        if (i >= 0) v.push_back(static_cast<unsigned>(i));
      if (v.size() == 2) edges.push_back(v[0] < v[1] ? Edge{v[0], v[1]} : Edge{v[1], v[0]});
      else if (v.size() == 4) quads.push_back({v[0], v[1], v[2], v[3]});
      else
        for (std::size_t j = 2; j < v.size(); ++j) tris.push_back({v[0], v[j - 1], v[j]});
    }
  } else {
    position.set(mesh->positions);
    edges_f.set(mesh->edges);
    triangles_f.set(mesh->triangles);
    quads_f.set(mesh->quads);
    tetrahedra_f.set(mesh->tetrahedra);
    hexahedra_f.set(mesh->hexahedra);
  }
  set_nb_points(position.value().size());
  return true;
}

std::uint64_t MeshContainer::elements_version(Elements e) const {
  // Read through the accessor first: a list derived or pulled on read moves its version then.
  switch (e) {
    case Elements::edges: return edges(), edges_f.version();
    case Elements::triangles: return triangles(), triangles_f.version();
    case Elements::quads: return quads(), quads_f.version();
    case Elements::tetrahedra: return tetrahedra(), tetrahedra_f.version();
    case Elements::hexahedra: return hexahedra(), hexahedra_f.version();
  }
  return 0;
}

std::size_t MeshContainer::nb_points() const {
  ensure();
  const auto& p = position.get();
  std::size_t n = p.size();
  if (n == 0) {
    // Without coordinates: one past the largest index used by any element.
    n = std::max({topo::count_points(edges_f.get()), topo::count_points(triangles_f.get()),
                  topo::count_points(quads_f.get()), topo::count_points(tetrahedra_f.get()),
                  topo::count_points(hexahedra_f.get())});
  }
  return std::max(n, nb_points_hint_);
}

bool MeshContainer::has_positions() const {
  ensure();
  return !position.get().empty();
}

Vec3 MeshContainer::point(std::size_t i) const {
  ensure();
  const auto& p = position.get();
  return i < p.size() ? p[i] : Vec3::Zero();
}

bool MeshContainer::check_indices(std::size_t n) const {
  bool ok = true;
  auto scan = [&](const auto& list, const char* what) {
    for (std::size_t e = 0; e < list.size() && ok; ++e)
      for (unsigned v : list[e])
        if (v >= n) {
          msg_warning(std::string(what) + " " + std::to_string(e) + " uses point " + std::to_string(v) +
                      " but the topology has " + std::to_string(n) + " points");
          ok = false;
          break;
        }
  };
  scan(edges_f.get(), "edge");
  scan(triangles_f.get(), "triangle");
  scan(quads_f.get(), "quad");
  scan(tetrahedra_f.get(), "tetrahedron");
  scan(hexahedra_f.get(), "hexahedron");
  return ok;
}

void MeshContainer::clear_topology() {
  nb_points_hint_ = 0;
  position.edit().clear();
  edges_f.edit().clear();
  triangles_f.edit().clear();
  quads_f.edit().clear();
  tetrahedra_f.edit().clear();
  hexahedra_f.edit().clear();
}

MeshContainer::Cache& MeshContainer::cache() const {
  if (!cache_) cache_ = std::make_unique<Cache>();
  // Reading the lists pulls links and lazy derivations before versions are compared.
  edges();
  triangles();
  quads();
  tetrahedra();
  hexahedra();
  position.get();
  const std::uint64_t v[8] = {edges_f.version(),      triangles_f.version(), quads_f.version(),
                              tetrahedra_f.version(), hexahedra_f.version(), position.version(),
                              static_cast<std::uint64_t>(nb_points_hint_), points_stamp()};
  if (!std::equal(v, v + 8, cache_->versions)) {
    cache_ = std::make_unique<Cache>();
    std::copy(v, v + 8, cache_->versions);
    cache_->nb_points = nb_points();
  }
  return *cache_;
}

namespace {
// "Around vertex" shells: element indices in increasing order, sized to cover every index.
template <class List>
void build_around_vertex(const List& list, std::size_t nb_points, std::vector<std::vector<unsigned>>& out) {
  out.assign(std::max(nb_points, topo::count_points(list)), {});
  for (std::size_t i = 0; i < list.size(); ++i)
    for (unsigned v : list[i]) out[v].push_back(static_cast<unsigned>(i));
}

// Elements holding all of `vs` (sorted intersection of the vertex shells).
unsigned find_common(const std::vector<std::vector<unsigned>>& shells, std::initializer_list<unsigned> vs) {
  std::vector<unsigned> acc;
  bool first = true;
  for (unsigned v : vs) {
    if (v >= shells.size()) return MeshTopologyBase::kInvalidIndex;
    if (first) {
      acc = shells[v];
      first = false;
      continue;
    }
    std::vector<unsigned> next;
    std::set_intersection(acc.begin(), acc.end(), shells[v].begin(), shells[v].end(), std::back_inserter(next));
    acc.swap(next);
  }
  return acc.empty() ? MeshTopologyBase::kInvalidIndex : acc.front();
}
}  // namespace

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::edges_around_vertex() const {
  Cache& c = cache();
  if (!c.has_eav) {
    c.has_eav = true;
    build_around_vertex(edges_f.value(), c.nb_points, c.eav);
  }
  return c.eav;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::triangles_around_vertex() const {
  Cache& c = cache();
  if (!c.has_tav) {
    c.has_tav = true;
    build_around_vertex(triangles_f.value(), c.nb_points, c.tav);
  }
  return c.tav;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::quads_around_vertex() const {
  Cache& c = cache();
  if (!c.has_qav) {
    c.has_qav = true;
    build_around_vertex(quads_f.value(), c.nb_points, c.qav);
  }
  return c.qav;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::tetrahedra_around_vertex() const {
  Cache& c = cache();
  if (!c.has_teav) {
    c.has_teav = true;
    build_around_vertex(tetrahedra_f.value(), c.nb_points, c.teav);
  }
  return c.teav;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::hexahedra_around_vertex() const {
  Cache& c = cache();
  if (!c.has_hav) {
    c.has_hav = true;
    build_around_vertex(hexahedra_f.value(), c.nb_points, c.hav);
  }
  return c.hav;
}

unsigned MeshContainer::edge_index(unsigned a, unsigned b) const {
  const auto& eav = edges_around_vertex();
  if (a >= eav.size()) return kInvalidIndex;
  const auto& edges = edges_f.value();
  for (unsigned e : eav[a])
    if (edges[e][0] == b || edges[e][1] == b) return e;
  return kInvalidIndex;
}

unsigned MeshContainer::triangle_index(unsigned a, unsigned b, unsigned c) const {
  return find_common(triangles_around_vertex(), {a, b, c});
}

unsigned MeshContainer::quad_index(unsigned a, unsigned b, unsigned c, unsigned d) const {
  return find_common(quads_around_vertex(), {a, b, c, d});
}

const std::vector<std::array<unsigned, 3>>& MeshContainer::edges_in_triangle() const {
  Cache& c = cache();
  if (!c.has_eit) {
    c.has_eit = true;
    const auto& tris = triangles_f.value();
    c.eit.resize(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i)
      for (unsigned j = 0; j < 3; ++j) {
        c.eit[i][j] = edge_index(tris[i][(j + 1) % 3], tris[i][(j + 2) % 3]);
        if (c.eit[i][j] == kInvalidIndex)
          msg_warning("edge " + std::to_string(j) + " of triangle " + std::to_string(i) +
                      " is missing from the edge list");
      }
  }
  return c.eit;
}

const std::vector<std::array<unsigned, 4>>& MeshContainer::edges_in_quad() const {
  Cache& c = cache();
  if (!c.has_eiq) {
    c.has_eiq = true;
    const auto& quads = quads_f.value();
    c.eiq.resize(quads.size());
    for (std::size_t i = 0; i < quads.size(); ++i)
      for (unsigned j = 0; j < 4; ++j) {
        c.eiq[i][j] = edge_index(quads[i][(j + 1) % 4], quads[i][(j + 2) % 4]);
        if (c.eiq[i][j] == kInvalidIndex)
          msg_warning("edge " + std::to_string(j) + " of quad " + std::to_string(i) + " is missing from the edge list");
      }
  }
  return c.eiq;
}

const std::vector<std::array<unsigned, 6>>& MeshContainer::edges_in_tetrahedron() const {
  Cache& c = cache();
  if (!c.has_eite) {
    c.has_eite = true;
    const auto& tets = tetrahedra_f.value();
    c.eite.resize(tets.size());
    for (std::size_t i = 0; i < tets.size(); ++i)
      for (unsigned j = 0; j < 6; ++j) {
        c.eite[i][j] = edge_index(tets[i][topo::kEdgesInTetra[j][0]], tets[i][topo::kEdgesInTetra[j][1]]);
        if (c.eite[i][j] == kInvalidIndex)
          msg_warning("edge " + std::to_string(j) + " of tetrahedron " + std::to_string(i) +
                      " is missing from the edge list");
      }
  }
  return c.eite;
}

const std::vector<std::array<unsigned, 4>>& MeshContainer::triangles_in_tetrahedron() const {
  Cache& c = cache();
  if (!c.has_tite) {
    c.has_tite = true;
    const auto& tets = tetrahedra_f.value();
    c.tite.resize(tets.size());
    for (std::size_t i = 0; i < tets.size(); ++i)
      for (unsigned j = 0; j < 4; ++j) {
        const Tetra& t = tets[i];
        c.tite[i][j] = triangle_index(t[(j + 1) % 4], t[(j + 2) % 4], t[(j + 3) % 4]);
        if (c.tite[i][j] == kInvalidIndex)
          msg_warning("face " + std::to_string(j) + " of tetrahedron " + std::to_string(i) +
                      " is missing from the triangle list");
      }
  }
  return c.tite;
}

const std::vector<std::array<unsigned, 12>>& MeshContainer::edges_in_hexahedron() const {
  Cache& c = cache();
  if (!c.has_eih) {
    c.has_eih = true;
    const auto& hexas = hexahedra_f.value();
    c.eih.resize(hexas.size());
    for (std::size_t i = 0; i < hexas.size(); ++i)
      for (unsigned j = 0; j < 12; ++j) {
        c.eih[i][j] = edge_index(hexas[i][topo::kEdgesInHexa[j][0]], hexas[i][topo::kEdgesInHexa[j][1]]);
        if (c.eih[i][j] == kInvalidIndex)
          msg_warning("edge " + std::to_string(j) + " of hexahedron " + std::to_string(i) +
                      " is missing from the edge list");
      }
  }
  return c.eih;
}

const std::vector<std::array<unsigned, 6>>& MeshContainer::quads_in_hexahedron() const {
  Cache& c = cache();
  if (!c.has_qih) {
    c.has_qih = true;
    const auto& hexas = hexahedra_f.value();
    c.qih.resize(hexas.size());
    for (std::size_t i = 0; i < hexas.size(); ++i)
      for (unsigned j = 0; j < 6; ++j) {
        const auto& f = topo::kQuadsInHexa[j];
        const Hexa& h = hexas[i];
        c.qih[i][j] = quad_index(h[f[0]], h[f[1]], h[f[2]], h[f[3]]);
        if (c.qih[i][j] == kInvalidIndex)
          msg_warning("face " + std::to_string(j) + " of hexahedron " + std::to_string(i) +
                      " is missing from the quad list");
      }
  }
  return c.qih;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::triangles_around_edge() const {
  Cache& c = cache();
  if (!c.has_tae) {
    c.has_tae = true;
    const auto& eit = edges_in_triangle();
    const auto& tris = triangles_f.value();
    const auto& edges = edges_f.value();
    c.tae.assign(edges.size(), {});
    for (std::size_t i = 0; i < tris.size(); ++i)
      for (unsigned j = 0; j < 3; ++j) {
        const unsigned e = eit[i][j];
        if (e == kInvalidIndex) continue;
        auto& shell = c.tae[e];
        // A triangle running along the edge's direction is put first.
        if (edges[e][0] == tris[i][(j + 1) % 3]) shell.insert(shell.begin(), static_cast<unsigned>(i));
        else shell.push_back(static_cast<unsigned>(i));
      }
  }
  return c.tae;
}

namespace {
template <std::size_t N>
void build_around(const std::vector<std::array<unsigned, N>>& in, std::size_t n,
                  std::vector<std::vector<unsigned>>& out) {
  out.assign(n, {});
  for (std::size_t i = 0; i < in.size(); ++i)
    for (unsigned e : in[i])
      if (e < n) out[e].push_back(static_cast<unsigned>(i));
}
}  // namespace

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::quads_around_edge() const {
  Cache& c = cache();
  if (!c.has_qae) {
    c.has_qae = true;
    build_around(edges_in_quad(), edges_f.value().size(), c.qae);
  }
  return c.qae;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::tetrahedra_around_edge() const {
  Cache& c = cache();
  if (!c.has_teae) {
    c.has_teae = true;
    build_around(edges_in_tetrahedron(), edges_f.value().size(), c.teae);
  }
  return c.teae;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::tetrahedra_around_triangle() const {
  Cache& c = cache();
  if (!c.has_teat) {
    c.has_teat = true;
    build_around(triangles_in_tetrahedron(), triangles_f.value().size(), c.teat);
  }
  return c.teat;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::hexahedra_around_edge() const {
  Cache& c = cache();
  if (!c.has_hae) {
    c.has_hae = true;
    build_around(edges_in_hexahedron(), edges_f.value().size(), c.hae);
  }
  return c.hae;
}

const std::vector<MeshTopologyBase::IndexList>& MeshContainer::hexahedra_around_quad() const {
  Cache& c = cache();
  if (!c.has_haq) {
    c.has_haq = true;
    build_around(quads_in_hexahedron(), quads_f.value().size(), c.haq);
  }
  return c.haq;
}

// ---------------------------------------------------------------- MeshTopology

namespace {
// A lazy list derivation: runs `fn` when one of its inputs changed and the output is read.
class ListUpdate final : public Engine {
 public:
  ListUpdate(std::vector<BaseField*> in, BaseField* out, std::function<void()> fn) : fn_(std::move(fn)) {
    for (BaseField* f : in) add_input(f);
    add_output(out);
  }

 protected:
  void do_update() override { fn_(); }

 private:
  std::function<void()> fn_;
};
}  // namespace

MeshTopology::MeshTopology() { uv.add_alias("texcoords"); }

MeshTopology::~MeshTopology() {
  edges_f.set_producer(nullptr);
  triangles_f.set_producer(nullptr);
  quads_f.set_producer(nullptr);
}

void MeshTopology::drop_updates() {
  edges_f.set_producer(nullptr);
  triangles_f.set_producer(nullptr);
  quads_f.set_producer(nullptr);
  edge_update_.reset();
  triangle_update_.reset();
  quad_update_.reset();
}

void MeshTopology::clear_topology() {
  drop_updates();
  MeshContainer::clear_topology();
  prisms.edit().clear();
  pyramids.edit().clear();
  uv.edit().clear();
}

void MeshTopology::init() {
  MeshContainer::init();
  // Drop the derivations of a previous init (a topological mapping re-initialises its output).
  drop_updates();

  const bool no_edges = edges_f.get().empty();
  const bool no_triangles = triangles_f.get().empty();
  const bool no_quads = quads_f.get().empty();
  const bool has_volume = !tetrahedra_f.get().empty() || !hexahedra_f.get().empty();
  const bool has_surface = !triangles_f.get().empty() || !quads_f.get().empty();

  if (no_edges) {
    if (edges_f.parent()) edges_f.set_parent(nullptr);
    auto derive = [this] {
      auto& out = edges_f.edit();
      if (!tetrahedra_f.get().empty() || !hexahedra_f.get().empty())
        out = topo::edges_of_volumes(tetrahedra_f.get(), hexahedra_f.get());
      else if (!triangles_f.get().empty() || !quads_f.get().empty())
        out = topo::edges_of_surfaces(triangles_f.get(), quads_f.get());
    };
    if (has_volume)
      edge_update_ = std::make_unique<ListUpdate>(std::vector<BaseField*>{&hexahedra_f, &tetrahedra_f}, &edges_f,
                                                  derive);
    else if (has_surface)
      edge_update_ = std::make_unique<ListUpdate>(std::vector<BaseField*>{&triangles_f, &quads_f}, &edges_f,
                                                  derive);
  }
  if (no_triangles) {
    if (triangles_f.parent()) triangles_f.set_parent(nullptr);
    triangle_update_ = std::make_unique<ListUpdate>(
        std::vector<BaseField*>{&tetrahedra_f}, &triangles_f,
        [this] { triangles_f.edit() = topo::triangles_of_tetrahedra(tetrahedra_f.get(), false); });
  }
  if (no_quads) {
    if (quads_f.parent()) quads_f.set_parent(nullptr);
    quad_update_ = std::make_unique<ListUpdate>(
        std::vector<BaseField*>{&hexahedra_f}, &quads_f,
        [this] { quads_f.edit() = topo::quads_of_hexahedra(hexahedra_f.get()); });
  }
  if (has_positions()) check_indices(position.get().size());
  if (compute_all_buffers.value()) {
    // Build every crossed buffer now (SOFA's computeCrossElementBuffers).
    if (!hexahedra().empty()) {
      hexahedra_around_vertex();
      if (!quads().empty()) hexahedra_around_quad();
      if (!edges().empty()) hexahedra_around_edge();
    }
    if (!tetrahedra().empty()) {
      tetrahedra_around_vertex();
      if (!triangles().empty()) tetrahedra_around_triangle();
      if (!edges().empty()) tetrahedra_around_edge();
    }
    if (!quads().empty()) {
      quads_around_vertex();
      if (!edges().empty()) quads_around_edge();
    }
    if (!triangles().empty()) {
      triangles_around_vertex();
      if (!edges().empty()) triangles_around_edge();
    }
    if (!edges().empty()) edges_around_vertex();
  }
}

void register_mesh_topology(Registry& r) {
  ComponentInfo info;
  info.name = "MeshTopology";
  info.category = "Topology";
  info.description = "Generic constant topology loaded from a mesh file.";
  info.create = creator<MeshTopology>();
  r.add(std::move(info));
}

const std::vector<Prism>& prisms_of(const MeshTopologyBase& t) {
  static const std::vector<Prism> none;
  const auto* m = dynamic_cast<const MeshTopology*>(&t);
  return m ? m->prisms.get() : none;
}

const std::vector<Pyramid>& pyramids_of(const MeshTopologyBase& t) {
  static const std::vector<Pyramid> none;
  const auto* m = dynamic_cast<const MeshTopology*>(&t);
  return m ? m->pyramids.get() : none;
}

}  // namespace sinew
