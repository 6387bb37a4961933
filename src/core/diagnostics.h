// Diagnostics: messages collected while loading and running a scene.
//
// Loading never throws on bad input: every problem becomes a Message with a
// source location (file:line) and, when known, the component it concerns.
// A scene with errors is refused as a whole, never half-run.
#pragma once

#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace sinew {

enum class Severity { info, warning, error };

struct SourceLocation {
  std::string file;  // empty when the message does not come from a file
  int line = 0;      // 1-based; 0 when unknown
};

struct Message {
  Severity severity = Severity::info;
  SourceLocation where;
  std::string who;  // "component 'name' (Type)" or empty
  std::string text;
};

class Diagnostics {
 public:
  Diagnostics() = default;
  Diagnostics(const Diagnostics& o) : messages_(o.messages_), errors_(o.errors_), warnings_(o.warnings_) {}
  Diagnostics& operator=(const Diagnostics& o) {
    messages_ = o.messages_, errors_ = o.errors_, warnings_ = o.warnings_;
    return *this;
  }
  // Thread-safe: solvers running in parallel may report.
  void add(Severity s, SourceLocation where, std::string who, std::string text);
  void info(SourceLocation where, std::string text) { add(Severity::info, std::move(where), {}, std::move(text)); }
  void warning(SourceLocation where, std::string text) { add(Severity::warning, std::move(where), {}, std::move(text)); }
  void error(SourceLocation where, std::string text) { add(Severity::error, std::move(where), {}, std::move(text)); }

  const std::vector<Message>& messages() const { return messages_; }
  bool has_errors() const { return errors_ > 0; }
  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }
  void clear() { messages_.clear(); errors_ = warnings_ = 0; }

  // "file:line: error: component 'x' (Type): text"
  static std::string format(const Message& m);

 private:
  std::vector<Message> messages_;
  int errors_ = 0;
  int warnings_ = 0;
  std::mutex mutex_;
};

// Closest names to `name` among `candidates` (edit distance, case-insensitive),
// best first, at most `max` of them; used for "did you mean" suggestions.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates,
                                       std::size_t max = 3);

}  // namespace sinew
