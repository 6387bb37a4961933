#include "render/jpeg_io.h"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <jpeglib.h>

namespace sinew::render {

namespace {

// libjpeg reports errors through a callback that must not return, and C++ exceptions must not
// cross its C frames: the callback keeps the message and jumps back to decode(), whose state
// lives in this plain struct (no C++ object is skipped by the jump, no local is clobbered).
struct Decoder {
  jpeg_decompress_struct info;
  jpeg_error_mgr err;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  unsigned char* rgb;  // malloc'd, width·height·3
  bool created;
};

void on_error(j_common_ptr info) {
  Decoder* d = static_cast<Decoder*>(info->client_data);
  (*info->err->format_message)(info, d->message);
  std::longjmp(d->jump, 1);
}

bool decode(Decoder* d, std::FILE* f) {
  if (setjmp(d->jump)) return false;
  jpeg_create_decompress(&d->info);
  d->created = true;
  jpeg_stdio_src(&d->info, f);
  jpeg_read_header(&d->info, TRUE);
  d->info.out_color_space = JCS_RGB;  // greyscale and YCbCr converted by the library
  jpeg_start_decompress(&d->info);
  const JDIMENSION w = d->info.output_width, h = d->info.output_height;
  if (w == 0 || h == 0 || w > 16384 || h > 16384) {
    std::snprintf(d->message, sizeof d->message, "bad size %ux%u", unsigned(w), unsigned(h));
    return false;
  }
  d->rgb = static_cast<unsigned char*>(std::malloc(std::size_t(w) * h * 3));
  if (!d->rgb) {
    std::snprintf(d->message, sizeof d->message, "out of memory");
    return false;
  }
  while (d->info.output_scanline < h) {
    JSAMPROW rows[1] = {d->rgb + std::size_t(d->info.output_scanline) * w * 3};
    jpeg_read_scanlines(&d->info, rows, 1);
  }
  jpeg_finish_decompress(&d->info);
  return true;
}

}  // namespace

std::optional<Image> read_jpeg(const std::string& path, std::string* error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    if (error) *error = "cannot open " + path;
    return std::nullopt;
  }
  Decoder* d = static_cast<Decoder*>(std::calloc(1, sizeof(Decoder)));
  if (!d) {
    std::fclose(f);
    if (error) *error = "out of memory reading " + path;
    return std::nullopt;
  }
  d->info.err = jpeg_std_error(&d->err);
  d->err.error_exit = on_error;
  d->info.client_data = d;
  const bool ok = decode(d, f);
  std::optional<Image> out;
  if (ok) {
    Image img;
    img.width = static_cast<int>(d->info.output_width);
    img.height = static_cast<int>(d->info.output_height);
    const std::size_t n = std::size_t(img.width) * img.height;
    img.rgba.resize(n * 4);
    for (std::size_t i = 0; i < n; ++i) {
      std::memcpy(&img.rgba[i * 4], &d->rgb[i * 3], 3);
      img.rgba[i * 4 + 3] = 255;
    }
    out = std::move(img);
  } else if (error) {
    *error = path + " is not a readable JPEG file: " + d->message;
  }
  if (d->created) jpeg_destroy_decompress(&d->info);
  std::free(d->rgb);
  std::free(d);
  std::fclose(f);
  return out;
}

}  // namespace sinew::render
