#include "engine/select/mesh_sampler.h"

#include <limits>
#include <set>

#include "core/registry.h"

namespace sinew {

MeshSampler::MeshSampler() {
  add_input(&number);
  add_input(&position);
  add_input(&edges);
  add_input(&max_iter);
  add_output(&output_indices);
  add_output(&output_position);
}

namespace {
struct Sampler {
  const std::vector<Vec3>& x;
  const std::vector<std::vector<unsigned>>& ngb;  // empty: Euclidean
  bool geodesic;
  std::vector<unsigned> ind;
  std::vector<double> dist;
  std::vector<unsigned> voronoi;

  void distances() {
    const std::size_t n = x.size();
    dist.assign(n, std::numeric_limits<double>::max());
    voronoi.resize(n, 0);
    if (!geodesic) {
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < ind.size(); ++j) {
          const double d = (x[i] - x[ind[j]]).squaredNorm();
          if (d < dist[i]) {
            dist[i] = d;
            voronoi[i] = static_cast<unsigned>(j);
          }
        }
      return;
    }
    std::set<std::pair<double, unsigned>> q;
    for (std::size_t i = 0; i < ind.size(); ++i) {
      q.insert({0.0, ind[i]});
      dist[ind[i]] = 0;
      voronoi[ind[i]] = static_cast<unsigned>(i);
    }
    while (!q.empty()) {
      const unsigned v = q.begin()->second;
      q.erase(q.begin());
      for (unsigned v2 : ngb[v]) {
        const double d = dist[v] + (x[v] - x[v2]).norm();
        if (dist[v2] > d) {
          auto it = q.find({dist[v2], v2});
          if (it != q.end()) q.erase(it);
          voronoi[v2] = voronoi[v];
          dist[v2] = d;
          q.insert({d, v2});
        }
      }
    }
  }

  bool lloyd() {
    const std::size_t n = x.size(), ns = ind.size();
    std::vector<Vec3> center(ns, Vec3::Zero());
    std::vector<unsigned> count(ns, 0);
    for (std::size_t i = 0; i < n; ++i) {
      center[voronoi[i]] += x[i];
      ++count[voronoi[i]];
    }
    for (std::size_t i = 0; i < ns; ++i) center[i] /= static_cast<double>(count[i]);
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = (x[i] - center[voronoi[i]]).squaredNorm();
    std::vector<double> dmin(ns);
    for (std::size_t i = 0; i < ns; ++i) dmin[i] = d[ind[i]];
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i)
      if (d[i] < dmin[voronoi[i]]) {
        dmin[voronoi[i]] = d[i];
        ind[voronoi[i]] = static_cast<unsigned>(i);
        changed = true;
      }
    distances();
    return changed;
  }
};
}  // namespace

void MeshSampler::do_update() {
  const std::vector<Vec3>& x = position.get();
  const std::vector<Edge>& e = edges.get();
  std::vector<std::vector<unsigned>> ngb;
  if (!e.empty()) {
    ngb.resize(x.size());
    for (const Edge& ed : e) {
      if (ed[0] >= x.size() || ed[1] >= x.size()) {
        msg_error("an edge refers to a point beyond the " + std::to_string(x.size()) + " positions: no samples");
        output_indices.set({});
        output_position.set({});
        return;
      }
      ngb[ed[0]].push_back(ed[1]);
      ngb[ed[1]].push_back(ed[0]);
    }
  }
  if (x.empty()) {
    output_indices.set({});
    output_position.set({});
    return;
  }
  Sampler s{x, ngb, !e.empty(), {0u}, {}, {}};
  // Farthest point sampling from vertex 0.
  s.distances();
  const std::size_t nbc = std::min<std::size_t>(number.get(), x.size());
  while (s.ind.size() < nbc) {
    double dmax = 0;
    unsigned imax = 0;
    for (std::size_t i = 0; i < s.dist.size(); ++i)
      if (s.dist[i] > dmax) {
        dmax = s.dist[i];
        imax = static_cast<unsigned>(i);
      }
    if (dmax == 0) break;
    s.ind.push_back(imax);
    s.distances();
  }
  for (unsigned it = 0; it < max_iter.get(); ++it)
    if (!s.lloyd()) break;
  std::vector<Vec3> out;
  out.reserve(s.ind.size());
  for (unsigned i : s.ind) out.push_back(x[i]);
  output_indices.set(std::move(s.ind));
  output_position.set(std::move(out));
}

void register_mesh_sampler(Registry& r) {
  ComponentInfo info;
  info.name = "MeshSampler";
  info.category = "Engine/Select";
  info.description = "well-spread samples of a mesh's vertices (farthest point sampling and Lloyd relaxation)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<MeshSampler>(); };
  r.add(std::move(info));
}

}  // namespace sinew
