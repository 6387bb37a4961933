// Helpers shared by the libFuzzer targets (fuzz/README.md).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace sinew::fuzz {

// A file of this process (one per name) that each input is written to, for the
// readers that take a path: /tmp/sinew-fuzz-<pid>-<name>.
inline const std::string& scratch_path(const char* name) {
  static const std::string path = "/tmp/sinew-fuzz-" + std::to_string(::getpid()) + "-" + name;
  return path;
}

inline bool write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

// Sizes from inputs are checked against the memory a scene may use; the fuzzers
// lower it (alloc_check.h) so that a huge count is refused instead of being
// allocated up to libFuzzer's RSS limit. Call before anything reads it.
inline void limit_scene_memory() { ::setenv("SINEW_MEMORY_LIMIT_MB", "64", 0); }

}  // namespace sinew::fuzz
