#include "exporter/simulation_exporter.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace sinew {

SimulationExporter::SimulationExporter() = default;

std::string SimulationExporter::base_name() const {
  return filename.get().empty() ? name.get() : filename.get();
}

void SimulationExporter::init() {
  if (filename.get().empty()) filename.set(name.get());
  do_init();
}

void SimulationExporter::reinit() { init(); }

bool SimulationExporter::wants_events() const {
  // SOFA switches listening on when an export is due at begin or every n steps.
  return listening.get() || export_every.get() != 0 || export_at_begin.get();
}

void SimulationExporter::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_end) {
    if (!enable.get() || export_every.get() == 0) return;
    ++step_counter_;
    if (step_counter_ % export_every.get() == 0) write();
  } else if (e.kind == Event::Kind::simulation_init_done) {
    if (enable.get() && export_at_begin.get()) write();
  }
}

void SimulationExporter::cleanup() {
  if (enable.get() && export_at_end.get()) write();
}

std::string SimulationExporter::target_path(const std::string& base, bool autonumber) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path path = fs::path(base).lexically_normal();
  if (fs::is_directory(path, ec)) path /= name.get();
  if (path.has_parent_path() && !fs::exists(path.parent_path(), ec)) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) {
      msg_error("filename: cannot create the folder " + path.parent_path().string() + ": " + ec.message());
      return {};
    }
  }
  std::string out = path.string();
  if (autonumber && export_every.get() != 0) {
    char number[16];
    std::snprintf(number, sizeof number, "%05u", step_counter_ / export_every.get());
    out += number;
  }
  return out;
}

}  // namespace sinew
