// TaskSchedulerSettings: the number of threads the scene's parallel parts
// (parallelODESolving, Parallel* collision phases, parallel assembly) may use.
// nbThreads 0: every core; −n: every core but n. Results never depend on it.
#include <algorithm>
#include <memory>
#include <thread>

#include <oneapi/tbb/global_control.h>

#include "core/registry.h"
#include "core/roles.h"

namespace sinew {

namespace {

class TaskSchedulerSettings final : public Component {
 public:
  Field<int> nb_threads{this, "nbThreads", 0,
                        "threads of the task scheduler; 0: every core, -n: every core but n", "Scheduler"};
  Field<std::string> task_scheduler_type{this, "taskSchedulerType", "_default",
                                         "kind of task scheduler (oneTBB here whatever the value)", "Scheduler"};

  void init() override {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    int n = nb_threads.value();
    if (n <= 0) n = std::max(1, cores + n);
    nb_threads.set(n);
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
