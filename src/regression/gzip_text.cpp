#include "regression/gzip_text.h"

#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace sinew::regression {
namespace {

void set_error(std::string* error, std::string message) {
  if (error) *error = std::move(message);
}

// Owns a FILE* so that every early return closes it.
struct File {
  std::FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

}  // namespace

bool is_gzip(std::string_view data) {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f &&
         static_cast<unsigned char>(data[1]) == 0x8b;
}

std::optional<std::string> gunzip_text(std::string_view data, std::string* error) {
  z_stream zs{};
  // 16 + MAX_WBITS: expect a gzip wrapper (header and trailer) around deflate data.
  if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) {
    set_error(error, "zlib: inflateInit2 failed");
    return std::nullopt;
  }
  std::string out;
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());  // reference files are far below 4 GiB
  char buffer[1 << 16];
  for (;;) {
    zs.next_out = reinterpret_cast<Bytef*>(buffer);
    zs.avail_out = sizeof(buffer);
    const int rc = inflate(&zs, Z_NO_FLUSH);
    out.append(buffer, sizeof(buffer) - zs.avail_out);
    if (rc == Z_STREAM_END) {
      // Another member may follow; anything else after a member is ignored.
      const std::string_view rest(reinterpret_cast<const char*>(zs.next_in), zs.avail_in);
      if (!is_gzip(rest)) break;
      inflateReset(&zs);
      continue;
    }
    if (rc == Z_OK) continue;  // more output pending or input left
    if (rc == Z_BUF_ERROR) {
      // No progress possible although all input was supplied and the output
      // buffer was empty: the stream was cut. Keep what was decompressed.
      break;
    }
    const char* msg = zs.msg ? zs.msg : "corrupt data";
    set_error(error, std::string("zlib: ") + msg);
    inflateEnd(&zs);
    return std::nullopt;
  }
  inflateEnd(&zs);
  return out;
}

std::optional<std::string> read_text_file(const std::string& path, std::string* error) {
  File file{std::fopen(path.c_str(), "rb")};
  if (!file.f) {
    set_error(error, path + ": " + std::strerror(errno));
    return std::nullopt;
  }
  std::string data;
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), file.f)) > 0) data.append(buffer, n);
  if (std::ferror(file.f)) {
    set_error(error, path + ": read error");
    return std::nullopt;
  }
  if (!is_gzip(data)) return data;
  std::string zerror;
  auto text = gunzip_text(data, &zerror);
  if (!text) set_error(error, path + ": " + zerror);
  return text;
}

std::string gzip_text(std::string_view text) {
  z_stream zs{};
  deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out;
  out.resize(deflateBound(&zs, static_cast<uLong>(text.size())));
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  zs.avail_in = static_cast<uInt>(text.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  // deflateBound guarantees a single Z_FINISH call completes the member.
  deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

bool write_text_file(const std::string& path, std::string_view text, bool gzip, std::string* error) {
  File file{std::fopen(path.c_str(), "wb")};
  if (!file.f) {
    set_error(error, path + ": " + std::strerror(errno));
    return false;
  }
  const std::string compressed = gzip ? gzip_text(text) : std::string();
  const std::string_view bytes = gzip ? std::string_view(compressed) : text;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.f) != bytes.size()) {
    set_error(error, path + ": write error");
    return false;
  }
  const int rc = std::fclose(file.f);
  file.f = nullptr;
  if (rc != 0) {
    set_error(error, path + ": write error on close");
    return false;
  }
  return true;
}

}  // namespace sinew::regression
