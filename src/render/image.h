// A picture in memory: 8-bit RGBA, rows from the top of the image down.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace sinew::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width·height·4

  std::array<int, 3> rgb(int x, int y) const {
    const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    return {p[0], p[1], p[2]};
  }
};

}  // namespace sinew::render
