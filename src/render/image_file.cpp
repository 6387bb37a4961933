#include "render/image_file.h"

#include <fstream>

#include "render/bmp_io.h"
#include "render/jpeg_io.h"
#include "render/png_io.h"

namespace sinew::render {

std::optional<Image> read_image(const std::string& path, std::string* error) {
  unsigned char head[4] = {};
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      if (error) *error = "cannot open " + path;
      return std::nullopt;
    }
    in.read(reinterpret_cast<char*>(head), sizeof head);
  }
  if (head[0] == 0x89 && head[1] == 'P' && head[2] == 'N' && head[3] == 'G') return read_png(path, error);
  if (head[0] == 0xFF && head[1] == 0xD8) return read_jpeg(path, error);
  if (head[0] == 'B' && head[1] == 'M') return read_bmp(path, error);
  if (error) *error = path + ": not a PNG, JPEG or BMP picture";
  return std::nullopt;
}

}  // namespace sinew::render
