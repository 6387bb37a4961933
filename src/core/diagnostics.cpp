#include "core/diagnostics.h"

#include <algorithm>
#include <cctype>

namespace sinew {

void Diagnostics::add(Severity s, SourceLocation where, std::string who, std::string text) {
  // Safety net: a message never carries megabytes of scene text (values quoted
  // in messages are shortened by quote_value; this catches the rest).
  constexpr std::size_t kMaxText = 4000;
  if (text.size() > kMaxText) {
    const std::size_t total = text.size();
    std::size_t cut = kMaxText;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text.resize(cut);
    text += "… (message shortened: " + std::to_string(total) + " characters)";
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (s == Severity::error) ++errors_;
  if (s == Severity::warning) ++warnings_;
  messages_.push_back({s, std::move(where), std::move(who), std::move(text)});
}

std::string Diagnostics::format(const Message& m) {
  std::string out;
  if (!m.where.file.empty()) {
    out += m.where.file;
    if (m.where.line > 0) out += ":" + std::to_string(m.where.line);
    out += ": ";
  }
  out += m.severity == Severity::error ? "error: " : m.severity == Severity::warning ? "warning: " : "info: ";
  if (!m.who.empty()) out += m.who + ": ";
  out += m.text;
  return out;
}

namespace {
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}
}  // namespace

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates,
                                       std::size_t max) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(name, c);
    // Only suggest names that are reasonably close: at most ~40% of the letters differ.
    if (d * 5 <= std::max(name.size(), c.size()) * 2) scored.emplace_back(d, c);
  }
  std::stable_sort(scored.begin(), scored.end(), [](auto& x, auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && i < max; ++i) out.push_back(scored[i].second);
  return out;
}

}  // namespace sinew
