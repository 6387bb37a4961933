// BackgroundSetting (Sofa.GL.Component / SofaGLFW): the viewer's background.
#pragma once

#include "core/roles.h"

namespace sinew {

class BackgroundSetting final : public VisualComponent {
 public:
  // Kept as text: SOFA's RGBAColor (a name, #rrggbb or 3–4 numbers), read by the renderer.
  Field<std::string> color{this, "color", "1 1 1 1", "background colour", "Display"};
  Field<std::string> image{this, "image", "", "background image file (tiled at its size, as SofaGLFW draws it)",
                           "Display"};
  BackgroundSetting() { image.set_file(true, false); }  // resolved like meshes; missing: a warning
  void init() override;
  // The image file was found at init (else the colour is used).
  bool image_found() const { return image_found_; }

 private:
  bool image_found_ = false;
};

}  // namespace sinew
