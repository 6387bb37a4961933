// MeshLoader's post-processing (spec/mechanics.md §7.1): transform, triangulate,
// createSubelements, onlyAttachedPoints and normals, in SOFA's order.
#include "io/mesh_readers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "io/reader_text.h"
#include "io/sofa_quat.h"

namespace sinew::io {

using internal::maybe_flip;

std::array<double, 16> trs_matrix(const Vec3& t, const Vec3& rot_deg, const Vec3& s) {
  using M4 = std::array<double, 16>;
  auto mul = [](const M4& a, const M4& b) {
    M4 r{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) {
        const double aik = a[i * 4 + k];
        for (int j = 0; j < 4; ++j) r[i * 4 + j] += aik * b[k * 4 + j];
      }
    return r;
  };
  M4 T{1, 0, 0, t[0], 0, 1, 0, t[1], 0, 0, 1, t[2], 0, 0, 0, 1};
  const Vec3 rad(rot_deg[0] * M_PI / 180.0, rot_deg[1] * M_PI / 180.0, rot_deg[2] * M_PI / 180.0);
  const auto R3 = SQuat::from_euler(rad).matrix();
  M4 R{R3[0], R3[1], R3[2], 0, R3[3], R3[4], R3[5], 0, R3[6], R3[7], R3[8], 0, 0, 0, 0, 1};
  M4 S{s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1};
  return mul(mul(T, R), S);
}

Vec3 transform_point(const std::array<double, 16>& M, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    r[i] = M[i * 4 + 0] * v[0];
    for (int j = 1; j < 3; ++j) r[i] += M[i * 4 + j] * v[j];
    r[i] += M[i * 4 + 3];
  }
  return r;
}

namespace {

template <std::size_t N>
std::array<unsigned, N> sorted(std::array<unsigned, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

template <std::size_t N>
void append_unique(std::vector<std::array<unsigned, N>>& list, std::set<std::array<unsigned, N>>& seen,
                   const std::array<unsigned, N>& e) {
  if (seen.insert(sorted(e)).second) list.push_back(e);
}

template <std::size_t N>
std::set<std::array<unsigned, N>> sorted_set(const std::vector<std::array<unsigned, N>>& list) {
  std::set<std::array<unsigned, N>> s;
  for (const auto& e : list) s.insert(sorted(e));
  return s;
}

bool near_identity(const std::array<double, 16>& M) {
  // SOFA compares matrices row by row with Vec equality (1e-6).
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!(std::abs(M[i * 4 + j] - (i == j ? 1.0 : 0.0)) < 1e-6)) return false;
  return true;
}

}  // namespace

