// OglColorMap (SOFA's Sofa.GL.Component.Rendering2D): a colour palette that
// other visual components (DataDisplay) use to turn values into colours, and a
// legend drawn over the picture when showLegend (render/draw_text.h).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

class OglColorMap final : public VisualComponent {
 public:
  Field<unsigned> palette_size{this, "paletteSize", 256u, "how many colours the palette has (>= 2)",
                               "Visualization"};
  Field<std::string> color_scheme{this, "colorScheme", "HSV",
                                  "colour scheme: Red to Blue, Blue to Red, HSV, Red, Green, Blue, Yellow to Cyan, "
                                  "Cyan to Yellow, Red to Yellow, Yellow to Red, Yellow to Green, Green to Yellow, "
                                  "Green to Cyan, Cyan to Green, Cyan to Blue, Blue to Cyan, BlueInv, GreenInv, "
                                  "RedInv, Custom",
                                  "Visualization"};
  Field<bool> show_legend{this, "showLegend", false, "draw the colour scale over the picture", "Visualization"};
  Field<Vec2> legend_offset{this, "legendOffset", Vec2(10, 5), "legend position on screen (pixels)",
                            "Visualization"};
  Field<std::string> legend_title{this, "legendTitle", "", "title of the legend", "Visualization"};
  Field<unsigned> legend_size{this, "legendSize", 11u, "font size of the legend", "Visualization"};
  Field<double> min{this, "min", 0.0, "value written at the bottom of the legend", "Visualization"};
  Field<double> max{this, "max", 0.0, "value written at the top of the legend", "Visualization"};
  Field<double> legend_range_scale{this, "legendRangeScale", 1.0, "factor applied to min and max in the legend",
                                   "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;

  // The palette for the current colorScheme and paletteSize (rebuilt when either changed).
  const std::vector<Rgba>& palette() const;

 private:
  mutable std::vector<Rgba> palette_;
  mutable std::uint64_t scheme_version_ = ~0ull, size_version_ = ~0ull;
};

}  // namespace sinew
