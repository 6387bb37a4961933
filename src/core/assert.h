// Checks of Sinew's own assumptions (Drake's DRAKE_ASSERT / DRAKE_DEMAND,
// Box2D's B2_ASSERT with its validation build).
//
//   SINEW_ASSERT(cond, "why")  armed in Debug builds and in validation builds
//                              (cmake -DSINEW_VALIDATE=ON); compiled out in
//                              Release, so it may sit in hot loops.
//   SINEW_DEMAND(cond, "why")  always armed: cheap checks outside loops.
//
// A failed check is a bug in Sinew, never a problem of the scene: it prints
// the condition, the reason, the file and line, and aborts. Problems of the
// input (scene files, meshes, Python calls) are messages (msg_error), never
// asserts: bad input must not take the process down.
#pragma once

namespace sinew::detail {
[[noreturn]] void assertion_failed(const char* condition, const char* why, const char* file, int line);
}  // namespace sinew::detail

#define SINEW_DEMAND(condition, why)                                                         \
  do {                                                                                       \
    if (!(condition)) [[unlikely]]                                                           \
      ::sinew::detail::assertion_failed(#condition, (why), __FILE__, __LINE__);              \
  } while (false)

#if defined(SINEW_VALIDATE) || !defined(NDEBUG)
#define SINEW_ASSERT_ARMED 1
#define SINEW_ASSERT(condition, why) SINEW_DEMAND(condition, why)
#else
#define SINEW_ASSERT_ARMED 0
// Not evaluated, but still compiled (names checked, no unused-variable warnings).
#define SINEW_ASSERT(condition, why) \
  do {                               \
    if (false) (void)(condition);    \
  } while (false)
#endif
