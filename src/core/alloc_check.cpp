#include "core/alloc_check.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "core/component.h"

namespace sinew {

namespace {
std::uint64_t machine_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  std::uint64_t bytes = std::uint64_t{64} << 30;
  if (pages > 0 && page > 0) bytes = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
  if (const char* cap = std::getenv("SINEW_MEMORY_LIMIT_MB")) {
    char* end = nullptr;
    const unsigned long long mb = std::strtoull(cap, &end, 10);
    if (end != cap && mb > 0 && mb < (bytes >> 20)) bytes = static_cast<std::uint64_t>(mb) << 20;
  }
  return bytes;
}
}  // namespace

std::uint64_t physical_memory_bytes() {
  static const std::uint64_t bytes = machine_memory_bytes();  // thread-safe static init
  return bytes;
}

bool allocation_fits(double count, double bytes_each) {
  if (!(count >= 0) || !(bytes_each >= 0)) return false;  // also NaN
  return count * bytes_each <= static_cast<double>(physical_memory_bytes());
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) bytes /= 1000, ++u;
  char buf[64];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

bool check_allocation(const Component& c, std::string_view field, std::string_view value_text, double count,
                      double bytes_each) {
  if (allocation_fits(count, bytes_each)) return true;
  c.msg_error("'" + std::string(field) + "' = " + std::string(value_text) + " would need " +
              format_bytes(count * bytes_each) + ", more than this machine's " +
              format_bytes(static_cast<double>(physical_memory_bytes())) + " of memory");
  return false;
}

}  // namespace sinew
