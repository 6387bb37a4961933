#include "engine/analyze/clustering_engine.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <utility>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

namespace {

double distance(const std::vector<double>& x, std::size_t a, const std::vector<double>& y, std::size_t b) {
  const double d0 = x[3 * a] - y[3 * b], d1 = x[3 * a + 1] - y[3 * b + 1], d2 = x[3 * a + 2] - y[3 * b + 2];
  return std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

}  // namespace

ClusteringEngine::ClusteringEngine(StateType type)
    : fixed_position(this, "fixedPosition", empty_coords(type), "Input positions of fixed (non mechanical) particles.",
                     "Inputs"),
      position(this, "position", empty_coords(type), "Input rest positions.", "Inputs") {
  in_file.set_file(true, /*required=*/false);
  add_input(&radius);
  add_input(&fixed_radius);
  add_input(&number);
  add_input(&fixed_position);
  add_input(&position);
  add_input(&in_file);
  add_output(&cluster);
}

void ClusteringEngine::init() {
  topo_ = node()->find_up<MeshTopologyBase>();
  for (const Field<double>* f : {&radius, &fixed_radius})
    if (!(std::isfinite(f->value()) && f->value() >= 0)) {
      msg_error(f->name() + " must be a finite distance >= 0 (got " + f->text() + ")");
      set_state(ComponentState::invalid);
      return;
    }
  set_dirty();
}

std::vector<ClusteringEngine::Index> ClusteringEngine::neighbours(Index v) const {
  // SOFA's getVerticesAroundVertex: the other end of each edge around v, in that list's order.
  std::vector<Index> out;
  const auto& around = topo_->edges_around_vertex();
  if (v >= around.size()) return out;
  const auto& edges = topo_->edges();
  for (unsigned e : around[v]) out.push_back(edges[e][0] == v ? edges[e][1] : edges[e][0]);
  return out;
}

void ClusteringEngine::do_update() {
  if (state() == ComponentState::invalid) return;
  if (load()) return;
  const std::vector<double>& x = position.get().data;
  const std::vector<double>& fixed = fixed_position.get().data;
  const std::size_t np = x.size() / 3, nf = fixed.size() / 3;
  const bool topological = topo_ && use_topo.value();
  if (topological && topo_->nb_points() < np) {
    msg_error("the topology has " + std::to_string(topo_->nb_points()) + " points, the positions " +
              std::to_string(np));
    cluster.set({});
    return;
  }
  std::vector<Index> centres, voronoi;
  if (number.value() == -1) {
    for (std::size_t i = 0; i < np; ++i) {
      centres.push_back(static_cast<Index>(i));
      voronoi.push_back(static_cast<Index>(i));
    }
  } else if (np > 0) {
    farthest_point_sampling(x, centres, voronoi);
  }
  std::vector<std::vector<unsigned>> clusters(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) clusters[i].push_back(centres[i]);
  const double r = radius.value();
  if (topological) {
    // SOFA's AddNeighborhoodFromNeighborhood: grow ring by ring from the centre, taking each
    // neighbour of the last ring that is in the centre's Voronoi cell (plus one ring) or closer
    // than the radius, until a ring adds nothing.
    for (std::size_t i = 0; i < centres.size(); ++i) {
      std::vector<unsigned>& c = clusters[i];
      std::vector<Index> last{centres[i]};
      const std::size_t p = c[0];
      bool inserted = true;
      while (inserted) {
        inserted = false;
        std::vector<Index> next;
        for (Index v : last)
          for (Index q : neighbours(v)) {
            if (q >= np) continue;
            if (voronoi[v] == i || distance(x, p, x, q) < r)
              if (std::find(c.begin(), c.end(), q) == c.end()) {
                c.push_back(q);
                next.push_back(q);
                inserted = true;
              }
          }
        last = std::move(next);
      }
    }
  } else {
    for (std::size_t j = 0; j < np; ++j) {
      bool inserted = false;
      for (std::size_t i = 0; i < centres.size(); ++i)
        if (j != centres[i] && distance(x, j, x, centres[i]) < r) {
          clusters[i].push_back(static_cast<unsigned>(j));
          inserted = true;
        }
      if (!inserted) {  // to the nearest centre: no point is left out
        double dmin = std::numeric_limits<double>::max();
        int imin = -1;
        for (std::size_t i = 0; i < centres.size(); ++i)
          if (j != centres[i]) {
            const double d = distance(x, j, x, centres[i]);
            if (d < dmin) {
              dmin = d;
              imin = static_cast<int>(i);
            }
          }
        if (imin != -1) clusters[static_cast<std::size_t>(imin)].push_back(static_cast<unsigned>(j));
      }
    }
    for (std::size_t j = 0; j < nf; ++j)
      for (std::size_t i = 0; i < centres.size(); ++i)
        if (distance(fixed, j, x, centres[i]) < fixed_radius.value())
          clusters[i].push_back(static_cast<unsigned>(j + np));
  }
  cluster.set(std::move(clusters));
  save();
}

void ClusteringEngine::farthest_point_sampling(const std::vector<double>& x, std::vector<Index>& centres,
                                               std::vector<Index>& voronoi) const {
  const std::size_t np = x.size() / 3;
  // As SOFA, a negative count other than -1 wraps to a huge one: every point.
  std::size_t nbc = static_cast<unsigned>(number.value());
  if (nbc > np) nbc = np;
  centres.assign(1, 0);
  voronoi.assign(np, 0);
  std::vector<double> distances(np, std::numeric_limits<double>::max());
  const bool topological = topo_ && use_topo.value();
  // Each new centre is the point farthest from the centres so far (distances only decrease).
  while (centres.size() < nbc) {
    if (topological) dijkstra(x, centres, distances, voronoi);
    else voronoi_of(x, centres, distances, voronoi);
    double dmax = 0;
    Index imax = 0;
    for (std::size_t i = 0; i < np; ++i)
      if (distances[i] > dmax) {
        dmax = distances[i];
        imax = static_cast<Index>(i);
      }
    if (dmax == 0) break;
    centres.push_back(imax);
  }
  if (topological) dijkstra(x, centres, distances, voronoi);
  else voronoi_of(x, centres, distances, voronoi);
}

void ClusteringEngine::dijkstra(const std::vector<double>& x, const std::vector<Index>& centres,
                                std::vector<double>& distances, std::vector<Index>& voronoi) const {
  // SOFA's priority queue: a set of (distance, point), a point's stale entry erased when it improves.
  std::set<std::pair<double, Index>> queue;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    queue.insert({0.0, centres[i]});
    distances[centres[i]] = 0;
    voronoi[centres[i]] = static_cast<Index>(i);
  }
  const std::size_t np = x.size() / 3;
  while (!queue.empty()) {
    const Index v = queue.begin()->second;
    queue.erase(queue.begin());
    for (Index v2 : neighbours(v)) {
      if (v2 >= np) continue;
      const double d = distances[v] + distance(x, v, x, v2);
      if (distances[v2] > d) {
        const auto it = queue.find({distances[v2], v2});
        if (it != queue.end()) queue.erase(it);
        voronoi[v2] = voronoi[v];
        distances[v2] = d;
        queue.insert({d, v2});
      }
    }
  }
}

