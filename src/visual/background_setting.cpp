// BackgroundSetting: the viewer's background colour (SOFA's default white when the component
// is present) or image (SofaGLFWWindow::drawBackgroundImage: the picture tiled at its own
// pixel size from the bottom-left corner, under the scene; the colour is then unused).
#include "visual/background_setting.h"

#include <fstream>

#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

void BackgroundSetting::init() {
  // SOFA logs the failed load and keeps the previous background; the scene runs.
  const std::string& file = image.get();
  image_found_ = !file.empty() && std::ifstream(file).good();
  if (!file.empty() && !image_found_)
    msg_warning("background image " + quote_value(file) + " not found: the background colour is used");
}

void register_background_setting(Registry& r) {
  ComponentInfo info;
  info.name = "BackgroundSetting";
  info.category = "Visual";
  info.description = "background colour or image of the viewer and of `sinew render`";
  info.create = creator<BackgroundSetting>();
  r.add(std::move(info));
}

}  // namespace sinew
