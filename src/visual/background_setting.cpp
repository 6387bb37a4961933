// BackgroundSetting: the viewer's background colour (SOFA's default white when the component
// is present) or image. The renderer clears with the colour; the image is not drawn yet.
#include "visual/background_setting.h"

#include "core/registry.h"

namespace sinew {

void register_background_setting(Registry& r) {
  ComponentInfo info;
  info.name = "BackgroundSetting";
  info.category = "Visual";
  info.description = "background colour or image of the viewer (the colour is used by `sinew render`)";
  info.create = creator<BackgroundSetting>();
  r.add(std::move(info));
}

}  // namespace sinew
