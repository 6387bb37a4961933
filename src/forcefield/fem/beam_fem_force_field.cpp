#include "forcefield/fem/beam_fem_force_field.h"

#include <cmath>
#include <string>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

using beam::Quat;
using beam::V3;

namespace {

inline Quat orientation(const std::vector<double>& x, unsigned i) {
  return {x[i * 7 + 3], x[i * 7 + 4], x[i * 7 + 5], x[i * 7 + 6]};
}
inline V3 center_diff(const std::vector<double>& x, unsigned b, unsigned a) {
  return {x[b * 7] - x[a * 7], x[b * 7 + 1] - x[a * 7 + 1], x[b * 7 + 2] - x[a * 7 + 2]};
}

// Initial beam frame (SOFA initLarge): node a's orientation turned halfway
// towards node b's. add_force replaces it by node a's orientation.
Quat mid_frame(const std::vector<double>& x, unsigned a, unsigned b) {
  Quat qa = orientation(x, a), qb = orientation(x, b);
  beam::qnormalize(qa);
  beam::qnormalize(qb);
  Quat dq = beam::qdiff(qb, qa);
  beam::qnormalize(dq);
  V3 w = beam::rotation_vector(dq);
  const double theta = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (theta > 0.0000001) {
    // The rotation vector is normalised first; axis_angle normalises again (no-op).
    w = {w[0] / theta, w[1] / theta, w[2] / theta};
    Quat q = beam::qmul(qa, beam::axis_angle(w, theta / 2));
    beam::qnormalize(q);
    return q;
  }
  return qa;
}

}  // namespace

void BeamFEMForceField::init() {
  ForceField::init();
  beams_.clear();
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  if (s.state_type() != StateType::rigid3) {
    msg_error(std::string("beams need a Rigid3d state, not ") + s.info().name);
    set_state(ComponentState::invalid);
    return;
  }
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found: the beams are the edges of a topology (MeshTopology, EdgeSetTopologyContainer)");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Edge>& edges = topology->edges();
  if (edges.empty()) {
    msg_error("the topology has no edges: there is no beam");
    set_state(ComponentState::invalid);
    return;
  }
  const double r = radius.get(), ri = radius_inner.get();
  if (!(r > 0.0) || !std::isfinite(r) || !(ri >= 0.0) || !(ri < r)) {
    msg_error("bad cross-section: radius = " + std::to_string(r) + ", radiusInner = " + std::to_string(ri) +
              " (need radius > 0 and 0 <= radiusInner < radius)");
    set_state(ComponentState::invalid);
    return;
  }

  // The edges visited, in SOFA's order: listSegment when all its indices are edges.
  std::vector<unsigned> visit = list_segment.get();
  for (unsigned i : visit)
    if (i >= edges.size()) {
      msg_warning("listSegment refers to edge " + std::to_string(i) + " but the topology has " +
                  std::to_string(edges.size()) + " edges: the force field applies to all edges");
      visit.clear();
      break;
    }
  partial_ = !visit.empty();
  if (visit.empty()) {
    visit.resize(edges.size());
    for (unsigned i = 0; i < edges.size(); ++i) visit[i] = i;
  }

  const std::size_t n = s.size();
  const std::vector<double>& x0 = s.read(kRestPosition);
  const std::vector<double>& x = s.read(kPosition);
  beams_.reserve(visit.size());
  for (unsigned ei : visit) {
    const unsigned a = edges[ei][0], b = edges[ei][1];
    if (a >= n || b >= n) {
      msg_error("edge " + std::to_string(ei) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                ") refers to a point beyond the state size " + std::to_string(n));
      beams_.clear();
      set_state(ComponentState::invalid);
      return;
    }
    const V3 d = center_diff(x0, a, b);
    const double L = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(L > 0.0)) {
      msg_error("edge " + std::to_string(ei) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                ") has zero rest length");
      beams_.clear();
      set_state(ComponentState::invalid);
      return;
    }
    Beam bm;
    bm.a = a, bm.b = b;
    bm.section = beam::make_section(young_modulus.get(), L, poisson_ratio.get(), r, ri);
    bm.k = beam::local_stiffness(bm.section);
    bm.q = mid_frame(x, a, b);
    beams_.push_back(bm);
  }
}

