// libFuzzer target: a whole XML scene, as `sinew run` takes it: the XML reader
// (includes, macros), graph building (every registered component, attributes,
// links, resource files found in the SOFA data folders), init and two steps.
//
// The input is written to a scratch .scn file; relative resource names resolve in
// SINEW_FUZZ_DATA_DIR's share/ and examples/ (the scenes' meshes), as for the
// regression scenes. Run it from a scratch folder: exporters in mutated scenes
// write their files relative to the working directory.
//
// A finding is a crash, a sanitizer report, a hang, a leak or memory beyond the
// RSS limit; a scene refused with errors is the expected outcome.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/diagnostics.h"
#include "fuzz_support.h"
#include "runner/session.h"

#ifndef SINEW_FUZZ_DATA_DIR
#define SINEW_FUZZ_DATA_DIR ""
#endif

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sinew::fuzz::limit_scene_memory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sinew;
  const std::string& path = fuzz::scratch_path("scene.scn");
  if (!fuzz::write_file(path, data, size)) return 0;
  runner::SessionOptions options;
  const char* dir = std::getenv("SINEW_DATA_DIR");
  options.data_paths = runner::sofa_data_paths(dir && *dir ? dir : SINEW_FUZZ_DATA_DIR);
  runner::Session session(path, options);
  if (!session.ok()) {
    if (session.diagnostics().error_count() == 0 && session.loaded()) __builtin_trap();  // refused without a word
    return 0;
  }
  for (int i = 0; i < 2 && session.step(); ++i) {
  }
  return 0;
}
