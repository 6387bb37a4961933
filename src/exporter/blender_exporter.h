// BlenderExporter (Vec3d, Rigid3d; SOFA's Sofa.Component.IO.Mesh): the node's
// mechanical state as a Blender point cache, `<filename>[NNNNN]_00.bphys`
// (numbered with exportEveryNumberOfSteps, see SimulationExporter).
//
// Format (little-endian): "BPHYSICS", then unsigned type (simulationType:
// 0 soft body, 1 particles, 2 cloth; hair (3) is written as cloth), unsigned
// point count, unsigned data flags (6: location and velocity; 22 for hair:
// also the rest position), then per point from the last to the first: float
// position[3], float velocity[3] (zero when absent), and for hair the rest
// position[3]; hair strands (every nbPtsByHair points) get an extra root point
// one unit along the strand's first segment. With hair, init also writes the
// info frame SOFA writes (`<filename>`: "BPHYSICS", 1 1 64, 0.f 100.f 100.f).
// `path`, `baseName` and `step` are SOFA Data that its writer does not read;
// accepted. Rigid3d states export their centres and linear velocities.
#pragma once

#include "core/roles.h"
#include "exporter/simulation_exporter.h"

namespace sinew {

class BlenderExporter final : public SimulationExporter {
 public:
  Field<std::string> path{this, "path", "", "output path (not read by SOFA's writer)", "Export"};
  Field<std::string> base_name_f{this, "baseName", "", "base name of the output files (not read by SOFA's writer)",
                                 "Export"};
  Field<int> simulation_type{this, "simulationType", 0,
                             "0: soft body, 1: particles, 2: cloth, 3: hair", "Export"};
  Field<int> step{this, "step", 2, "save every that many frames (not read by SOFA's writer)", "Export"};
  Field<int> nb_pts_by_hair{this, "nbPtsByHair", 20, "points per hair strand (simulationType 3)", "Export"};

  bool write() override;

 private:
  void do_init() override;
  MechanicalState* state_ = nullptr;
};

}  // namespace sinew
