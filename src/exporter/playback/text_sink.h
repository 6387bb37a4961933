// An output text file for the playback writers (WriteState, WriteTopology): plain, or
// gzip-compressed when the name ends in ".gz", flushed after every write so that a run that
// stops early (crash, Ctrl-C) leaves every block written so far readable, as SOFA's writers.
#pragma once

#include <cstdio>
#include <string>

namespace sinew {

class TextSink {
 public:
  TextSink() = default;
  TextSink(const TextSink&) = delete;
  TextSink& operator=(const TextSink&) = delete;
  ~TextSink() { close(); }

  // Creates (truncates) `path`, creating its folder if needed. On failure returns false and
  // sets *error; the sink stays closed.
  bool open(const std::string& path, std::string* error);
  void close();
  bool is_open() const { return file_ != nullptr || gz_ != nullptr; }
  // Writes and flushes `text` (nothing when closed).
  void put(const std::string& text);

 private:
  FILE* file_ = nullptr;
  void* gz_ = nullptr;  // gzFile, kept opaque so that users need not include zlib.h
};

}  // namespace sinew
