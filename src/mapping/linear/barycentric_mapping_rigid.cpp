#include "mapping/linear/barycentric_mapping_rigid.h"

#include <cmath>
#include <limits>

#include "core/node.h"
#include "mapping/linear/barycentric_coords.h"
#include "math/decompose.h"
#include "math/quat.h"

namespace sinew {

namespace {

// r = M·v, summed in SOFA's order.
inline void rigid_mul3(const double M[3][3], const double* v, double* r) {
  for (int i = 0; i < 3; ++i) r[i] = M[i][0] * v[0] + M[i][1] * v[1] + M[i][2] * v[2];
}

// a × b
inline void rigid_cross3(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

// Edge basis of tetrahedron t: M[i][j] = (x_{t[j+1]} − x_{t[0]})[i] (edges as columns).
inline void edge_basis(const Tetra& t, const double* X, double M[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) M[i][j] = X[t[j + 1] * 3 + i] - X[t[0] * 3 + i];
}

// The four barycentric weights (1 − fx − fy − fz, fx, fy, fz) of coordinates b = (fx, fy, fz).
inline void bary_weights(const double* b, double w[4]) {
  w[0] = 1 - b[0] - b[1] - b[2];
  w[1] = b[0];
  w[2] = b[1];
  w[3] = b[2];
}

// o = Σ_k w_k·A[t_k] over the tetrahedron's vertices (A: a Vec3 array), summed in vertex order.
inline void blend(const Tetra& t, const double w[4], const double* A, double* o) {
  for (int k = 0; k < 3; ++k)
    o[k] = A[t[0] * 3 + k] * w[0] + A[t[1] * 3 + k] * w[1] + A[t[2] * 3 + k] * w[2] + A[t[3] * 3 + k] * w[3];
}

}  // namespace

bool BarycentricMappingRigid::init_mapping() {
  if (!input_topology) input_topology.set(in_[0]->node() ? in_[0]->node()->find_up<MeshTopologyBase>() : nullptr);
  if (!output_topology && out_ && out_->node()) output_topology.set(out_->node()->find_up<MeshTopologyBase>());
  if (!input_topology) {
    msg_error("no input topology found; set input_topology=\"@...\"");
    return false;
  }
  const MeshTopologyBase& topo = *input_topology;
  const std::string& cls = topo.class_name();
  if (cls != "TetrahedronSetTopologyContainer" || topo.tetrahedra().empty() || !topo.hexahedra().empty()) {
    msg_error("the Vec3d,Rigid3d template maps frames into tetrahedra only: the input topology " + topo.describe() +
              " must be a TetrahedronSetTopologyContainer with tetrahedra (SOFA uses other, unsupported "
              "mappers for other topologies)");
    return false;
  }
  const int x_id = use_rest_position.value() ? kRestPosition : kPosition;
  const std::vector<double>& in = in_coord(x_id);
  const std::vector<double> out = *out_coord_read(x_id);  // copy: resizing the output must not invalidate it
  std::vector<std::size_t> degenerate;
  const std::string bad = embed(in, out, degenerate);
  if (!degenerate.empty())
    msg_warning(std::to_string(degenerate.size()) + " tetrahedra of " + topo.describe() +
                " are degenerate (zero volume) and take no frame; the first is " + std::to_string(degenerate[0]));
  if (!bad.empty()) {
    msg_error(bad);
    return false;
  }
  frozen_ = false;
  snapshot_.clear();
  actual_ = in;
  resize_output(map_.size());
  return true;
}

std::string BarycentricMappingRigid::embed(const std::vector<double>& in, const std::vector<double>& out,
                                           std::vector<std::size_t>& degenerate) {
  const MeshTopologyBase& topo = *input_topology;
  const std::size_t n_in = in.size() / 3;
  tetras_ = topo.tetrahedra();
  version_ = tetra_version();
  needed_ = 0;
  map_.clear();
  for (std::size_t t = 0; t < tetras_.size(); ++t)
    for (unsigned v : tetras_[t]) {
      if (v >= n_in)
        return "tetrahedron " + std::to_string(t) + " of " + topo.describe() + " uses point " + std::to_string(v) +
               " but the input state has " + std::to_string(n_in) + " points";
      needed_ = std::max<std::size_t>(needed_, std::size_t{v} + 1);
    }

  // Local frames of the tetrahedra: the inverse of their edge basis, and their centroids.
  struct Frame {
    double inv[3][3];
    double c[3];
    bool ok;
  };
  std::vector<Frame> frames(tetras_.size());
  for (std::size_t t = 0; t < tetras_.size(); ++t) {
    Frame& f = frames[t];
    double m[3][3];
    edge_basis(tetras_[t], in.data(), m);
    f.ok = bary_invert3(m, f.inv);
    if (!f.ok) degenerate.push_back(t);
    for (int k = 0; k < 3; ++k) {
      const Tetra& e = tetras_[t];
      f.c[k] = (in[e[0] * 3 + k] + in[e[1] * 3 + k] + in[e[2] * 3 + k] + in[e[3] * 3 + k]) * 0.25;
    }
  }

  const std::size_t n_out = out.size() / 7;
  map_.assign(n_out, Embedding{});
  for (std::size_t i = 0; i < n_out; ++i) {
    const double* p = &out[i * 7];
    double best = 1e10, coefs[3] = {0, 0, 0};
    long index = -1;
    for (std::size_t t = 0; t < tetras_.size(); ++t) {
      const Frame& f = frames[t];
      if (!f.ok) continue;
      const double* x0 = &in[tetras_[t][0] * 3];
      const double r[3] = {p[0] - x0[0], p[1] - x0[1], p[2] - x0[2]};
      double v[3];
      rigid_mul3(f.inv, r, v);
      double d = std::max(std::max(-v[0], -v[1]), std::max(-v[2], v[0] + v[1] + v[2] - 1));
      if (d > 0) {
        const double c0 = p[0] - f.c[0], c1 = p[1] - f.c[1], c2 = p[2] - f.c[2];
        d = c0 * c0 + c1 * c1 + c2 * c2;
      }
      if (d < best) {
        best = d;
        index = static_cast<long>(t);
        coefs[0] = v[0], coefs[1] = v[1], coefs[2] = v[2];
      }
    }
    if (index < 0) {
      map_.clear();
      return "frame " + std::to_string(i) + " could not be located in any tetrahedron of " + topo.describe();
    }
    Embedding& e = map_[i];
    e.tetra = static_cast<unsigned>(index);
    for (int k = 0; k < 3; ++k) e.bary[k] = coefs[k];
    // Axis c of the frame (column c of its rotation) in the tetrahedron's edge basis, normalised.
    const Mat3 R = quat_to_matrix(Quat::from(p + 3));
    for (int c = 0; c < 3; ++c) {
      const double d[3] = {R(0, c), R(1, c), R(2, c)};
      double* b = e.axis[c];
      rigid_mul3(frames[index].inv, d, b);
      const double len = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
      if (len > std::numeric_limits<double>::epsilon())
        for (int k = 0; k < 3; ++k) b[k] /= len;
    }
  }
  return "";
}

// SOFA's processTopologicalChanges for this mapper: its init again (tetrahedra only), from the
// positions of the last propagation (relocation_snapshot.h), once the lists are final.
void BarycentricMappingRigid::handle_topology_change(MeshTopologyBase& source) {
  if (state() != ComponentState::valid || !input_topology) return;
  snapshot_.take(source, in_[0], in_coord(kPosition), out_, *out_coord_read(kPosition), 7);
}

void BarycentricMappingRigid::reembed() {
  std::vector<double> in, out;  // copies: resize_output may reallocate the output
  const std::string unannounced = snapshot_.select(in_coord(kPosition), *out_coord_read(kPosition), in, out,
                                                   input_topology->describe(), "re-embedding the frames from their current positions");
  if (!unannounced.empty()) msg_warning(unannounced);
  std::vector<std::size_t> degenerate;
  const std::string bad = embed(in, out, degenerate);
  frozen_ = !bad.empty();
  if (frozen_) {
    map_.clear();
    needed_ = 0;
    if (!warned_frozen_) {
      warned_frozen_ = true;
      msg_warning((bad.empty() ? "no tetrahedron left in " + input_topology->describe() : bad) +
                  " after a topological change: the frames keep their positions (SOFA's map would name "
                  "tetrahedra that no longer exist)");
    }
  }
  snapshot_.clear();
  actual_ = in_coord(kPosition);
  if (!frozen_) resize_output(map_.size());
}

void BarycentricMappingRigid::apply(int x) {
  follow_topology();
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  if (frozen_) return hold_output(x, *outp, *out_coord_read(kPosition));
  const std::vector<double>& in = in_coord(x);
  actual_ = in;  // SOFA's actualTetraPosition: J is taken at the last mapped positions
  std::vector<double>& out = *outp;
  out.resize(map_.size() * 7);
  const double* X = in.data();
  for (std::size_t i = 0; i < map_.size(); ++i) {
    const Embedding& e = map_[i];
    const Tetra& t = tetra_of(i);
    double w[4];
    bary_weights(e.bary, w);
    double* o = &out[i * 7];
    blend(t, w, X, o);
    // Axes carried by the deformed edge basis, then their closest rotation.
    double E[3][3];
    edge_basis(t, X, E);
    Mat3 A;
    for (int c = 0; c < 3; ++c) {
      double a[3];
      rigid_mul3(E, e.axis[c], a);
      for (int k = 0; k < 3; ++k) A(k, c) = a[k];
    }
    quat_from_matrix(polar_rotation(A)).store(o + 3);
  }
}

void BarycentricMappingRigid::apply_j(int v, int role) {
  follow_topology();
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  if (frozen_) {
    std::fill(outp->begin(), outp->end(), 0.0);
    return;
  }
  const std::vector<double>& in = in_deriv(v, role);
  std::vector<double>& out = *outp;
  out.resize(map_.size() * 6);
  const double* V = in.data();
  const double* X = actual_.data();
  for (std::size_t i = 0; i < map_.size(); ++i) {
    const Embedding& e = map_[i];
    const Tetra& t = tetra_of(i);
    double w[4];
    bary_weights(e.bary, w);
    double* o = &out[i * 6];
    blend(t, w, V, o);
    double omega[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      double c[3];
      rigid_cross3(X + t[k] * 3, V + t[k] * 3, c);
      omega[0] += c[0], omega[1] += c[1], omega[2] += c[2];
    }
    o[3] = omega[0], o[4] = omega[1], o[5] = omega[2];
  }
}

void BarycentricMappingRigid::apply_jt(int f, int role) {
  follow_topology();
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  double* F = in.data();
  const double* X = actual_.data();
  const std::size_t n = std::min(map_.size(), out.size() / 6);
  for (std::size_t i = 0; i < n; ++i) {
    const Embedding& e = map_[i];
    const Tetra& t = tetra_of(i);
    const double* fi = &out[i * 6];
    double w[4];
    bary_weights(e.bary, w);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) F[t[k] * 3 + c] += fi[c] * w[k];
    // The torque as forces: −x_k × τ on each vertex (the transpose of ω = Σ x_k × v_k).
    for (int k = 0; k < 4; ++k) {
      double c[3];
      rigid_cross3(X + t[k] * 3, fi + 3, c);
      for (int d = 0; d < 3; ++d) F[t[k] * 3 + d] -= c[d];
    }
  }
}

// Constraint rows keep their translation part only (SOFA's applyJT on constraint matrices).
void BarycentricMappingRigid::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (out_dof >= map_.size() || snapshot_.pending) return;
  const Embedding& e = map_[out_dof];
  const Tetra& t = tetra_of(out_dof);
  double w[4];
  bary_weights(e.bary, w);
  for (int k = 0; k < 4; ++k) {
    const double d[3] = {v[0] * w[k], v[1] * w[k], v[2] * w[k]};
    sink.add(0, t[k], d);
  }
}

bool BarycentricMappingRigid::jacobian(std::vector<JacobianEntry>& out) {
  follow_topology();
  const double* X = actual_.data();
  for (std::size_t i = 0; i < map_.size(); ++i) {
    const Embedding& e = map_[i];
    const Tetra& t = tetra_of(i);
    double w[4];
    bary_weights(e.bary, w);
    const std::uint32_t row = static_cast<std::uint32_t>(i * 6);
    for (std::uint32_t d = 0; d < 3; ++d)
      for (int k = 0; k < 4; ++k) out.push_back({0, row + d, t[k] * 3 + d, w[k]});
    // ω = x_k × v_k: the rows of [x_k]×, zeros included (a pattern independent of the positions).
    for (int k = 0; k < 4; ++k) {
      const double* x = X + t[k] * 3;
      const std::uint32_t col = t[k] * 3;
      const double m[3][3] = {{0, -x[2], x[1]}, {x[2], 0, -x[0]}, {-x[1], x[0], 0}};
      for (std::uint32_t a = 0; a < 3; ++a)
        for (std::uint32_t b = 0; b < 3; ++b)
          if (a != b) out.push_back({0, row + 3 + a, col + b, m[a][b]});
    }
  }
  return true;
}

}  // namespace sinew
