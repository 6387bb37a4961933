// WriteTopology (SOFA's Sofa.Component.Playback): a mesh topology's element lists written to
// a text file, the format of the regression's topology references (regression/topology_file.h):
//   T= <time>
//     Edges= <n>
//   <2n indices>
//     Triangles= ... Quads= ... Tetrahedra= ... Hexahedra= ...
// gzip-compressed when the filename ends in ".gz", flushed after every block.
//
// When, at each AnimateBeginEvent (SOFA's rule, no tolerance): while times of `time` are left,
// when the clock reaches the next one (t >= time[i]); after them, every `period` from the last
// (t >= last + period). With the defaults (no time, period 0) that is every step; note that a
// list of times with period 0 goes on writing at every step once the list is done, as in SOFA.
// Times are printed with 6 significant digits, as SOFA's stream. `interval` is accepted and
// unused, as in SOFA; `writeShellContainers` writes nothing (SOFA writes a "not handled" line).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "exporter/playback/text_sink.h"

namespace sinew {

class WriteTopology final : public Component {
 public:
  WriteTopology();

  Field<std::string> filename{this, "filename", "", "output file name (.gz: compressed)", "Export"};
  Field<bool> write_containers{this, "writeContainers", true,
                               "write the edges, triangles, quads, tetrahedra and hexahedra", "Export"};
  Field<bool> write_shell_containers{this, "writeShellContainers", false,
                                     "write the shell containers (not handled, as in SOFA)", "Export"};
  Field<double> interval{this, "interval", 0.0, "time between outputs (unused, as in SOFA)", "Export", "time"};
  Field<std::vector<double>> time{this, "time", {}, "times of the outputs", "Export", "time"};
  Field<double> period{this, "period", 0.0, "time between outputs after the listed times", "Export", "time"};
  Link<MeshTopologyBase> topology{this, "topology", "topology written (default: the node's or the nearest above)"};

  void init() override;
  void reset() override;
  void cleanup() override { out_.close(); }
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  // Blocks written so far.
  int exports() const { return exports_; }

 private:
  TextSink out_;
  std::size_t next_ = 0;
  double last_time_ = 0;
  int exports_ = 0;
};

}  // namespace sinew
