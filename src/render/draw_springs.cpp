// Springs in pictures, as SOFA's SpringForceField::draw: one line per enabled spring between
// its ends, drawn with showForceFields when both ends are in one state, with
// showInteractionForceFields when they join two states. Colours tell compressed springs
// (length below 0.9999 of the rest length) from the others: red / green between two states,
// orange / spring green within one.
#include "core/node.h"
#include "forcefield/spring/spring_force_field.h"
#include "render/draw_collision.h"
#include "visual/visual_style.h"

namespace sinew::render {

namespace {

bool end_point(const MechanicalState& s, unsigned i, float out[3]) {
  const int w = s.info().coord_width, dim = std::min(3, s.info().spatial_dim);
  const std::vector<double>& x = s.read(kPosition);
  if (w <= 0 || std::size_t(i) * w + dim > x.size()) return false;
  for (int c = 0; c < 3; ++c) out[c] = c < dim ? static_cast<float>(x[std::size_t(i) * w + c]) : 0.f;
  return true;
}

}  // namespace

void add_springs(DrawList& list, Node& node, const DisplayFlags& flags) {
  for (const auto& o : node.objects()) {
    const auto* ff = dynamic_cast<const SpringForceField*>(o.get());
    if (!ff || ff->state() != ComponentState::valid) continue;
    const std::vector<MechanicalState*> st = ff->states();
    if (st.empty() || !st.front() || !st.back()) continue;
    const MechanicalState& s1 = *st.front();
    const MechanicalState& s2 = *st.back();
    const bool external = &s1 != &s2;
    if (!flags.shown(external ? DisplayFlags::interaction_force_fields : DisplayFlags::force_fields)) continue;
    static const float kCompressed[2][4] = {{1, 0.5f, 0, 1}, {1, 0, 0, 1}};  // [external]
    static const float kStretched[2][4] = {{0, 1, 0.5f, 1}, {0, 1, 0, 1}};
    Batch& b = fresh_batch(list, ff, Batch::Kind::lines);
    for (const auto* springs : {&ff->spring_list(), &ff->grid_springs()})
      for (const springs::LinearSpring& sp : *springs) {
        if (!sp.enabled) continue;
        float a[3], c[3];
        if (!end_point(s1, sp.m1, a) || !end_point(s2, sp.m2, c)) continue;
        const float d = std::sqrt((a[0] - c[0]) * (a[0] - c[0]) + (a[1] - c[1]) * (a[1] - c[1]) +
                                  (a[2] - c[2]) * (a[2] - c[2]));
        const float* rgba = d < sp.l0 * 0.9999 ? kCompressed[external] : kStretched[external];
        b.positions.insert(b.positions.end(), a, a + 3);
        b.positions.insert(b.positions.end(), c, c + 3);
        for (int k = 0; k < 2; ++k) b.colors.insert(b.colors.end(), rgba, rgba + 4);
      }
    close_batch(list, b);
  }
}

}  // namespace sinew::render
