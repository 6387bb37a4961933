// TaskSchedulerSettings: the number of threads the scene's parallel parts
// (parallelODESolving, Parallel* collision phases, parallel assembly) may use.
// nbThreads 0: every core; −n: every core but n. Results never depend on it.
#include <memory>

#include <oneapi/tbb/global_control.h>

#include "core/registry.h"
#include "core/roles.h"
#include "core/task_scheduler_fields.h"

namespace sinew {

namespace {

class TaskSchedulerSettings final : public Component {
 public:
  TaskSchedulerFields scheduler{this};

  void init() override {
    const int n = scheduler.resolve();
    // Held for the component's lifetime: the limit ends with the scene.
    limit_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                   static_cast<std::size_t>(n));
  }

 private:
  std::unique_ptr<tbb::global_control> limit_;
};

}  // namespace

void register_task_scheduler_settings(Registry& r) {
  ComponentInfo info;
  info.name = "TaskSchedulerSettings";
  info.category = "Setting";
  info.description = "number of threads of the parallel parts of the step";
  info.create = creator<TaskSchedulerSettings>();
  r.add(std::move(info));
}

}  // namespace sinew
