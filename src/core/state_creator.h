// Registry creator for components whose layout follows the state type of
// their template ("Vec3d", "Rigid3d"): MechanicalObject, ROIs, engines and
// constraints built as T(StateType). Unknown templates create nothing.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/roles.h"

namespace sinew {

template <class T>
std::function<std::unique_ptr<Component>(const std::string&)> state_creator() {
  return [](const std::string& t) -> std::unique_ptr<Component> {
    StateType st;
    if (!state_type_from_name(t, st)) return nullptr;
    return std::make_unique<T>(st);
  };
}

}  // namespace sinew
