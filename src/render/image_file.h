// Pictures read from files whatever their format (PNG, JPEG, BMP), told apart by their
// first bytes rather than their names: the textures of SOFA's scenes.
#pragma once

#include <optional>
#include <string>

#include "render/image.h"

namespace sinew::render {

std::optional<Image> read_image(const std::string& path, std::string* error);

}  // namespace sinew::render