void BeamFEMForceField::add_force(const MechParams& p) {
  if (beams_.empty()) return;
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& x0 = s.read(kRestPosition);
  std::vector<double>& f = s.write(p.f);
  double depl[12], force[12];
  for (Beam& bm : beams_) {
    const unsigned a = bm.a, b = bm.b;
    const Quat qa = orientation(x, a);  // SOFA rotates with the unnormalised orientation here
    bm.q = qa;
    beam::qnormalize(bm.q);

    // Translation of b in a's frame, relative to the rest one.
    const V3 p0 = beam::qinverse_rotate(orientation(x0, a), center_diff(x0, b, a));
    const V3 p1 = beam::qinverse_rotate(qa, center_diff(x, b, a));
    // Rotation of b relative to a, relative to the rest one.
    Quat dq0 = beam::qdiff(orientation(x0, b), orientation(x0, a));
    Quat dq = beam::qdiff(orientation(x, b), qa);
    beam::qnormalize(dq0);
    beam::qnormalize(dq);
    Quat t = beam::qdiff(dq, dq0);
    beam::qnormalize(t);
    const V3 th = beam::rotation_vector(t);

    for (int c = 0; c < 6; ++c) depl[c] = 0.0;
    for (int c = 0; c < 3; ++c) depl[6 + c] = p1[c] - p0[c], depl[9 + c] = th[c];
    beam::mat12_mul(bm.k, depl, force);

    for (int blk = 0; blk < 4; ++blk) {
      const V3 w = beam::qrotate(qa, {force[blk * 3], force[blk * 3 + 1], force[blk * 3 + 2]});
      double* fo = &f[(blk < 2 ? a : b) * 6 + (blk % 2) * 3];
      fo[0] += -w[0], fo[1] += -w[1], fo[2] += -w[2];
    }
  }
}

void BeamFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  if (beams_.empty()) return;
  MechanicalState& s = *mstate;
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  double d[12], fl[12];
  for (Beam& bm : beams_) {
    beam::qnormalize(bm.q);
    const Quat& q = bm.q;
    for (int blk = 0; blk < 4; ++blk) {
      const double* v = &dx[(blk < 2 ? bm.a : bm.b) * 6 + (blk % 2) * 3];
      const V3 u = beam::qinverse_rotate(q, {v[0], v[1], v[2]});
      d[blk * 3] = u[0], d[blk * 3 + 1] = u[1], d[blk * 3 + 2] = u[2];
    }
    beam::mat12_mul(bm.k, d, fl);
    for (int blk = 0; blk < 4; ++blk) {
      const V3 w = beam::qrotate(q, {fl[blk * 3], fl[blk * 3 + 1], fl[blk * 3 + 2]});
      double* o = &df[(blk < 2 ? bm.a : bm.b) * 6 + (blk % 2) * 3];
      o[0] += -w[0] * kfactor, o[1] += -w[1] * kfactor, o[2] += -w[2] * kfactor;
    }
  }
}

bool BeamFEMForceField::build_stiffness(MatrixSink& K) {
  if (beams_.empty()) return true;
  const MechanicalState* s = mstate.get();
  const bool sym = use_symmetric_assembly.get() && !partial_;
  double Kg[12][12];
  for (Beam& bm : beams_) {
    beam::qnormalize(bm.q);
    const std::array<double, 9> R = beam::qmatrix(bm.q);
    // Block (x1, y1) of the world stiffness: R·K0_block·Rᵀ.
    auto block = [&](int x1, int y1, double m[3][3]) {
      double t[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double acc = R[i * 3] * bm.k[x1 * 12 + y1 + j];
          for (int k = 1; k < 3; ++k) acc += R[i * 3 + k] * bm.k[(x1 + k) * 12 + y1 + j];
          t[i][j] = acc;
        }
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double acc = t[i][0] * R[j * 3];
          for (int k = 1; k < 3; ++k) acc += t[i][k] * R[j * 3 + k];
          m[i][j] = acc;
        }
    };
    double m[3][3];
    if (sym) {
      // Upper block triangle mirrored, diagonal blocks averaged with their transpose.
      for (auto& row : Kg)
        for (double& v : row) v = 0.0;
      for (int x1 = 0; x1 < 12; x1 += 3)
        for (int y1 = x1; y1 < 12; y1 += 3) {
          block(x1, y1, m);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              Kg[i + x1][j + y1] += m[i][j];
              Kg[j + y1][i + x1] += m[i][j];
            }
          if (x1 == y1)
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) Kg[i + x1][j + y1] *= 0.5;
        }
    } else {
      for (int x1 = 0; x1 < 12; x1 += 3)
        for (int y1 = 0; y1 < 12; y1 += 3) {
          block(x1, y1, m);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) Kg[x1 + i][y1 + j] = m[i][j];
        }
    }
    std::size_t idx[12];
    for (int c = 0; c < 6; ++c) idx[c] = bm.a * 6 + c, idx[6 + c] = bm.b * 6 + c;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) K.add(s, idx[i], s, idx[j], -Kg[i][j]);
  }
  return true;
}

void register_beam_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "BeamFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "3D beam finite elements (axial, bending, torsion) on the edges of a topology, Rigid3d frames";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.requirement = Requirement::state;
  info.create = creator<BeamFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
