// Components that only matter to a viewer (styles, grids, frames,
// labels, backgrounds). They load without error and do nothing in batch
// runs; their attributes are accepted as they are.
#include "core/registry.h"
#include "core/roles.h"

namespace sinew {

namespace {
class ViewerOnly final : public VisualComponent {
 public:
  bool accepts_any_attribute() const override { return true; }
};
}  // namespace

void register_viewer_only(Registry& r) {
  const struct {
    const char* name;
    const char* what;
  } list[] = {
      {"DefaultVisualManagerLoop", "visual update loop of the viewer"},
      {"VisualGrid", "reference grid drawn by the viewer"},
      {"OglSceneFrame", "axes drawn in a corner of the viewer"},
      {"LineAxis", "axes drawn by the viewer"},
      {"OglLabel", "text label drawn by the viewer"},
      {"Visual3DText", "3D text drawn by the viewer"},
      {"ViewerSetting", "viewer window settings (resolution, fullscreen, picking method)"},
      {"GlobalSystemMatrixImage", "image of a linear system's matrix (SofaMatrix plugin)"},
      {"TrailRenderer", "trail of past positions drawn by the viewer"},
      {"StatsSetting", "statistics the GUI application prints or exports"},
      {"SofaDefaultPathSetting", "folders where the GUI application saves records and plots"},
  };
  for (const auto& e : list) {
    ComponentInfo info;
    info.name = e.name;
    info.category = "Visual";
    info.description = std::string(e.what) + " (viewer only; no effect in batch runs)";
    info.create = creator<ViewerOnly>();
    r.add(std::move(info));
  }
}

}  // namespace sinew
