// Mappings in pictures (display flag showMappings), as SOFA's mappings draw
// themselves: the output points of BarycentricMapping, RigidMapping,
// BeamLinearMapping and DeformableOnRigidFrameMapping as yellow 7-pixel points;
// for BarycentricMapping, also a green line from each output point to every
// input vertex that carries it with a weight of at least 1e-4 (SOFA's mappers'
// draw). SOFA reads showMappings (not showMechanicalMappings) for mechanical and
// visual mappings alike. SkinningMapping draws a line from each frame's centre to
// each point it moves, coloured (w, w, 0) by the weight; HexahedronCompositeFEMMapping
// its fine grid points, light green, 7 px.
#include <cmath>
#include <cstring>

#include "core/node.h"
#include "mapping/linear/barycentric_mapping.h"
#include "mapping/linear/hexahedron_composite_fem_mapping.h"
#include "mapping/linear/skinning_mapping.h"
#include "render/draw_collision.h"
#include "visual/visual_style.h"

namespace sinew::render {

namespace {

// The output's points as floats (xyz), from its state or its visual model; false without any.
bool output_points(const Mapping& m, std::vector<float>& out) {
  out.clear();
  if (const MechanicalState* s = m.output()) {
    const int w = s->info().coord_width, dim = std::min(3, s->info().spatial_dim);
    if (w <= 0 || dim <= 0) return false;
    const std::vector<double>& x = s->read(kPosition);
    for (std::size_t i = 0; i + w <= x.size(); i += w)
      for (int c = 0; c < 3; ++c) out.push_back(c < dim ? static_cast<float>(x[i + c]) : 0.f);
    return true;
  }
  if (VisualState* v = m.visual_output()) {
    if (const std::vector<double>* x = v->visual_vec(kPosition)) {
      for (double d : *x) out.push_back(static_cast<float>(d));
      out.resize(out.size() / 3 * 3);
      return true;
    }
  }
  return false;
}

bool draws_points(const std::string& cls) {
  return cls == "BarycentricMapping" || cls == "RigidMapping" || cls == "BeamLinearMapping" ||
         cls == "DeformableOnRigidFrameMapping";
}

// SOFA's SkinningMapping::draw: frame centre → point, (w, w, 0), for the point's frames of weight > 0.
void skinning_lines(DrawList& list, const SkinningMapping& m, const std::vector<float>& pts) {
  const std::vector<MechanicalState*> in = m.inputs();
  if (in.empty() || !in[0] || in[0]->info().coord_width != 7) return;
  const std::vector<double>& frames = in[0]->read(kPosition);
  const std::vector<unsigned>& index = m.frame_index();
  const std::vector<double>& w = m.weights();
  const std::vector<unsigned>& count = m.counts();
  const std::size_t slots = m.slots();
  Batch& b = fresh_batch(list, &m, Batch::Kind::lines);
  for (std::size_t i = 0; i < pts.size() / 3 && i < count.size(); ++i)
    for (std::size_t k = 0; k < count[i] && i * slots + k < w.size(); ++k) {
      const double wk = w[i * slots + k];
      const std::size_t f = index[i * slots + k];
      if (!(wk > 0.0)) break;
      if (7 * f + 2 >= frames.size()) continue;
      for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(frames[7 * f + c]));
      b.positions.insert(b.positions.end(), &pts[3 * i], &pts[3 * i] + 3);
      const float rgba[4] = {static_cast<float>(wk), static_cast<float>(wk), 0.f, 1.f};
      for (int e = 0; e < 2; ++e) b.colors.insert(b.colors.end(), rgba, rgba + 4);
    }
  close_batch(list, b);
}

}  // namespace

void add_mappings(DrawList& list, Node& node) {
  thread_local std::vector<float> pts;
  for (const auto& o : node.objects()) {
    auto* m = dynamic_cast<Mapping*>(o.get());
    if (!m || m->state() != ComponentState::valid) continue;
    if (const auto* comp = dynamic_cast<const HexahedronCompositeFEMMapping*>(m)) {
      Batch& b = fresh_batch(list, m, Batch::Kind::points);
      for (const Vec3& q : comp->fine_points())
        for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(q[c]));
      b.shading.diffuse = {0.2f, 1.f, 0.f, 1.f};
      b.point_size = 7.f;
      close_batch(list, b);
      continue;
    }
    if (const auto* skin = dynamic_cast<const SkinningMapping*>(m)) {
      if (output_points(*m, pts)) skinning_lines(list, *skin, pts);
      continue;
    }
    if (!draws_points(m->class_name())) continue;
    if (!output_points(*m, pts) || pts.empty()) continue;
    Batch& b = fresh_batch(list, m, Batch::Kind::points);
    b.positions = pts;
    b.shading.diffuse = {1, 1, 0, 1};
    b.point_size = 7.f;
    close_batch(list, b);

    const auto* bary = dynamic_cast<const BarycentricMapping*>(m);
    const std::vector<MechanicalState*> in = m->inputs();
    if (!bary || in.empty() || !in[0] || in[0]->info().coord_width != 3) continue;
    const std::vector<double>& x = in[0]->read(kPosition);
    const BaryTable& t = bary->drawn_table();
    Batch& lines = fresh_batch(list, m, Batch::Kind::lines);
    const std::size_t n = std::min(t.points(), pts.size() / 3);
    for (std::size_t i = 0; i < n; ++i)
      for (std::uint32_t k = t.begin(i); k < t.end(i); ++k) {
        const double w = t.weight(k);
        const std::size_t v = t.vertex(k);
        if (!(w <= -0.0001 || w >= 0.0001) || 3 * v + 2 >= x.size()) continue;
        lines.positions.insert(lines.positions.end(), &pts[3 * i], &pts[3 * i] + 3);
        for (int c = 0; c < 3; ++c) lines.positions.push_back(static_cast<float>(x[3 * v + c]));
      }
    lines.shading.diffuse = {0, 1, 0, 1};
    close_batch(list, lines);
  }
}

}  // namespace sinew::render
