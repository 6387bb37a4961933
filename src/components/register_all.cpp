// Registers every built-in component. The list of `register_x(Registry& r)`
// functions is generated from the sources at build time
// (cmake/gen_registrations.cmake): explicit calls rather than static
// initialisers, so that static libraries cannot drop components at link time.
#include "components/register_all.h"

#include "core/registry.h"
#include "registrations.inc"

namespace sinew {

SINEW_REGISTRATION_DECLS

void register_all_components() {
  static bool done = false;
  if (done) return;
  done = true;
  Registry& r = registry();
  SINEW_REGISTRATION_CALLS(r)
}

}  // namespace sinew
