// Edge/triangle neighbourhoods computed locally from the element lists, as
// SOFA's containers define them (spec/mechanics.md §5.1): edge j of a
// triangle is the one opposite its vertex j, (t[j+1], t[j+2]); the triangles
// around an edge are listed in triangle order. When the topology exposes no
// edges they are derived from the triangles the way MeshTopology does
// (first occurrence, oriented as found).
#pragma once

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "core/roles.h"

namespace sinew {

struct TriangleAdjacency {
  std::vector<Edge> edges;
  std::vector<std::array<int, 3>> edges_in_triangle;     // −1 when the edge is not in the edge list
  std::vector<std::vector<unsigned>> triangles_around_edge;

  // Builds from `triangles` and `given_edges` (derived from the triangles when empty).
  void build(const std::vector<Triangle>& triangles, const std::vector<Edge>& given_edges) {
    std::map<std::pair<unsigned, unsigned>, unsigned> index;
    auto key = [](unsigned a, unsigned b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
    edges = given_edges;
    if (edges.empty()) {
      for (const Triangle& t : triangles)
        for (int j = 0; j < 3; ++j) {
          const unsigned a = t[(j + 1) % 3], b = t[(j + 2) % 3];
          if (index.emplace(key(a, b), static_cast<unsigned>(edges.size())).second) edges.push_back({a, b});
        }
    } else {
      for (unsigned i = 0; i < edges.size(); ++i) index.emplace(key(edges[i][0], edges[i][1]), i);
    }
    edges_in_triangle.assign(triangles.size(), {-1, -1, -1});
    triangles_around_edge.assign(edges.size(), {});
    for (unsigned i = 0; i < triangles.size(); ++i) {
      const Triangle& t = triangles[i];
      for (int j = 0; j < 3; ++j) {
        auto it = index.find(key(t[(j + 1) % 3], t[(j + 2) % 3]));
        if (it == index.end()) continue;
        edges_in_triangle[i][j] = static_cast<int>(it->second);
        triangles_around_edge[it->second].push_back(i);
      }
    }
  }

  // Local index (0..2) of edge `e` in triangle `t` = index of the opposite vertex; −1 if absent.
  int edge_index_in_triangle(unsigned t, unsigned e) const {
    for (int j = 0; j < 3; ++j)
      if (edges_in_triangle[t][j] == static_cast<int>(e)) return j;
    return -1;
  }
};

}  // namespace sinew
