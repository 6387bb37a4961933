#include "exporter/playback/text_sink.h"

#include <zlib.h>

#include <filesystem>

namespace sinew {

bool TextSink::open(const std::string& path, std::string* error) {
  close();
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0) {
    gz_ = gzopen(path.c_str(), "wb");
    if (!gz_ && error) *error = "cannot create the compressed file '" + path + "'";
  } else {
    file_ = std::fopen(path.c_str(), "w");
    if (!file_ && error) *error = "cannot create the file '" + path + "'";
  }
  return is_open();
}

void TextSink::close() {
  if (file_) std::fclose(file_);
  if (gz_) gzclose(static_cast<gzFile>(gz_));
  file_ = nullptr;
  gz_ = nullptr;
}

void TextSink::put(const std::string& text) {
  if (gz_) {
    gzputs(static_cast<gzFile>(gz_), text.c_str());
    gzflush(static_cast<gzFile>(gz_), Z_SYNC_FLUSH);
  } else if (file_) {
    std::fputs(text.c_str(), file_);
    std::fflush(file_);
  }
}

}  // namespace sinew
