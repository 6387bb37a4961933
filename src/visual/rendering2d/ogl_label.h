// OglLabel (SOFA's Sofa.GL.Component.Rendering2D): a line of text at a pixel position of the
// picture, drawn by src/render with SOFA's ASCII font texture (render/draw_text.h).
#pragma once

#include <string>

#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

class OglLabel final : public VisualComponent {
 public:
  OglLabel() { listening.set(true); }

  Field<std::string> prefix{this, "prefix", "", "text before the label", "Visualization"};
  Field<std::string> label{this, "label", "", "the text", "Visualization"};
  Field<std::string> suffix{this, "suffix", "", "text after the label", "Visualization"};
  Field<unsigned> x{this, "x", 10u, "horizontal position of the text's left edge (pixels from the left)",
                    "Visualization"};
  Field<unsigned> y{this, "y", 10u, "vertical position of the text's top (pixels from the top)", "Visualization"};
  Field<unsigned> fontsize{this, "fontsize", 14u, "font size: a glyph is fontsize pixels wide, twice as high",
                           "Visualization"};
  Field<std::string> color{this, "color", "gray", "colour of the text", "Visualization"};
  Field<bool> select_contrasting_color{this, "selectContrastingColor", false,
                                       "black or white, whichever contrasts with the BackgroundSetting's colour",
                                       "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the text", "Visualization"};
  Field<unsigned> update_label_every_nb_steps{this, "updateLabelEveryNbSteps", 0u,
                                              "0: the label shown is always the current one; N: it is read again "
                                              "once every N + 1 steps",
                                              "Visualization"};

  // color="contrast" is SOFA's old spelling of selectContrastingColor="true".
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override { reinit(); }
  void reinit() override;
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;

  // What is drawn: prefix + the label as last read + suffix (into `out`, its storage reused).
  void text(std::string& out) const;
  std::string text() const {
    std::string s;
    text(s);
    return s;
  }
  // The colour drawn (the contrasting one when selected).
  const Rgba& shown_color() const { return color_; }

 private:
  std::string internal_label_;
  unsigned step_counter_ = 0;
  Rgba color_{0.5f, 0.5f, 0.5f, 1.f};
};

}  // namespace sinew
