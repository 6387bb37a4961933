// AddDataRepository: adds a folder to the data paths while the scene is read
// (SOFA's SceneUtility). The work is done by the scene builder
// (scene/builder.cpp, add_data_repository) when it creates this component:
// the folder (relative to the scene file's folder) must exist; files named
// by the components after it are then also searched there, last.
#include "core/component.h"
#include "core/registry.h"

namespace sinew {

namespace {
class AddDataRepository final : public Component {
 public:
  Field<std::string> path{this, "path", "", "folder added to the data paths", "Infos"};
};
}  // namespace

void register_add_data_repository(Registry& r) {
  ComponentInfo info;
  info.name = "AddDataRepository";
  info.category = "SceneUtility";
  info.description = "adds a folder to the data paths at load time";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<AddDataRepository>(); };
  r.add(std::move(info));
}

}  // namespace sinew
