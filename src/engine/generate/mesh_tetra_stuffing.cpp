#include "engine/generate/mesh_tetra_stuffing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/registry.h"

namespace sinew {

namespace {
// SOFA's Vec arithmetic, component by component.
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross3(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
// sofa::geometry::Triangle::rayIntersection: forward hits only (t ≥ ε).
bool ray_hit(const Vec3& n0, const Vec3& n1, const Vec3& n2, const Vec3& origin, const Vec3& dir, double& t) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  t = 0;
  const Vec3 e0 = n1 - n0, e1 = n2 - n0;
  const Vec3 pvec = cross3(dir, e1);
  const double det = dot3(e0, pvec);
  if (std::fabs(det) <= eps) return false;
  const double inv_det = 1.0 / det;
  const Vec3 tvec = origin - n0;
  const double u = dot3(tvec, pvec) * inv_det;
  if (u < 0.0 - eps || u > 1.0 + eps) return false;
  const Vec3 qvec = cross3(tvec, e0);
  const double v = dot3(dir, qvec) * inv_det;
  if (v < 0.0 - eps || (u + v) > 1.0 + eps) return false;
  t = dot3(e1, qvec) * inv_det;
  if (t < eps || t != t || v != v || u != u) return false;
  return true;
}
double edge_size2(int e) { return e < 6 ? 4 : 3; }
}  // namespace

MeshTetraStuffing::MeshTetraStuffing() {
  output_tetrahedra.add_alias("outputTetras");
  split_tetrahedra.add_alias("splitTetras");
  for (BaseField* f : std::initializer_list<BaseField*>{&input_points, &input_triangles, &input_quads, &alpha_long,
                                                        &alpha_short, &snap_points, &split_tetrahedra, &size, &vbbox})
    add_input(f);
  add_output(&output_points);
  add_output(&output_tetrahedra);
}

void MeshTetraStuffing::init() {
  set_dirty();
  update();
}

// Neighbour of point p along lattice direction e (−1 outside the grids): e < 6
// along an axis of the same grid (even: −, odd: +), else one of the 8
// diagonal neighbours in the other grid.
int MeshTetraStuffing::edge_point(int p, int e) const {
  int c[3];
  if (p < ph0_) {
    c[0] = p % gsize_[0];
    p /= gsize_[0];
    c[1] = p % gsize_[1];
    p /= gsize_[1];
    c[2] = p;
    if (e < 6) {
      if (e & 1) {
        if (++c[e >> 1] >= gsize_[e >> 1]) return -1;
      } else if (--c[e >> 1] < 0) {
        return -1;
      }
      return c[0] + gsize_[0] * (c[1] + gsize_[1] * c[2]);
    }
    e -= 6;
    c[0] += (e >> 0) & 1;
    c[1] += ((e >> 1) ^ e) & 1;
    c[2] += ((e >> 2) ^ e) & 1;
    return ph0_ + c[0] + hsize_[0] * (c[1] + hsize_[1] * c[2]);
  }
  p -= ph0_;
  c[0] = p % hsize_[0];
  p /= hsize_[0];
  c[1] = p % hsize_[1];
  p /= hsize_[1];
  c[2] = p;
  if (e < 6) {
    if (e & 1) {
      if (++c[e >> 1] >= hsize_[e >> 1]) return -1;
    } else if (--c[e >> 1] < 0) {
      return -1;
    }
    return ph0_ + c[0] + hsize_[0] * (c[1] + hsize_[1] * c[2]);
  }
  e -= 6;
  c[0] += ((e >> 0) & 1) - 1;
  c[1] += (((e >> 1) ^ e) & 1) - 1;
  c[2] += (((e >> 2) ^ e) & 1) - 1;
  for (int i = 0; i < 3; ++i)
    if (static_cast<unsigned>(c[i]) >= static_cast<unsigned>(gsize_[i])) return -1;
  return c[0] + gsize_[0] * (c[1] + gsize_[1] * c[2]);
}

void MeshTetraStuffing::do_update() {
  const std::vector<Vec3>& inP = input_points.get();
  std::vector<Triangle> inT = input_triangles.get();
  const std::vector<Quad>& inQ = input_quads.get();
  if (inP.empty() || (inT.empty() && inQ.empty())) {
    msg_error("empty input mesh: link inputPoints and inputTriangles (or inputQuads) to a topology or mesh loader");
    return;
  }
  for (const Quad& q : inQ) {
    inT.push_back({q[0], q[1], q[2]});
    inT.push_back({q[0], q[2], q[3]});
  }
  for (const Triangle& t : inT)
    for (unsigned v : t)
      if (v >= inP.size()) {
        msg_error("an input triangle refers to point " + std::to_string(v) + ", beyond the " +
                  std::to_string(inP.size()) + " input points: nothing generated");
        return;
      }

  // Input box (SOFA's loop: a coordinate below the minimum is not compared with the maximum) and normals.
  Vec3 lo = inP[0], hi = inP[0];
  for (std::size_t p = 1; p < inP.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      if (inP[p][c] < lo[c]) lo[c] = inP[p][c];
      else if (inP[p][c] > hi[c]) hi[c] = inP[p][c];
    }
  std::vector<Vec3> normal(inT.size());
  for (std::size_t t = 0; t < inT.size(); ++t)
    normal[t] = cross3(inP[inT[t][1]] - inP[inT[t][0]], inP[inT[t][2]] - inP[inT[t][0]]);

  VecN<6> bb = vbbox.get();
  if (bb[0] >= bb[3]) {
    const Vec3 grow = (hi - lo) * 0.01;
    for (int c = 0; c < 3; ++c) {
      bb[c] = lo[c] - grow[c];
      bb[c + 3] = hi[c] + grow[c];
    }
    vbbox.set(bb);
  }
  cellsize_ = size.get();
  if (cellsize_ < 0) {
    const double bsize = std::max({bb[3] - bb[0], bb[4] - bb[1], bb[5] - bb[2]});
    cellsize_ = bsize / -cellsize_;
  }
  if (!(cellsize_ > 0) || !std::isfinite(cellsize_)) {
    msg_error("the cell size is not positive (size = " + std::to_string(size.get()) + "): nothing generated");
    return;
  }
  const Vec3 b0(bb[0], bb[1], bb[2]), b1(bb[3], bb[4], bb[5]);
  const Vec3 p0 = (b0 + b1) / 2;
  Vec3 g0, h0;
  for (int c = 0; c < 3; ++c) {
    const int c0 = -(static_cast<int>((p0[c] - b0[c]) / cellsize_) + 2);
    const int c1 = static_cast<int>((b1[c] - p0[c]) / cellsize_) + 2;
    gsize_[c] = c1 - c0 + 1;
    g0[c] = p0[c] + c0 * cellsize_;
    hsize_[c] = gsize_[c] + 1;
    h0[c] = g0[c] - cellsize_ / 2;
  }
  const double cells = static_cast<double>(gsize_[0]) * gsize_[1] * gsize_[2];
  if (cells > 5e7) {
    msg_error("the grid would have " + std::to_string(cells) + " cells: choose a larger size");
    return;
  }
  ph0_ = gsize_[0] * gsize_[1] * gsize_[2];
  std::vector<Vec3> outP(static_cast<std::size_t>(ph0_ + hsize_[0] * hsize_[1] * hsize_[2]));
  std::vector<Tetra> outT;
  int p = 0;
  for (int z = 0; z < gsize_[2]; ++z)
    for (int y = 0; y < gsize_[1]; ++y)
      for (int x = 0; x < gsize_[0]; ++x, ++p) outP[p] = g0 + Vec3(x * cellsize_, y * cellsize_, z * cellsize_);
  p = ph0_;
  for (int z = 0; z < hsize_[2]; ++z)
    for (int y = 0; y < hsize_[1]; ++y)
      for (int x = 0; x < hsize_[0]; ++x, ++p) outP[p] = h0 + Vec3(x * cellsize_, y * cellsize_, z * cellsize_);

  int nbp = static_cast<int>(outP.size());
  inside_.assign(outP.size(), 0);
  std::array<double, kEdgeShell> zero{};
  dist_.assign(outP.size(), zero);
  split_points_.clear();

  // Rays along each lattice line, from its first point: votes and distances to the surface.
  struct Hit {
    int tid;
    double t;
  };
  std::vector<Hit> hits;
  for (int q = 0; q < nbp; ++q)
    for (int e = 0; e < kEdgeShell; e += 2) {
      int p1 = edge_point(q, e);
      const int p2 = edge_point(q, e + 1);
      if (p1 == -1 || p2 != -1) continue;
      const Vec3 origin = outP[q];
      const Vec3 dir = outP[p1] - origin;
      hits.clear();
      for (std::size_t t = 0; t < inT.size(); ++t) {
        double th;
        if (ray_hit(inP[inT[t][0]], inP[inT[t][1]], inP[inT[t][2]], origin, dir, th))
          hits.push_back({static_cast<int>(t), th});
      }
      if (hits.empty()) continue;
      std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
      const int n = static_cast<int>(hits.size());
      for (Hit& h : hits) h.tid = dot3(normal[static_cast<std::size_t>(h.tid)], dir) < 0 ? -1 : 1;
      int d = 0, i = 0;
      p1 = q;
      while (p1 != -1) {
        while (i < n && hits[i].t < d) ++i;
        if (i >= n) inside_[p1] -= hits[n - 1].tid;
        else if (i == 0) inside_[p1] += hits[0].tid;
        else if ((d - hits[i - 1].t) < (hits[i].t - d)) inside_[p1] += hits[i].tid;
        else inside_[p1] -= hits[i - 1].tid;
        if (i < n) dist_[p1][e] = hits[i].t - d;
        if (i > 0) dist_[p1][e + 1] = d - hits[i - 1].t;
        p1 = edge_point(p1, e);
        ++d;
      }
    }
  for (int q = 0; q < nbp; ++q)
    if (inside_[q] == 0) --inside_[q];  // undecided points are outside

  if (snap_points.get()) {
    const double along = alpha_long.get(), ashort = alpha_short.get();
    auto alpha_of = [&](int e) { return e < 6 ? along : ashort; };
    std::vector<bool> violated(outP.size(), false);
    std::set<int> viol_in, viol_out;
    for (int q = 0; q < nbp; ++q) {
      const bool in1 = inside_[q] > 0;
      bool v = false;
      for (int e = 0; e < kEdgeShell && !v; ++e) {
        const int q2 = edge_point(q, e);
        if (q2 == -1) continue;
        const bool in2 = inside_[q2] > 0;
        if (!(in1 ^ in2)) continue;
        if (dist_[q][e] != 0.0 && dist_[q][e] < alpha_of(e)) v = true;
      }
      violated[q] = v;
      if (v) (in1 ? viol_in : viol_out).insert(q);
    }
    auto snap = [&](int q, int e) {
      const int q2 = edge_point(q, e);
      outP[q] += (outP[q2] - outP[q]) * dist_[q][e];
      inside_[q] = 0;  // on the surface now
      violated[q] = false;
    };
    int nwraps = 0;
    do {
      nwraps = 0;
      for (const int q : viol_out) {
        if (inside_[q] == 0) continue;  // already snapped
        double min_dist = 0;
        int min_edge = -1;
        for (int e = 0; e < kEdgeShell; ++e) {
          const int q2 = edge_point(q, e);
          if (q2 == -1) continue;
          if (inside_[q2] > 0 || violated[q2]) continue;  // only towards points that are not violated
          if (dist_[q][e] == 0.0 || dist_[q][e] >= alpha_of(e)) continue;
          const double dd = dist_[q][e] * dist_[q][e] * edge_size2(e);
          if (min_edge == -1 || dd < min_dist) {
            min_edge = e;
            min_dist = dd;
          }
        }
        if (min_edge == -1) continue;
        snap(q, min_edge);
        ++nwraps;
        for (int e = 0; e < kEdgeShell; ++e) {
          dist_[q][e] = 0;
          const int q2 = edge_point(q, e);
          if (q2 == -1) continue;
          dist_[q2][e ^ 1] = 0;
          if (violated[q2] && inside_[q2] > 0) {
            bool v = false;
            for (int e2 = 0; e2 < kEdgeShell && !v; ++e2) {
              const int q3 = edge_point(q2, e2);
              if (q3 == -1 || inside_[q3] >= 0) continue;
              // SOFA picks the threshold from the outer edge e here.
              if (dist_[q2][e2] != 0.0 && dist_[q2][e2] < alpha_of(e)) v = true;
            }
            if (!v) {
              violated[q2] = false;
              viol_in.erase(q2);
            }
          }
        }
      }
    } while (nwraps > 0);
    for (const int q : viol_in) {
      if (inside_[q] == 0) {
        msg_error("inside point " + std::to_string(q) + " already snapped");
        continue;
      }
      double min_dist = 0;
      int min_edge = -1;
      for (int e = 0; e < kEdgeShell; ++e) {
        const int q2 = edge_point(q, e);
        if (q2 == -1 || inside_[q2] >= 0) continue;  // only towards outside points
        if (dist_[q][e] == 0.0 || dist_[q][e] >= alpha_of(e)) continue;
        const double dd = dist_[q][e] * dist_[q][e] * edge_size2(e);
        if (min_edge == -1 || dd < min_dist) {
          min_edge = e;
          min_dist = dd;
        }
      }
      if (min_edge == -1) {
        msg_error("inside point " + std::to_string(q) + " has no violated edge");
        continue;
      }
      snap(q, min_edge);
      for (int e = 0; e < kEdgeShell; ++e) {
        dist_[q][e] = 0;
        const int q2 = edge_point(q, e);
        if (q2 != -1) dist_[q2][e ^ 1] = 0;
      }
    }
  }

  if (split_tetrahedra.get()) {
    for (int q = 0; q < nbp; ++q) {
      if (inside_[q] >= 0) continue;  // outside points
      for (int e = 0; e < kEdgeShell; ++e) {
        const int q2 = edge_point(q, e);
        if (q2 == -1 || inside_[q2] <= 0) continue;  // towards inside points
        const int np = static_cast<int>(outP.size());
        outP.push_back(outP[q] + (outP[q2] - outP[q]) * dist_[q][e]);
        split_points_[{q, q2}] = np;
      }
    }
  }

  const int g01 = gsize_[0] * gsize_[1], h01 = hsize_[0] * hsize_[1];
  for (int q = 0, ph = ph0_, z = 0; z < gsize_[2]; ++z, ph += hsize_[0])
    for (int y = 0; y < gsize_[1]; ++y, ++ph)
      for (int x = 0; x < gsize_[0]; ++x, ++q, ++ph) {
        if (x > 0) {
          const int shell[4] = {ph, ph + hsize_[0], ph + hsize_[0] + h01, ph + h01};
          for (int i = 0; i < 4; ++i) add_tetra(outT, outP, q, q - 1, shell[(i + 1) % 4], shell[i]);
        }
        if (y > 0) {
          const int shell[4] = {ph, ph + h01, ph + 1 + h01, ph + 1};
          for (int i = 0; i < 4; ++i) add_tetra(outT, outP, q, q - gsize_[0], shell[(i + 1) % 4], shell[i]);
        }
        if (z > 0) {
          const int shell[4] = {ph, ph + 1, ph + 1 + hsize_[0], ph + hsize_[0]};
          for (int i = 0; i < 4; ++i) add_tetra(outT, outP, q, q - g01, shell[(i + 1) % 4], shell[i]);
        }
      }

  // Remove the points no tetrahedron uses.
  std::vector<int> new_id(outP.size(), 0);
  for (const Tetra& t : outT)
    for (unsigned v : t) new_id[v] = 1;
  nbp = 0;
  for (std::size_t q = 0; q < new_id.size(); ++q) {
    if (new_id[q] == 0) {
      new_id[q] = -1;
      continue;
    }
    new_id[q] = nbp++;
    if (new_id[q] != static_cast<int>(q)) {
      outP[static_cast<std::size_t>(new_id[q])] = outP[q];
      if (inside_.size() > q) inside_[static_cast<std::size_t>(new_id[q])] = inside_[q];
    }
  }
  outP.resize(static_cast<std::size_t>(nbp));
  for (Tetra& t : outT)
    for (unsigned& v : t) v = static_cast<unsigned>(new_id[v]);

  // Orientation and duplicate-face checks, as SOFA.
  std::set<Triangle> faces;
  for (std::size_t t = 0; t < outT.size(); ++t) {
    Tetra& T = outT[t];
    const Vec3 a = outP[T[1]] - outP[T[0]], b = outP[T[2]] - outP[T[0]], c = outP[T[3]] - outP[T[0]];
    if (dot3(a, cross3(b, c)) < 0) {
      msg_warning("tetrahedron " + std::to_string(t) + " is inverted: two vertices swapped");
      std::swap(T[2], T[3]);
    }
    for (int i = 0; i < 4; ++i) {
      int i0 = 0;
      if (T[(i + 2) % 4] < T[(i + i0) % 4]) i0 = 1;
      if (T[(i + 3) % 4] < T[(i + i0) % 4]) i0 = 2;
      Triangle tr{T[(i + 1 + ((i0 + 0) % 3)) % 4], T[(i + 1 + ((i0 + 1) % 3)) % 4], T[(i + 1 + ((i0 + 2) % 3)) % 4]};
      if (i % 2) std::swap(tr[1], tr[2]);
      if (!faces.insert(tr).second)
        msg_error("duplicate triangle " + std::to_string(tr[0]) + " " + std::to_string(tr[1]) + " " +
                  std::to_string(tr[2]) + " in tetrahedron " + std::to_string(t));
    }
  }
  dist_.clear();
  output_points.set(std::move(outP));
  output_tetrahedra.set(std::move(outT));
}

void MeshTetraStuffing::add_final_tetra(std::vector<Tetra>& out, const std::vector<Vec3>& x, int p1, int p2, int p3,
                                        int p4, bool flip) {
  if (flip) std::swap(p3, p4);
  const Vec3 a = x[p2] - x[p1], b = x[p3] - x[p1], c = x[p4] - x[p1];
  if (dot3(a, cross3(b, c)) < 0) std::swap(p3, p4);
  out.push_back({static_cast<unsigned>(p1), static_cast<unsigned>(p2), static_cast<unsigned>(p3),
                 static_cast<unsigned>(p4)});
}

namespace {
// SOFA's needFlip: whether the two vertex orders differ in parity once both start at their smallest.
bool need_flip(int p1, int p2, int p3, int p4, int q1, int q2, int q3, int q4) {
  bool flip = false;
  while (p1 > p2 || p1 > p3 || p1 > p4) {
    const int t = p1;
    p1 = p2, p2 = p3, p3 = p4, p4 = t;
    flip = !flip;
  }
  while (q1 > q2 || q1 > q3 || q1 > q4) {
    const int t = q1;
    q1 = q2, q2 = q3, q3 = q4, q4 = t;
    flip = !flip;
  }
  while (p2 > p3 || p2 > p4) {
    const int t = p2;
    p2 = p3, p3 = p4, p4 = t;
  }
  while (q2 > q3 || q2 > q4) {
    const int t = q2;
    q2 = q3, q3 = q4, q4 = t;
  }
  if (p3 == q4) flip = !flip;
  return flip;
}
}  // namespace

bool MeshTetraStuffing::flip_diag(const std::vector<Vec3>& x, int a, int b, int c, int, int e) const {
  if (e < ph0_) {
    if (a < ph0_) return true;
    if (b < ph0_) return false;
  } else {
    if (a >= ph0_) return true;
    if (b >= ph0_) return false;
  }
  int nsup = 0;
  for (int i = 0; i < 3; ++i)
    if (x[a][i] > x[c][i]) ++nsup;
  return (nsup & 1) != (a < ph0_ ? 1 : 0);
}

int MeshTetraStuffing::split_point(int from, int to) {
  if (auto it = split_points_.find({from, to}); it != split_points_.end()) return it->second;
  if (auto it = split_points_.find({to, from}); it != split_points_.end()) return it->second;
  msg_error("cut point between " + std::to_string(from) + " and " + std::to_string(to) + " not found");
  return from;
}

void MeshTetraStuffing::add_tetra(std::vector<Tetra>& out, std::vector<Vec3>& x, int p1, int p2, int p3, int p4) {
  {
    const Vec3 a = x[p2] - x[p1], b = x[p3] - x[p1], c = x[p4] - x[p1];
    if (dot3(a, cross3(b, c)) < 0) std::swap(p3, p4);
  }
  const int in1 = inside_[p1], in2 = inside_[p2], in3 = inside_[p3], in4 = inside_[p4];
  int nneg = 0, npos = 0, nzero = 0;
  int pneg[4] = {0, 0, 0, 0}, ppos[4] = {0, 0, 0, 0}, pzero[4] = {0, 0, 0, 0};
  for (const auto& [pp, in] : {std::pair{p1, in1}, std::pair{p2, in2}, std::pair{p3, in3}, std::pair{p4, in4}}) {
    if (in < 0) pneg[nneg++] = pp;
    else if (in > 0) ppos[npos++] = pp;
    else pzero[nzero++] = pp;
  }
  if (npos == 0 && nneg > 0) return;  // outside
  if (nneg == 0 || !split_tetrahedra.get()) {
    add_final_tetra(out, x, p1, p2, p3, p4, false);
  } else if (npos == 1) {
    const int q0 = ppos[0];
    if (in1 < 0) p1 = split_point(p1, q0);
    if (in2 < 0) p2 = split_point(p2, q0);
    if (in3 < 0) p3 = split_point(p3, q0);
    if (in4 < 0) p4 = split_point(p4, q0);
    add_final_tetra(out, x, p1, p2, p3, p4, false);
  } else if (npos == 2 && nneg == 1) {
    const int q0 = pzero[0];
    const int cut1 = split_point(pneg[0], ppos[0]), cut2 = split_point(pneg[0], ppos[1]);
    const bool flip_d = flip_diag(x, ppos[0], ppos[1], cut2, cut1, pneg[0]);
    const bool flip_t = need_flip(q0, ppos[0], ppos[1], pneg[0], p1, p2, p3, p4);
    if (!flip_d) {
      add_final_tetra(out, x, q0, ppos[0], ppos[1], cut2, flip_t);
      add_final_tetra(out, x, q0, ppos[0], cut2, cut1, flip_t);
    } else {
      add_final_tetra(out, x, q0, ppos[0], ppos[1], cut1, flip_t);
      add_final_tetra(out, x, q0, ppos[1], cut2, cut1, flip_t);
    }
  } else if (npos == 2 && nneg == 2) {
    const int cut1 = split_point(pneg[0], ppos[0]), cut2 = split_point(pneg[0], ppos[1]);
    const int cut3 = split_point(pneg[1], ppos[0]), cut4 = split_point(pneg[1], ppos[1]);
    const bool flip_a = flip_diag(x, ppos[0], ppos[1], cut2, cut1, pneg[0]);
    const bool flip_b = flip_diag(x, ppos[0], ppos[1], cut4, cut3, pneg[1]);
    const bool flip_t = need_flip(ppos[0], ppos[1], pneg[0], pneg[1], p1, p2, p3, p4);
    if (!flip_a && flip_b) {
      add_final_tetra(out, x, ppos[0], ppos[1], cut2, cut3, flip_t);
      add_final_tetra(out, x, ppos[0], cut2, cut1, cut3, flip_t);
      add_final_tetra(out, x, ppos[1], cut2, cut3, cut4, flip_t);
    } else if (flip_a && !flip_b) {
      add_final_tetra(out, x, ppos[0], ppos[1], cut1, cut4, flip_t);
      add_final_tetra(out, x, ppos[1], cut1, cut4, cut2, flip_t);
      add_final_tetra(out, x, ppos[0], cut1, cut3, cut4, flip_t);
    } else {
      msg_error(std::string("invalid tetrahedron split: flipA = ") + (flip_a ? "1" : "0") +
                ", flipB = " + (flip_b ? "1" : "0"));
    }
  } else {  // npos == 3, nneg == 1
    const int cut1 = split_point(pneg[0], ppos[0]), cut2 = split_point(pneg[0], ppos[1]),
              cut3 = split_point(pneg[0], ppos[2]);
    const bool flip1 = flip_diag(x, ppos[0], ppos[1], cut2, cut1, pneg[0]);
    const bool flip2 = flip_diag(x, ppos[1], ppos[2], cut3, cut2, pneg[0]);
    bool flip3 = flip_diag(x, ppos[2], ppos[0], cut1, cut3, pneg[0]);
    if (flip1 == flip2 && flip2 == flip3) {
      msg_error("invalid tetrahedron split");
      flip3 = !flip1;
    }
    const int pp0 = (flip1 && !flip2) ? ppos[1] : (flip2 && !flip3) ? ppos[2] : ppos[0];
    const int pc0 = (!flip1 && flip2) ? cut2 : (!flip2 && flip3) ? cut3 : cut1;
    const bool flip_t = need_flip(pneg[0], ppos[0], ppos[1], ppos[2], p1, p2, p3, p4);
    add_final_tetra(out, x, pp0, cut1, cut3, cut2, flip_t);
    add_final_tetra(out, x, pc0, ppos[0], ppos[1], ppos[2], flip_t);
    if (flip1 == flip2)
      add_final_tetra(out, x, ppos[1], cut2, pp0, pc0,
                      need_flip(ppos[1], pneg[0], pp0, pp0 == ppos[0] ? ppos[2] : ppos[0], p1, p2, p3, p4));
    else if (flip2 == flip3)
      add_final_tetra(out, x, ppos[2], cut3, pp0, pc0,
                      need_flip(ppos[2], pneg[0], pp0, pp0 == ppos[0] ? ppos[1] : ppos[0], p1, p2, p3, p4));
    else
      add_final_tetra(out, x, ppos[0], cut1, pp0, pc0,
                      need_flip(ppos[0], pneg[0], pp0, pp0 == ppos[1] ? ppos[2] : ppos[1], p1, p2, p3, p4));
  }
}

void register_mesh_tetra_stuffing(Registry& r) {
  ComponentInfo info;
  info.name = "MeshTetraStuffing";
  info.category = "Engine/Generate";
  info.description = "tetrahedral mesh of the inside of a closed surface (isosurface stuffing)";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<MeshTetraStuffing>(); };
  r.add(std::move(info));
}

}  // namespace sinew
