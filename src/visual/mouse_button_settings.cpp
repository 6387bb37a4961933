// Mouse settings of SOFA's GUI (ConfigurationSetting components): they only
// choose what a mouse button does in an interactive viewer (attach a spring,
// or a Lagrangian attachment with ConstraintAttachButtonSetting,
// spec/interaction.md §5.7). A batch run has no mouse: their Data are read and
// checked so a scene loads exactly as in SOFA, and nothing else happens.
#include <string>

#include "core/registry.h"
#include "core/roles.h"
#include "core/value_text.h"

namespace sinew {

namespace {

// SOFA's MouseButtonSetting: the button the operation is bound to.
class MouseButtonSetting : public VisualComponent {
 public:
  Field<std::string> button{this, "button", "Left", "mouse button used: Left, Middle or Right", "Setting"};

  void init() override {
    const std::string& b = button.value();
    // SOFA's OptionsGroup keeps its previous choice when given an unknown name.
    if (b != "Left" && b != "Middle" && b != "Right" && b != "0" && b != "1" && b != "2") {
      msg_warning("button " + quote_value(b) + " is not Left, Middle or Right: Left is used");
      button.set("Left");
    }
  }
};

// Left button attaches with a Lagrangian (bilateral) constraint.
class ConstraintAttachButtonSetting final : public MouseButtonSetting {};

// Left button attaches with a spring.
class AttachBodyButtonSetting final : public MouseButtonSetting {
 public:
  Field<double> stiffness{this, "stiffness", 1000.0, "stiffness of the spring that attaches a particle", "Setting",
                          "force/length"};
  Field<double> arrow_size{this, "arrowSize", 0.0, "size of the drawn spring (> 0: drawn as an arrow)", "Setting",
                           "length"};
  Field<double> show_factor_size{this, "showFactorSize", 1.0,
                                 "display scale of the joint spring when attaching rigids", "Setting"};

  void init() override {
    MouseButtonSetting::init();
    if (stiffness.value() < 0.0) msg_warning("stiffness is negative: the mouse spring would push away");
  }
};

// Left button pins the picked particle with a spring.
class FixPickedParticleButtonSetting final : public MouseButtonSetting {
 public:
  Field<double> stiffness{this, "stiffness", 10000.0, "stiffness of the spring that fixes a particle", "Setting",
                          "force/length"};
};

}  // namespace

void register_mouse_button_settings(Registry& r) {
  {
    ComponentInfo info;
    info.name = "ConstraintAttachButtonSetting";
    info.category = "Setting";
    info.description = "mouse attaches with a Lagrangian constraint (viewer only; no effect in batch runs)";
    info.create = creator<ConstraintAttachButtonSetting>();
    r.add(std::move(info));
  }
  {
    ComponentInfo info;
    info.name = "AttachBodyButtonSetting";
    info.category = "Setting";
    info.description = "mouse attaches with a spring (viewer only; no effect in batch runs)";
    info.create = creator<AttachBodyButtonSetting>();
    r.add(std::move(info));
  }
  {
    ComponentInfo info;
    info.name = "FixPickedParticleButtonSetting";
    info.category = "Setting";
    info.description = "mouse pins the picked particle with a spring (viewer only; no effect in batch runs)";
    info.create = creator<FixPickedParticleButtonSetting>();
    r.add(std::move(info));
  }
}

}  // namespace sinew
