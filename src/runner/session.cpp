#include "runner/session.h"

#include <exception>
#include <new>

#include "components/register_all.h"
#include "core/simulation.h"
#include "scene/resource_paths.h"

namespace sinew::runner {

std::vector<std::string> sofa_data_paths(const std::string& data_root) {
  return {data_root + "/share", data_root + "/examples"};
}

std::string find_data_file(const std::vector<std::string>& data_paths, const std::string& name) {
  scene::ResourcePaths paths;
  for (const std::string& dir : data_paths) paths.add(dir);
  paths.add_from_env();
  return paths.resolve(name, "").value_or(std::string());
}

Session::Session(const std::string& path, const SessionOptions& options) {
  register_all_components();
  scene::LoadOptions lo;
  lo.data_paths = options.data_paths;
  lo.script_args = options.script_args;
  // Loading and init never let an exception out (an allocation that failed
  // despite the size checks, a bug): it becomes an error and the scene is refused.
  try {
    scene_ = scene::load_scene(path, lo, load_diag_);
  } catch (const std::bad_alloc&) {
    scene_ = {};
    load_diag_.error({path, 0}, "loading failed: out of memory (a size in the scene is too large?)");
    return;
  } catch (const std::exception& e) {
    scene_ = {};
    load_diag_.error({path, 0}, std::string("loading failed: ") + e.what());
    return;
  }
  if (!scene_.root) return;
  if (scene_.root->diagnostics().has_errors()) return;  // refused whole, never half-run
  try {
    init_root(*scene_.root);
  } catch (const std::bad_alloc&) {
    scene_.root->diagnostics().error({path, 0},
                                     "initialisation failed: out of memory (a size in the scene is too large?)");
  } catch (const std::exception& e) {
    scene_.root->diagnostics().error({path, 0}, std::string("initialisation failed: ") + e.what());
  }
}

Session::~Session() {
  try {
    close();
  } catch (...) {  // a destructor lets nothing out; close() reports its own errors
  }
}

void Session::close() {
  // Only a simulation that was initialised is cleaned up: SOFA never runs cleanup on a
  // scene that failed to load, so no exporter writes from a half-built graph.
  if (scene_.root && scene_.root->initialised && !load_diag_.has_errors()) cleanup_root(*scene_.root);
}

bool Session::step() {
  if (!ok()) return false;
  try {
    scene_.root->step_index = steps_;
    animate(*scene_.root);
  } catch (const std::exception& e) {
    scene_.root->diagnostics().error({}, "step " + std::to_string(steps_) + " failed: " + e.what());
    return false;
  }
  ++steps_;
  return !scene_.root->diagnostics().has_errors();
}

}  // namespace sinew::runner
