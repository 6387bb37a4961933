// TransformPosition: transforms 3-D points by one method (SOFA's
// Engine/Transform): projectOnPlane, translation, rotation (Euler degrees),
// scale (about `origin`), scaleTranslation, scaleRotationTranslation, affine
// (a 4x4 matrix, homogeneous divide) or fromFile (the affine matrix read from
// a .tfm, .trm, .xfm or .txt file at every update). `fixedIndices` keep their
// input coordinates. SOFA's `random` method needs SOFA's random generator and
// is refused with an error.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class TransformPosition final : public Engine {
 public:
  TransformPosition();

  Field<Vec3> origin{this, "origin", Vec3::Zero(), "a point of the plane / the centre of the scale", "Inputs",
                     "length"};
  Field<FlatVec> input_position;
  Field<FlatVec> output_position;
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "plane normal (normalised at init)", "Inputs"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation vector", "Inputs", "length"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation (Euler angles in degrees)", "Inputs", "degrees"};
  Field<Vec3> scale{this, "scale", Vec3::Ones(), "scale factors", "Inputs"};
  Field<VecN<16>> matrix;
  Field<std::string> method{this, "method", "projectOnPlane",
                            "projectOnPlane, translation, rotation, random, scale, scaleTranslation, "
                            "scaleRotationTranslation, affine or fromFile",
                            "Inputs"};
  Field<int> seed_value{this, "seedValue", 0, "seed of the random generator (random method)", "Inputs"};
  Field<double> max_random_displacement{this, "maxRandomDisplacement", 1.0,
                                        "largest displacement of the random method", "Inputs", "length"};
  Field<std::vector<unsigned>> fixed_indices{this, "fixedIndices", {}, "indices of the points left untransformed",
                                             "Inputs"};
  Field<std::string> filename{this, "filename", "",
                              "file of an affine matrix (fromFile): .tfm, .trm, .xfm or .txt (read as .xfm)",
                              "Inputs"};
  Field<bool> draw_input{this, "drawInput", false, "draw the input points (viewer)", "Visualization"};
  Field<bool> draw_output{this, "drawOutput", false, "draw the output points (viewer)", "Visualization"};
  Field<double> point_size{this, "pointSize", 1.0, "size of the drawn points (viewer)", "Visualization"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  enum class Method { project_on_plane, translation, rotation, random, scale, scale_translation,
                      scale_rotation_translation, affine };
  Method select_method();
  void read_tfm(const std::string& path);
  void read_trm(const std::string& path);
  void read_xfm(const std::string& path);
};

}  // namespace sinew
