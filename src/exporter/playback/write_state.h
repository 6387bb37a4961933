// WriteState (SOFA's Sofa.Component.Playback; spec/user-interfaces.md §4.4): the node's
// mechanical state written to a text file, a block per export:
//   T= <time>
//     X= <all coordinates>      (writeX, default on)
//     X0= <rest positions>      (writeX0)
//     V= <velocities>           (writeV)
//     F= <forces>               (writeF)
// gzip-compressed when the filename ends in ".gz" (flushed after every block, as SOFA).
//
// When: at AnimateBeginEvent, at each time of `time` (0 by default) reached within 0.1·dt,
// then, once the first of them was written, every `period` (period given: from time[0],
// which must then be the only time; neither given: every step). Same rules as SOFA's.
// Deliberate difference: numbers are written with 17 significant digits (SOFA: 6), so that
// ReadState restores a state exactly; SOFA's readers read either.
// DOFsX / DOFsV are accepted and unused, as in SOFA. stopAt / keperiod (stop when the kinetic
// energy settles) are not implemented: a warning says so and the file is written on.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "exporter/playback/text_sink.h"

namespace sinew {

class WriteState final : public Component {
 public:
  WriteState();

  Field<std::string> filename{this, "filename", "", "output file name (.gz: compressed)", "Export"};
  Field<bool> write_x{this, "writeX", true, "write the positions (X=)", "Export"};
  Field<bool> write_x0{this, "writeX0", false, "write the rest positions (X0=)", "Export"};
  Field<bool> write_v{this, "writeV", false, "write the velocities (V=)", "Export"};
  Field<bool> write_f{this, "writeF", false, "write the forces (F=)", "Export"};
  Field<std::vector<double>> time{this, "time", {}, "times of the exports (default: t = 0)", "Export", "time"};
  Field<double> period{this, "period", 0.0, "time between exports after the first", "Export", "time"};
  Field<std::vector<unsigned>> dofs_x{this, "DOFsX", {}, "position DoFs to write (unused, as in SOFA)", "Export"};
  Field<std::vector<unsigned>> dofs_v{this, "DOFsV", {}, "velocity DoFs to write (unused, as in SOFA)", "Export"};
  Field<double> stop_at{this, "stopAt", 0.0, "kinetic energy threshold (not implemented)", "Export"};
  Field<double> ke_period{this, "keperiod", 0.0, "period of the kinetic energy test (not implemented)", "Export",
                          "time"};

  void init() override;
  void reinit() override;
  void reset() override;
  void cleanup() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  // Blocks written so far.
  int exports() const { return exports_; }

 private:
  void append_vec(std::string& out, const char* tag, int id) const;

  MechanicalState* state_ = nullptr;
  TextSink out_;
  bool valid_ = false, periodic_ = false, first_export_ = false;
  std::size_t next_ = 0;
  double last_time_ = 0;
  int exports_ = 0;
};

}  // namespace sinew
