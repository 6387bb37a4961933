#include "render/png_io.h"

#include <png.h>

#include <vector>

namespace sinew::render {

// libpng's simplified API (png_image): errors come back as return values with a
// message, not through setjmp/longjmp, which does not mix with C++ objects.

bool write_png(const std::string& path, const Image& image, std::string* error) {
  // The pictures are opaque: RGB keeps the files a quarter smaller than the RGBA rows.
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  std::vector<unsigned char> rgb(pixels * 3);
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = image.rgba[i * 4 + c];
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&png, path.c_str(), 0, rgb.data(), 0, nullptr)) {
    if (error) *error = "cannot write " + path + ": " + png.message;
    png_image_free(&png);
    return false;
  }
  return true;
}

std::optional<Image> read_png(const std::string& path, std::string* error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    if (error) *error = path + " is not a readable PNG file: " + png.message;
    png_image_free(&png);
    return std::nullopt;
  }
  png.format = PNG_FORMAT_RGBA;  // any colour type, expanded to 8-bit RGBA
  Image img;
  img.width = static_cast<int>(png.width);
  img.height = static_cast<int>(png.height);
  img.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, img.rgba.data(), 0, nullptr)) {
    if (error) *error = path + " is not a readable PNG file: " + png.message;
    png_image_free(&png);
    return std::nullopt;
  }
  return img;
}

}  // namespace sinew::render
