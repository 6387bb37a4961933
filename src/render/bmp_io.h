// Windows bitmaps (.bmp), as SOFA's textures ship them (textures/floor.bmp, ...): uncompressed
// 24- and 32-bit, and 8-bit with a palette, rows bottom-up or top-down. Read into RGBA, top row first.
#pragma once

#include <optional>
#include <string>

#include "render/image.h"

namespace sinew::render {

std::optional<Image> read_bmp(const std::string& path, std::string* error);

}  // namespace sinew::render
