// Whole text files that may be gzip-compressed (SOFA reads a few inputs,
// such as TopologicalChangeProcessor's change lists, through zlib).
#pragma once

#include <optional>
#include <string>

namespace sinew::io {

// The file's text; gzip data (any name) is decompressed, other files are read as they are.
// nullopt with a message in *error when the file cannot be opened or its compressed data is corrupt.
std::optional<std::string> read_text_maybe_gzip(const std::string& path, std::string* error = nullptr);

}  // namespace sinew::io
