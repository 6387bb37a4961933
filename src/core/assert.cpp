#include "core/assert.h"

#include <cstdio>
#include <cstdlib>

namespace sinew::detail {

void assertion_failed(const char* condition, const char* why, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal error: condition '%s' failed: %s\n(this is a bug in Sinew, not in the scene)\n",
               file, line, condition, why);
  std::fflush(stderr);
  std::abort();
}

}  // namespace sinew::detail
