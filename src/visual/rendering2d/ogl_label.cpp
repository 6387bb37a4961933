#include "visual/rendering2d/ogl_label.h"

#include "core/node.h"
#include "core/registry.h"
#include "visual/background_setting.h"

namespace sinew {

void OglLabel::parse(AttributeMap& attrs, Diagnostics& diag) {
  if (const std::string* c = attrs.peek("color"); c && *c == "contrast") {
    attrs.take("color");
    attrs.set("selectContrastingColor", "true");
    diag.warning(where, describe() +
                            ": color='contrast' is deprecated (SOFA v17.06); use selectContrastingColor='true'");
  }
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
}

void OglLabel::reinit() {
  if (select_contrasting_color.is_set() && color.is_set())
    msg_warning("selectContrastingColor and color are both set: the contrasting colour overrides color");
  internal_label_ = label.get();
  step_counter_ = 0;
  color_ = parse_rgba(color.get()).value_or(Rgba{0.5f, 0.5f, 0.5f, 1.f});
  if (!select_contrasting_color.get()) return;
  // SOFA's rule: the background's luma (YIQ's Y on 0..255) decides between black and white;
  // white when the scene has no BackgroundSetting.
  Node* n = node();
  const BackgroundSetting* bg = n ? n->root()->find_down<BackgroundSetting>() : nullptr;
  color_ = {1.f, 1.f, 1.f, 1.f};
  if (!bg) return;
  const Rgba b = parse_rgba(bg->color.get()).value_or(Rgba{1.f, 1.f, 1.f, 1.f});
  const float yiq = (b[0] * 255 * 299 + b[1] * 255 * 587 + b[2] * 255 * 114) / 1000;
  if (yiq >= 128) color_ = {0.f, 0.f, 0.f, 1.f};
}

void OglLabel::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  const unsigned every = update_label_every_nb_steps.get();
  if (every == 0) return;
  if (++step_counter_ > every) {
    step_counter_ = 0;
    internal_label_ = label.get();
  }
}

void OglLabel::text(std::string& out) const {
  // Without updateLabelEveryNbSteps SOFA reads the label at every visual update.
  const std::string& shown = update_label_every_nb_steps.get() ? internal_label_ : label.get();
  out.assign(prefix.get()).append(shown).append(suffix.get());
}

void register_ogl_label(Registry& r) {
  ComponentInfo info;
  info.name = "OglLabel";
  info.category = "Visual";
  info.description = "a line of text at a pixel position of the picture";
  info.create = creator<OglLabel>();
  r.add(std::move(info));
}

}  // namespace sinew
