// libFuzzer target: one mesh reader (the extension SINEW_FUZZ_EXT picks it, as
// read_mesh does for a loader's filename), then MeshLoader's post-processing with
// every option on, as a scene would ask for it.
//
// A finding is a crash, a sanitizer report, a hang or an allocation beyond the
// RSS limit; a reader refusing the input with a message is the expected outcome.
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "io/mesh_readers.h"

#ifndef SINEW_FUZZ_EXT
#error "SINEW_FUZZ_EXT (\".obj\", \".msh\", ...) names the reader"
#endif

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sinew::fuzz::limit_scene_memory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sinew;
  const std::string& path = fuzz::scratch_path("mesh" SINEW_FUZZ_EXT);
  if (!fuzz::write_file(path, data, size)) return 0;
  std::string error;
  io::ReadOptions ro;
  ro.flip_normals = size % 2 == 1;  // both orders, from the input itself
  std::optional<io::MeshData> m = io::read_mesh(path, &error, ro);
  if (!m) {
    if (error.empty()) __builtin_trap();  // a refusal always says why
    return 0;
  }
  io::FinishOptions fo;
  fo.create_subelements = true;
  fo.only_attached_points = size % 3 == 0;
  fo.triangulate = size % 5 == 0;
  fo.compute_normals = true;
  io::finish_mesh(*m, fo);
  // Normals are normalised or zero: never NaN from a mesh of moderate coordinates
  // (beyond 1e100 the cross products overflow, as SOFA's would).
  bool finite_in = true;
  for (const Vec3& p : m->positions) finite_in = finite_in && p.allFinite() && p.cwiseAbs().maxCoeff() < 1e100;
  if (finite_in)
    for (const Vec3& n : m->normals)
      if (!n.allFinite()) __builtin_trap();
  return 0;
}
