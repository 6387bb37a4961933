#include "core/alloc_check.h"

#include <unistd.h>

#include <cstdio>

#include "core/component.h"

namespace sinew {

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t{64} << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
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
