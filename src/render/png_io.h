// PNG files through libpng (Debian: libpng-dev): 8-bit RGBA written, any 8-bit PNG read
// (expanded to RGBA).
#pragma once

#include <optional>
#include <string>

#include "render/image.h"

namespace sinew::render {

bool write_png(const std::string& path, const Image& image, std::string* error);
std::optional<Image> read_png(const std::string& path, std::string* error);

}  // namespace sinew::render
