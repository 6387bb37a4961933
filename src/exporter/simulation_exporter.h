// The behaviour SOFA's exporters share (BaseSimulationExporter; spec/user-interfaces.md §4.1):
// `filename` (default: the component's name), `exportEveryNumberOfSteps` (counted at each
// AnimateEndEvent, 0 = never), `exportAtBegin` (once the simulation is initialised:
// SimulationInitDoneEvent), `exportAtEnd` (when the simulation is closed: cleanup) and
// `enable`. Subclasses write one export in write().
//
// Paths: a relative filename is relative to the working directory, as SOFA's (its
// DataFileName only resolves names that already exist in the data path; Sinew never
// looks there, so an exporter cannot overwrite a file of the data tree). A filename naming
// an existing folder gets the component's name appended; missing parent folders are created.
#pragma once

#include <string>

#include "core/component.h"

namespace sinew {

class SimulationExporter : public Component {
 public:
  SimulationExporter();

  Field<std::string> filename{this, "filename", "",
                              "path or file name to export to (default: the component's name)", "Export"};
  Field<unsigned> export_every{this, "exportEveryNumberOfSteps", 0u,
                               "export every that many steps (0: never)", "Export"};
  Field<bool> export_at_begin{this, "exportAtBegin", false, "export once the simulation is initialised", "Export"};
  Field<bool> export_at_end{this, "exportAtEnd", false, "export when the simulation is closed", "Export"};
  Field<bool> enable{this, "enable", true, "enable or disable the exports", "Export"};

  void init() final;
  void reinit() final;
  void cleanup() override;
  void handle_event(Event& e) override;
  bool wants_events() const override;

  // One export now; false (after a message) when it could not be written.
  virtual bool write() = 0;
  // Steps counted so far (AnimateEndEvent while exportEveryNumberOfSteps > 0).
  unsigned step_counter() const { return step_counter_; }

 protected:
  virtual void do_init() {}
  // `base` made ready to write: an existing folder gets the component's name, parent
  // folders are created; with `autonumber`, the export index (step counter divided by
  // exportEveryNumberOfSteps) is appended on five digits, as SOFA's exporters number files.
  // Empty (after an error naming the component) when the folder cannot be created.
  std::string target_path(const std::string& base, bool autonumber);
  // The filename field, or the component's name when it is empty.
  std::string base_name() const;

 private:
  unsigned step_counter_ = 0;
};

}  // namespace sinew
