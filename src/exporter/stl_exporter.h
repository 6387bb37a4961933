// STLExporter (SOFA's Sofa.Component.IO.Mesh; spec/user-interfaces.md §4.3): a surface as an
// STL file, `<filename>.stl`, numbered `<filename>NNNNN.stl` with exportEveryNumberOfSteps.
//
// position / triangle (alias triangles) / quad (alias quads): given, else taken from the
// node's visual model (OglModel), else from its topology (this node only, as SOFA). Quads
// are split (0 1 2)(0 2 3) when there are no triangles.
// binaryformat (default true): binary STL (80-byte header, count, facets); false: ASCII.
// Two deliberate differences from SOFA, whose writer swaps the two formats and leaves the
// binary header out: Sinew writes what the flag says, with the header, so any STL reader
// opens it; facets carry their unit normal (SOFA writes 0 0 0).
#pragma once

#include "core/roles.h"
#include "exporter/simulation_exporter.h"

namespace sinew {

class STLExporter final : public SimulationExporter {
 public:
  STLExporter();

  Field<bool> binary_format{this, "binaryformat", true, "binary STL (false: ASCII)", "Export"};
  Field<FlatVec> position;
  Field<std::vector<Triangle>> triangle{this, "triangle", {}, "triangles written", "Export"};
  Field<std::vector<Quad>> quad{this, "quad", {}, "quads written (split in two triangles) when there are no triangles",
                                "Export"};

  bool write() override { return write_file(true); }
  void handle_event(Event& e) override;

 private:
  void do_init() override;
  // `numbered`: the export index is appended when exportEveryNumberOfSteps is set.
  bool write_file(bool numbered);
};

}  // namespace sinew