void ClusteringEngine::voronoi_of(const std::vector<double>& x, const std::vector<Index>& centres,
                                  std::vector<double>& distances, std::vector<Index>& voronoi) {
  const std::size_t np = x.size() / 3;
  for (std::size_t i = 0; i < np; ++i)
    for (std::size_t j = 0; j < centres.size(); ++j) {
      const double d = distance(x, i, x, centres[j]);
      if (d < distances[i]) {
        distances[i] = d;
        voronoi[i] = static_cast<Index>(j);
      }
    }
}

// SOFA's file: useTopo radius fixedRadius count number, then per cluster its size and indices.
bool ClusteringEngine::load() {
  const std::string& file = in_file.value();
  if (file.empty()) return false;
  if (file == loaded_) return true;
  std::ifstream in(file);
  if (!in) {
    msg_error("cannot open the clusters file '" + file + "'");
    return false;
  }
  bool topo = false;
  double r = 0, rf = 0;
  std::size_t count = 0;
  int num = 0;
  in >> topo >> r >> rf >> count >> num;
  std::vector<std::vector<unsigned>> clusters;
  for (std::size_t i = 0; in && i < count; ++i) {
    std::size_t size = 0;
    in >> size;
    std::vector<unsigned> c;
    for (std::size_t j = 0; in && j < size; ++j) {
      unsigned k = 0;
      in >> k;
      c.push_back(k);
    }
    clusters.push_back(std::move(c));
  }
  if (!in || clusters.size() != count) {
    msg_error("the clusters file '" + file + "' is truncated or malformed");
    return false;
  }
  use_topo.set(topo);
  radius.set(r);
  fixed_radius.set(rf);
  number.set(num);
  cluster.set(std::move(clusters));
  loaded_ = file;
  return true;
}

void ClusteringEngine::save() const {
  const std::string& file = out_file.value();
  if (file.empty()) return;
  std::ofstream out(file);
  if (!out) {
    msg_error("cannot write the clusters file '" + file + "'");
    return;
  }
  const auto& clusters = cluster.value();
  out << use_topo.value() << ' ' << radius.value() << ' ' << fixed_radius.value() << ' ' << clusters.size() << ' '
      << number.value() << " \n";
  for (const auto& c : clusters) {
    out << c.size() << ' ';
    for (unsigned k : c) out << k << ' ';
    out << '\n';
  }
}

void register_clustering_engine(Registry& r) {
  ComponentInfo info;
  info.name = "ClusteringEngine";
  info.category = "Engine/Analyze";
  info.description = "overlapping clusters of points (farthest point sampling, Voronoi cells and a radius)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<ClusteringEngine>();
  r.add(std::move(info));
}

}  // namespace sinew
