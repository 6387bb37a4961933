// ParallelHexahedronFEMForceField (SOFA's MultiThreading plugin): HexahedronFEMForceField
// whose addForce (method large) and addDForce run on the task scheduler. Sinew's hexahedral
// kernel already evaluates large grids in parallel with a deterministic gather, so this is
// the same force field with SOFA's scheduler fields: the results are bit-identical to
// HexahedronFEMForceField whatever the thread count.
//
// nbThreads is honoured with a task arena of that many threads around the evaluation
// (0: every core, -n: every core but n, written back as SOFA does); a global limit
// (TaskSchedulerSettings, Sofa.Core.TaskScheduler.init) still caps it. Methods other than
// large evaluate addForce sequentially, with SOFA's warning.
#include <memory>

#include <oneapi/tbb/task_arena.h>

#include "core/registry.h"
#include "core/task_scheduler_fields.h"
#include "forcefield/fem/hexahedron_fem_force_field.h"

namespace sinew {

namespace {

class ParallelHexahedronFEMForceField final : public HexahedronFEMForceField {
 public:
  TaskSchedulerFields scheduler{this};

  void init() override {
    HexahedronFEMForceField::init();
    const int n = scheduler.resolve();
    arena_ = std::make_unique<tbb::task_arena>(n);
    serial_ = std::make_unique<tbb::task_arena>(1);
  }

  void add_force(const MechParams& p) override {
    if (update_stiffness_matrix.value() && !warned_update_) {
      msg_warning("Updating the stiffness matrix is not fully supported in a multithreaded context. "
                  "Set 'updateStiffnessMatrix' to false to remove this warning.");
      warned_update_ = true;
    }
    if (method.value() != "large") {
      if (!warned_method_)
        msg_warning("Multithreading is only partially supported for other methods than 'large'");
      warned_method_ = true;
      run(serial_, [&] { HexahedronFEMForceField::add_force(p); });
      return;
    }
    run(arena_, [&] { HexahedronFEMForceField::add_force(p); });
  }

  void add_dforce(const MechParams& p, double kfactor) override {
    run(arena_, [&] { HexahedronFEMForceField::add_dforce(p, kfactor); });
  }

 private:
  // Runs f in the arena (directly when init has not made it).
  template <class F>
  static void run(const std::unique_ptr<tbb::task_arena>& arena, F&& f) {
    if (arena) arena->execute(f);
    else f();
  }

  std::unique_ptr<tbb::task_arena> arena_, serial_;
  bool warned_method_ = false, warned_update_ = false;
};

}  // namespace

void register_parallel_hexahedron_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "ParallelHexahedronFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "HexahedronFEMForceField evaluated on the task scheduler (same results)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ParallelHexahedronFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
