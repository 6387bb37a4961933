// VisualModelOBJExporter (SOFA's Sofa.Component.IO.Mesh; spec/user-interfaces.md §4.3): every
// visual model (OglModel) of this node and below as one Wavefront OBJ with its MTL materials.
//
// Files: `<filename>.obj` and `<filename>.mtl` (a filename ending in ".obj" keeps it), with the
// export index on 5 digits before the extension when exportEveryNumberOfSteps is set.
// Each model is a group "g <k>_<name>" (k counts the models, top-down) with its material,
// its vertices ("v", 6 decimals as SOFA), normals ("vn"), texture coordinates ("vt") and
// faces "f p//n" (or "p/t/n" with texture coordinates), indices running on across models.
// Deliberate differences from SOFA: the OBJ names its MTL (`mtllib`), which SOFA leaves out
// so that viewers miss the colours; materials are named "mat<k>" with the model's number
// (SOFA restarts its count in every node, so two nodes give two "mat1").
#pragma once

#include "exporter/simulation_exporter.h"

namespace sinew {

class VisualModelOBJExporter final : public SimulationExporter {
 public:
  bool write() override;
  // Paths of the last export.
  const std::string& obj_path() const { return obj_path_; }
  const std::string& mtl_path() const { return mtl_path_; }

 private:
  std::string obj_path_, mtl_path_;
};

}  // namespace sinew
