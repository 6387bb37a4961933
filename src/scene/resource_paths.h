// Resource resolution: how a file name written in a scene becomes a file on disk.
//
// SOFA resolves a relative name first against the folder of the file being parsed
// (it switches the working directory there while loading), then against each folder
// of its data repository in order (`share/`, `examples/`, then SOFA_DATA_PATH), and
// the first existing candidate wins. ResourcePaths holds that ordered folder list and
// implements the lookup without ever touching the process working directory, so
// loading is re-entrant and thread-safe. See regression-protocol.md §8.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::scene {

class ResourcePaths {
 public:
  // Appends a data folder to the search list (searched after the folders added before).
  // Relative folders are made absolute against the current directory now, so a later
  // change of directory does not change what they mean. Empty strings and folders
  // already in the list are ignored (a duplicate could never produce a new hit).
  void add(std::string dir);

  // Appends every entry of the environment variable SOFA_DATA_PATH (':'-separated,
  // empty entries skipped), in order. Does nothing when the variable is unset.
  void add_from_env();

  // Resolves `name` the way SOFA does:
  //  1. an absolute name is used as is;
  //  2. otherwise `base_dir`/name (skipped when `base_dir` is empty);
  //  3. otherwise each data folder in order, first hit wins.
  // A candidate counts when it exists (a file or a folder). Returns the absolute,
  // lexically normalised path ("a/../b" folded), or nullopt when nothing exists —
  // including an absolute name that does not exist and an empty name.
  // Never throws (file system errors count as "does not exist").
  std::optional<std::string> resolve(std::string_view name, std::string_view base_dir) const;

  // The data folders, absolute, in search order.
  const std::vector<std::string>& dirs() const { return dirs_; }

 private:
  std::vector<std::string> dirs_;
};

// Absolute, lexically normalised form of `path` ("" stays ""); no file system access
// other than reading the current directory for relative paths. Never throws.
std::string absolute_normal(std::string_view path);

// Folder part of `path` after making it absolute (the folder a file's relative
// names resolve against). Never throws.
std::string parent_dir(std::string_view path);

}  // namespace sinew::scene
