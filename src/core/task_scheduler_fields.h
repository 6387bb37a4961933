// The two Data of SOFA's TaskSchedulerUser (nbThreads, taskSchedulerType), shared by the
// components that take them (TaskSchedulerSettings, ParallelHexahedronFEMForceField). Sinew's
// scheduler is oneTBB whatever the type says; results never depend on the thread count.
#pragma once

#include <algorithm>
#include <string>
#include <thread>

#include "core/field.h"

namespace sinew {

struct TaskSchedulerFields {
  explicit TaskSchedulerFields(Base* owner)
      : nb_threads{owner, "nbThreads", 0, "threads of the task scheduler; 0: every core, -n: every core but n",
                   "Scheduler"},
        task_scheduler_type{owner, "taskSchedulerType", "_default",
                            "kind of task scheduler (oneTBB here whatever the value)", "Scheduler"} {}

  // nbThreads resolved as SOFA does (0: every core, -n: every core but n; at least 1 here)
  // and written back.
  int resolve() {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    int n = nb_threads.value();
    if (n <= 0) n = std::max(1, cores + n);
    nb_threads.set(n);
    if (task_scheduler_type.value().empty()) task_scheduler_type.set("_default");
    return n;
  }

  Field<int> nb_threads;
  Field<std::string> task_scheduler_type;
};

}  // namespace sinew
