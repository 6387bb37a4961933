// DataDisplay (SOFA's Sofa.GL.Component.Rendering3D): a visual state (a mapping
// moves its points) that colours its mesh by values: one per point
// (pointData), per triangle or quad (triangleData alias cellData, quadData), or
// per corner of each triangle or quad (pointTriangleData, pointQuadData),
// through an OglColorMap (`colorMap`, else the first one from its node up;
// without one, SOFA's default palette, HSV with 256 colours, and SOFA's warning).
//
// What SOFA's drawVisual computes before drawing is `update_range()`: the size
// checks (an error, and nothing coloured, when a list does not match the
// mesh), the value range (the last non-empty cell list wins, as in SOFA), the
// userRange clamp and the maximal range over time, written to currentMin and
// currentMax. As in SOFA these outputs move only when the picture is drawn
// (sinew run draws nothing: they stay 0 in batch runs).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/roles.h"
#include "visual/color.h"
#include "visual/rendering2d/ogl_color_map.h"

namespace sinew {

class DataDisplay final : public VisualState {
 public:
  DataDisplay();

  Field<FlatVec> position;
  Field<FlatVec> rest_position;
  Field<std::vector<Vec3>> normal{this, "normal", {}, "vertex normals", "Vector"};
  Field<bool> enable{this, "enable", true, "draw the data", "Visualization"};
  Field<bool> maximal_range{this, "maximalRange", true, "keep the widest range seen over all steps",
                            "Visualization"};
  Field<std::vector<double>> point_data{this, "pointData", {}, "one value per point", "Visualization"};
  Field<std::vector<double>> triangle_data{this, "triangleData", {}, "one value per triangle (alias cellData)",
                                           "Visualization"};
  Field<std::vector<double>> quad_data{this, "quadData", {}, "one value per quad", "Visualization"};
  Field<std::vector<double>> point_triangle_data{this, "pointTriangleData", {},
                                                 "three values per triangle (one per corner)", "Visualization"};
  Field<std::vector<double>> point_quad_data{this, "pointQuadData", {}, "four values per quad (one per corner)",
                                             "Visualization"};
  Field<std::string> color_nan{this, "colorNaN", "0 0 0 1", "colour of NaN values", "Visualization"};
  Field<Vec2> user_range{this, "userRange", Vec2(1, -1), "clamp the range to [min, max] when min < max",
                         "Visualization"};
  Field<double> current_min{this, "currentMin", 0.0, "lower end of the range last drawn (output)",
                            "Visualization"};
  Field<double> current_max{this, "currentMax", 0.0, "upper end of the range last drawn (output)",
                            "Visualization"};
  Field<double> shininess{this, "shininess", -1.0, "specular exponent for point data [0, 128]; < 0: none",
                          "Visualization"};
  Field<double> transparency{this, "transparency", 1.0, "opacity of the coloured faces (1: opaque)",
                             "Visualization"};
  Link<OglColorMap> color_map{this, "colorMap", "colour map (default: the first OglColorMap from the node up)"};
  Link<MeshTopologyBase> topology{this, "topology", "mesh whose faces are coloured (default: the node's)"};

  std::size_t visual_size() const override { return position.value().size(); }
  void visual_resize(std::size_t n) override { position.edit().data.resize(n * 3, 0.0); }
  std::vector<double>* visual_vec(int id) override;

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;

  // What the next picture shows (SOFA's drawVisual up to the drawing itself).
  struct Range {
    bool point_data = false;  // pointData matches the points
    bool cell_data = false;   // a cell list matches the mesh
    double min = 0, max = 0;
  };
  Range update_range();

  // The colour of value v in [min, max] (colorNaN for NaN), with the transparency as alpha.
  Rgba color_of(double v, double min, double max) const;
  const MeshTopologyBase* mesh() const { return topology.get(); }

 private:
  void report(const std::string& text);

  double old_min_ = std::numeric_limits<double>::max();
  double old_max_ = std::numeric_limits<double>::lowest();
  std::vector<Rgba> default_palette_;  // without an OglColorMap
  Rgba nan_color_{0, 0, 0, 1};
  std::string last_error_;
};

}  // namespace sinew
