// Whole-file text I/O for reference files, plain or gzip-compressed.
//
// SOFA writes references with zlib, block by block with a sync flush after
// each block, and a run that is not closed cleanly leaves a gzip stream
// without its end marker and trailer. SOFA reads such files with gzread, which
// returns everything that was flushed, so we must as well.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sinew::regression {

// Reads the file at `path`. Gzip is detected by the magic bytes 1f 8b (not by
// the extension); anything else is returned verbatim.
// Gzip handling: concatenated members are joined; a stream cut anywhere
// (missing trailer, missing end of the deflate data) yields all the text
// that could be decompressed; bytes after a complete member that do not start
// another member are ignored (as gzread does).
// Returns nullopt and sets *error (if non-null) when the file cannot be read
// or the compressed data is corrupt.
std::optional<std::string> read_text_file(const std::string& path, std::string* error = nullptr);

// Decompresses an in-memory gzip stream with the same rules as read_text_file.
// Precondition: `data` starts with a gzip header (check with is_gzip).
std::optional<std::string> gunzip_text(std::string_view data, std::string* error = nullptr);

// True if `data` starts with the gzip magic bytes 1f 8b.
bool is_gzip(std::string_view data);

// Writes `text` to `path` (replacing it), as one complete gzip member if
// `gzip`, else verbatim. Returns false and sets *error (if non-null) on failure.
bool write_text_file(const std::string& path, std::string_view text, bool gzip,
                     std::string* error = nullptr);

// Compresses `text` into one complete gzip member (default level).
std::string gzip_text(std::string_view text);

}  // namespace sinew::regression
