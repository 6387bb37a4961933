// IdentityMultiMapping: the concatenation of its inputs, every point of the first input,
// then of the second, ... (a GatherMultiMapping, see subset_multi_mapping.h).
#include "core/registry.h"
#include "mapping/linear/subset_multi_mapping.h"

namespace sinew {

namespace {

class IdentityMultiMapping final : public GatherMultiMapping {
 public:
  using GatherMultiMapping::GatherMultiMapping;

 protected:
  bool sources(std::vector<Source>& src) override {
    for (std::size_t k = 0; k < in_.size(); ++k)
      for (std::size_t i = 0; i < in_[k]->size(); ++i)
        src.push_back({static_cast<unsigned>(k), static_cast<unsigned>(i)});
    return true;
  }
};

}  // namespace

void register_identity_multi_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "IdentityMultiMapping";
  info.category = "Mapping/Linear";
  info.description = "concatenates the points of several input states into one output state";
  info.templates = {"Vec3d,Vec3d", "Vec2d,Vec2d", "Vec1d,Vec1d", "Rigid3d,Rigid3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<IdentityMultiMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
