#include "render/bmp_io.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

namespace sinew::render {

namespace {

std::uint32_t u32(const std::vector<unsigned char>& b, std::size_t at) {
  return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (std::uint32_t(b[at + 3]) << 24);
}
std::uint16_t u16(const std::vector<unsigned char>& b, std::size_t at) { return b[at] | (b[at + 1] << 8); }

}  // namespace

std::optional<Image> read_bmp(const std::string& path, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<Image> {
    if (error) *error = path + " is not a readable BMP file: " + why;
    return std::nullopt;
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open it");
  const std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (b.size() < 54 || b[0] != 'B' || b[1] != 'M') return fail("no BM header");
  const std::uint32_t offset = u32(b, 10), header = u32(b, 14);
  if (header < 40) return fail("old OS/2 header");
  const auto width = static_cast<std::int32_t>(u32(b, 18));
  const auto height_signed = static_cast<std::int32_t>(u32(b, 22));
  const std::uint16_t bits = u16(b, 28);
  const std::uint32_t compression = u32(b, 30);
  if (compression != 0 && !(compression == 3 && bits == 32)) return fail("compressed bitmaps are not supported");
  if (bits != 8 && bits != 24 && bits != 32) return fail(std::to_string(bits) + "-bit pixels are not supported");
  const bool bottom_up = height_signed > 0;
  const std::int64_t height = bottom_up ? height_signed : -static_cast<std::int64_t>(height_signed);
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) return fail("bad size");
  const std::size_t row = (static_cast<std::size_t>(width) * bits / 8 + 3) & ~std::size_t(3);  // rows pad to 4 bytes
  if (offset + row * static_cast<std::size_t>(height) > b.size()) return fail("truncated");
  const std::size_t palette = 14 + header;
  Image img;
  img.width = width, img.height = static_cast<int>(height);
  img.rgba.resize(static_cast<std::size_t>(width) * img.height * 4);
  for (int y = 0; y < img.height; ++y) {
    const std::size_t src = offset + row * static_cast<std::size_t>(bottom_up ? img.height - 1 - y : y);
    for (int x = 0; x < width; ++x) {
      unsigned char* p = &img.rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      if (bits == 8) {
        const std::size_t e = palette + 4 * std::size_t(b[src + x]);
        if (e + 3 > b.size()) return fail("palette index beyond the palette");
        p[0] = b[e + 2], p[1] = b[e + 1], p[2] = b[e], p[3] = 255;
      } else {
        const std::size_t s = src + static_cast<std::size_t>(x) * (bits / 8);
        p[0] = b[s + 2], p[1] = b[s + 1], p[2] = b[s];  // stored blue, green, red
        p[3] = bits == 32 ? b[s + 3] : 255;
      }
    }
  }
  return img;
}

}  // namespace sinew::render
