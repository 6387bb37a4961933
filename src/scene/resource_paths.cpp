#include "scene/resource_paths.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace sinew::scene {

namespace fs = std::filesystem;

namespace {

// Lexically normalised absolute path without a trailing separator, so that
// "/data/share/" and "/data/share" compare equal and join the same way.
fs::path normal_absolute(const fs::path& p) {
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  if (ec) abs = p;  // no current directory: keep what we were given rather than fail
  abs = abs.lexically_normal();
  if (!abs.has_filename() && abs.has_relative_path()) abs = abs.parent_path();
  return abs;
}

bool exists_no_throw(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec) && !ec;
}

}  // namespace

std::string absolute_normal(std::string_view path) {
  if (path.empty()) return {};
  return normal_absolute(fs::path(path)).string();
}

std::string parent_dir(std::string_view path) {
  if (path.empty()) return normal_absolute(fs::path(".")).string();
  return normal_absolute(fs::path(path)).parent_path().string();
}

void ResourcePaths::add(std::string dir) {
  if (dir.empty()) return;
  std::string abs = absolute_normal(dir);
  if (std::find(dirs_.begin(), dirs_.end(), abs) != dirs_.end()) return;
  dirs_.push_back(std::move(abs));
}

void ResourcePaths::add_from_env() {
  const char* env = std::getenv("SOFA_DATA_PATH");
  if (env == nullptr) return;
  std::string_view rest(env);
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    add(std::string(rest.substr(0, colon)));
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
}

std::optional<std::string> ResourcePaths::resolve(std::string_view name, std::string_view base_dir) const {
  if (name.empty()) return std::nullopt;
  const fs::path p{std::string(name)};
  if (p.is_absolute()) {
    if (exists_no_throw(p)) return normal_absolute(p).string();
    return std::nullopt;
  }
  if (!base_dir.empty()) {
    const fs::path candidate = fs::path(std::string(base_dir)) / p;
    if (exists_no_throw(candidate)) return normal_absolute(candidate).string();
  }
  for (const std::string& dir : dirs_) {
    const fs::path candidate = fs::path(dir) / p;
    if (exists_no_throw(candidate)) return normal_absolute(candidate).string();
  }
  return std::nullopt;
}

}  // namespace sinew::scene
