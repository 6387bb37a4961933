// JPEG files through libjpeg-turbo (Debian: libjpeg-dev), read into RGBA, top row first.
#pragma once

#include <optional>
#include <string>

#include "render/image.h"

namespace sinew::render {

std::optional<Image> read_jpeg(const std::string& path, std::string* error);

}  // namespace sinew::render
