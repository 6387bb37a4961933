// CylinderVisualModel (SOFA's Sofa.Component.Visual): a visual state (so a
// mapping may move its points) drawn as one cylinder per edge. A viewer-side
// component: batch runs keep its positions up to date and check its inputs.
#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

namespace {

FlatVec empty3() {
  FlatVec v;
  v.width = 3;
  return v;
}

class CylinderVisualModel final : public VisualState {
 public:
  Field<FlatVec> position{this, "position", empty3(), "positions of the cylinder ends", "Vector", "length"};
  Field<FlatVec> rest_position{this, "restPosition", empty3(), "rest positions", "Vector", "length"};
  Field<double> radius{this, "radius", 1.0, "radius of the cylinders", "Visualization", "length"};
  Field<std::string> color{this, "color", "white", "colour of the cylinders", "Visualization"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "one cylinder per edge (two position indices)", "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the cylinders", "Visualization"};

  std::size_t visual_size() const override { return position.value().size(); }
  void visual_resize(std::size_t n) override { position.edit().data.resize(n * 3, 0.0); }
  std::vector<double>* visual_vec(int id) override {
    if (id == kRestPosition) return &rest_position.edit().data;
    if (id == kPosition || id >= kFirstDynamicVec) return &position.edit().data;
    return nullptr;
  }

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    check_color_field(*this, color, diag);
    if (!(radius.value() > 0.0)) diag.error(where, describe() + ": radius must be positive");
  }

  void init() override {
    const std::size_t n = position.get().size();
    for (const Edge& e : edges.get())
      if (e[0] >= n || e[1] >= n) {
        msg_error("edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ") refers past the " +
                  std::to_string(n) + " positions");
        set_state(ComponentState::invalid);
        return;
      }
  }
};

}  // namespace

void register_cylinder_visual_model(Registry& r) {
  ComponentInfo info;
  info.name = "CylinderVisualModel";
  info.category = "Visual";
  info.description = "draws a cylinder along each edge (viewer only)";
  info.create = creator<CylinderVisualModel>();
  r.add(std::move(info));
}

}  // namespace sinew
