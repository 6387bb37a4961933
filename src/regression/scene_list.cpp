#include "regression/scene_list.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <filesystem>

#include "regression/gzip_text.h"
#include "regression/stream_reader.h"

namespace sinew::regression {
namespace {

constexpr std::string_view kRegressionDirToken = "$REGRESSION_DIR";

// Joins with a single '/', keeping `tail` when it is absolute or `dir` empty.
std::string join_path(const std::string& dir, std::string_view tail) {
  if (dir.empty() || (!tail.empty() && tail.front() == '/')) return std::string(tail);
  if (dir.back() == '/') return dir + std::string(tail);
  return dir + "/" + std::string(tail);
}

bool is_directory(const std::string& path) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_directory(path, ec);
}

// std::stoi semantics without exceptions: leading whitespace, sign, digits;
// trailing characters ignored; fails without digits or outside int range.
bool parse_stoi(std::string_view token, int& value) {
  const std::string text(token);
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(begin, &end, 10);
  if (end == begin || errno == ERANGE || v < INT_MIN || v > INT_MAX) return false;
  value = static_cast<int>(v);
  return true;
}

// std::stod semantics without exceptions (strtod grammar: also "inf", "nan",
// hex); fails when nothing converts or the value is out of range.
bool parse_stod(std::string_view token, double& value) {
  const std::string text(token);
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = strtod_c(begin, &end);
  if (end == begin || errno == ERANGE) return false;
  value = v;
  return true;
}

std::string line_message(int line, const std::string& message) {
  return "line " + std::to_string(line) + ": " + message;
}

// Resolves the reference-folder line; returns "" when no candidate exists.
std::string resolve_reference_dir(const std::string& line, int line_number, SceneList& list,
                                  const ListEnvironment& env) {
  std::string candidate;
  if (line.compare(0, kRegressionDirToken.size(), kRegressionDirToken) == 0) {
    if (!env.regression_dir) {
      list.problems.push_back(line_message(line_number, "$REGRESSION_DIR is used but not set"));
    }
    candidate = env.regression_dir.value_or("") + line.substr(kRegressionDirToken.size());
  } else {
    candidate = join_path(list.list_dir, line);
  }
  list.reference_dir = candidate;
  if (is_directory(candidate)) return candidate;
  if (env.references_dir) {
    const std::string fallback = join_path(list.list_dir, *env.references_dir);
    if (is_directory(fallback)) {
      list.reference_dir = fallback;
      return fallback;
    }
  }
  list.problems.push_back(line_message(
      line_number, "reference folder '" + candidate +
                       "' does not exist (nor REGRESSION_REFERENCES_DIR); list ignored"));
  return "";
}

}  // namespace

ListEnvironment ListEnvironment::from_process() {
  ListEnvironment env;
  if (const char* v = std::getenv("REGRESSION_DIR")) env.regression_dir = v;
  if (const char* v = std::getenv("REGRESSION_REFERENCES_DIR")) env.references_dir = v;
  return env;
}

SceneList parse_scene_list(std::string_view text, const std::string& list_dir,
                           const ListEnvironment& env) {
  SceneList list;
  list.list_dir = list_dir;
  bool have_reference_line = false;
  int line_number = 0;
  for (std::string_view line : split_lines(text)) {
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    if (!have_reference_line) {
      have_reference_line = true;
      if (resolve_reference_dir(std::string(line), line_number, list, env).empty()) return list;
      continue;
    }
    std::vector<std::string_view> tokens;
    StreamReader reader(line);
    for (std::string_view word; reader.read_word(word);) tokens.push_back(word);
    if (tokens.size() < 3) {
      list.problems.push_back(line_message(
          line_number, "expected 'scene steps epsilon [mapped [lastonly [period]]]', got '" +
                           std::string(line) + "'; line ignored"));
      continue;
    }
    SceneEntry entry;
    entry.scene = std::string(tokens[0]);
    entry.line = line_number;
    int mapped = 0, last_only = 0;
    bool ok = parse_stoi(tokens[1], entry.steps) && parse_stod(tokens[2], entry.epsilon);
    if (ok && tokens.size() > 3) ok = parse_stoi(tokens[3], mapped);
    if (ok && tokens.size() > 4) ok = parse_stoi(tokens[4], last_only);
    if (ok && tokens.size() > 5) ok = parse_stoi(tokens[5], entry.period);
    if (!ok) {
      list.problems.push_back(
          line_message(line_number, "invalid number in '" + std::string(line) + "'; line ignored"));
      continue;
    }
    entry.mapped = mapped != 0;
    entry.last_only = last_only != 0;
    list.scenes.push_back(std::move(entry));
  }
  if (!have_reference_line) list.problems.push_back("no reference folder line");
  return list;
}

std::optional<SceneList> read_scene_list(const std::string& path, const ListEnvironment& env,
                                         std::string* error) {
  auto text = read_text_file(path, error);
  if (!text) return std::nullopt;
  return parse_scene_list(*text, std::filesystem::path(path).parent_path().string(), env);
}

std::string scene_path(const SceneList& list, const SceneEntry& entry) {
  return join_path(list.list_dir, entry.scene);
}

std::string reference_base(const SceneList& list, const SceneEntry& entry) {
  return join_path(list.reference_dir, entry.scene) + ".reference";
}

}  // namespace sinew::regression
