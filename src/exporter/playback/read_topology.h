// ReadTopology (SOFA's Sofa.Component.Playback): reads a topology file (WriteTopology's format,
// plain or gzip) and, at every AnimateBeginEvent, exposes the element lists of the last block
// due at time + shift. The node's topology is not changed, as in SOFA: the lists are outputs
// for other components (or for CompareTopology, which derives from this reader).
//
// Schedule (SOFA's readNext): blocks are read while their time is <= t + 1e-8 and kept when
// <= t, the last kept one giving the outputs (regression::BlockSchedule, whose quirks apply:
// a block printed just above the clock is read and dropped). `loop` reads the file again
// from its start, its times shifted by the last time read. A time going back (a reset) reads
// the file again from its start.
// Deliberate difference: SOFA appends each due block's elements to its lists (they grow at
// every step); here the lists hold the due block's elements. The lists are Data that SOFA does
// not name (not reachable from a scene); here they are named outputs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/roles.h"
#include "regression/block_schedule.h"
#include "regression/topology_file.h"

namespace sinew {

class ReadTopology : public Component {
 public:
  ReadTopology();

  Field<std::string> filename{this, "filename", "", "topology file to read (plain or gzip)", "Export"};
  Field<double> interval{this, "interval", 0.0, "time between inputs (unused, as in SOFA)", "Export", "time"};
  Field<double> shift{this, "shift", 0.0, "added to the simulation time to find the block to read", "Export", "time"};
  Field<bool> loop{this, "loop", false, "read the file again from its start when its end is reached", "Export"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the file describes (default: the node's or above)"};

  Field<std::vector<Edge>> edges{this, "edges", {}, "edges of the block read last", "Outputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the block read last", "Outputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the block read last", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedra of the block read last", "Outputs"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedra of the block read last", "Outputs"};

  void init() override;
  void reset() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  // Blocks read into the outputs so far.
  int blocks_read() const { return read_; }

 protected:
  // Parses the file and restarts the schedule; false (error reported) when it cannot be read.
  bool open();
  // The block due at the node's time + shift, if one became due at this event.
  const regression::TopologyBlock* advance();

  std::vector<regression::TopologyBlock> blocks_;
  bool opened_ = false;

 private:
  void publish(const regression::TopologyBlock& b);

  std::optional<regression::BlockSchedule> schedule_;
  double last_time_ = 0;
  int read_ = 0;
  bool warned_short_ = false;
};

}  // namespace sinew