void finish_mesh(MeshData& m, const FinishOptions& opt) {
  // 1. Transformation (replaces translation/rotation/scale when not the identity).
  std::array<double, 16> M = opt.transformation;
  if (near_identity(M)) M = trs_matrix(opt.translation, opt.rotation, opt.scale);
  if (!near_identity(M)) {
    bool is_transform = std::abs(M[15] - 1.0) <= 1e-6;
    for (int j = 0; j < 3; ++j) is_transform = is_transform && std::abs(M[12 + j]) <= 1e-6;
    if (is_transform)
      for (Vec3& p : m.positions) p = transform_point(M, p);
  }

  // 2. updateElements
  if (opt.triangulate) {
    for (const Quad& q : m.quads) {
      m.triangles.push_back(maybe_flip(Triangle{q[0], q[1], q[2]}, opt.flip_normals));
      m.triangles.push_back(maybe_flip(Triangle{q[0], q[2], q[3]}, opt.flip_normals));
    }
    m.quads.clear();
  }
  if (opt.create_subelements) {
    if (!m.hexahedra.empty()) {
      auto seen = sorted_set(m.quads);
      for (const Hexa& h : std::vector<Hexa>(m.hexahedra)) {
        const Quad f[6] = {{h[0], h[3], h[2], h[1]}, {h[4], h[5], h[6], h[7]}, {h[0], h[1], h[5], h[4]},
                           {h[1], h[2], h[6], h[5]}, {h[2], h[3], h[7], h[6]}, {h[3], h[0], h[4], h[7]}};
        for (const Quad& q : f) append_unique(m.quads, seen, q);
      }
    }
    if (!m.prisms.empty()) {
      auto qs = sorted_set(m.quads);
      auto ts = sorted_set(m.triangles);
      for (const Prism& p : std::vector<Prism>(m.prisms)) {
        append_unique(m.quads, qs, Quad{p[0], p[3], p[4], p[1]});
        append_unique(m.quads, qs, Quad{p[0], p[2], p[5], p[3]});
        append_unique(m.quads, qs, Quad{p[1], p[4], p[5], p[2]});
        append_unique(m.triangles, ts, Triangle{p[0], p[1], p[2]});
        append_unique(m.triangles, ts, Triangle{p[4], p[3], p[5]});
      }
    }
    if (!m.pyramids.empty()) {
      auto qs = sorted_set(m.quads);
      auto ts = sorted_set(m.triangles);
      for (const Pyramid& p : std::vector<Pyramid>(m.pyramids)) {
        append_unique(m.quads, qs, Quad{p[0], p[3], p[2], p[1]});
        append_unique(m.triangles, ts, Triangle{p[0], p[1], p[4]});
        append_unique(m.triangles, ts, Triangle{p[1], p[2], p[4]});
        append_unique(m.triangles, ts, Triangle{p[3], p[4], p[2]});
        append_unique(m.triangles, ts, Triangle{p[0], p[4], p[3]});
      }
    }
    if (!m.tetrahedra.empty()) {
      auto ts = sorted_set(m.triangles);
      for (const Tetra& t : m.tetrahedra) {
        append_unique(m.triangles, ts, Triangle{t[0], t[2], t[1]});
        append_unique(m.triangles, ts, Triangle{t[0], t[1], t[3]});
        append_unique(m.triangles, ts, Triangle{t[0], t[3], t[2]});
        append_unique(m.triangles, ts, Triangle{t[1], t[2], t[3]});
      }
    }
    if (!m.quads.empty()) {
      auto es = sorted_set(m.edges);
      for (const Quad& q : m.quads)
        for (int j = 0; j < 4; ++j) append_unique(m.edges, es, Edge{q[(j + 1) % 4], q[(j + 2) % 4]});
    }
    if (!m.triangles.empty()) {
      auto es = sorted_set(m.edges);
      for (const Triangle& t : m.triangles)
        for (int j = 0; j < 3; ++j) append_unique(m.edges, es, Edge{t[(j + 1) % 3], t[(j + 2) % 3]});
    }
  }

  // 3. updatePoints
  if (opt.only_attached_points) {
    std::set<unsigned> attached;
    auto collect = [&](const auto& list) {
      for (const auto& e : list)
        for (unsigned v : e) attached.insert(v);
    };
    collect(m.edges);
    collect(m.triangles);
    collect(m.quads);
    collect(m.tetrahedra);
    collect(m.prisms);
    collect(m.pyramids);
    collect(m.hexahedra);
    if (attached.size() != m.positions.size()) {
      std::vector<unsigned> old2new(m.positions.size(), 0);
      unsigned p = 0;
      for (unsigned v : attached) {
        if (v >= m.positions.size()) continue;
        old2new[v] = p;
        if (p != v) m.positions[p] = m.positions[v];
        ++p;
      }
      m.positions.resize(p);
      auto renumber = [&](auto& list) {
        for (auto& e : list)
          for (unsigned& v : e) v = v < old2new.size() ? old2new[v] : v;
      };
      renumber(m.edges);
      renumber(m.triangles);
      renumber(m.quads);
      renumber(m.tetrahedra);
      renumber(m.prisms);
      renumber(m.pyramids);
      renumber(m.hexahedra);
    }
  }

  // 4. updateNormals
  if (opt.compute_normals && m.normals.size() != m.positions.size()) {
    const std::size_t n = m.positions.size();
    m.normals.resize(n, Vec3::Zero());
    auto normalize = [](Vec3& v) {
      const double nn = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (nn > std::numeric_limits<double>::epsilon()) v /= nn;
    };
    for (const Triangle& t : m.triangles) {
      if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
      const Vec3 &v1 = m.positions[t[0]], &v2 = m.positions[t[1]], &v3 = m.positions[t[2]];
      Vec3 nn = cross3((v2 - v1), v3 - v1);
      normalize(nn);
      m.normals[t[0]] += nn;
      m.normals[t[1]] += nn;
      m.normals[t[2]] += nn;
    }
    for (const Quad& q : m.quads) {
      if (q[0] >= n || q[1] >= n || q[2] >= n || q[3] >= n) continue;
      const Vec3 &v1 = m.positions[q[0]], &v2 = m.positions[q[1]], &v3 = m.positions[q[2]], &v4 = m.positions[q[3]];
      Vec3 n1 = cross3((v2 - v1), v4 - v1), n2 = cross3((v3 - v2), v1 - v2), n3 = cross3((v4 - v3), v2 - v3),
           n4 = cross3((v1 - v4), v3 - v4);
      normalize(n1);
      normalize(n2);
      normalize(n3);
      normalize(n4);
      m.normals[q[0]] += n1;
      m.normals[q[1]] += n2;
      m.normals[q[2]] += n3;
      m.normals[q[3]] += n4;
    }
    for (Vec3& v : m.normals) normalize(v);
  }
}

}  // namespace sinew::io
