// StepThread: the viewer's simulation steps, run on a thread of their own.
//
// The viewer starts a step, draws the state before it while it runs, then waits for it
// before anything touches the scene again (input, panels, the next picture). A frame then
// lasts the longer of step and drawing, not their sum, and the step has a CPU of its own
// while a software renderer draws on the others. One step per frame still, as SOFA's viewer:
// a picture shows the state one step behind the step being computed.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace sinew::viewer {

class StepThread {
 public:
  // `step` runs on the thread, one call per start(); it returns false when the step failed.
  explicit StepThread(std::function<bool()> step);
  ~StepThread();  // waits for a running step, then ends the thread
  StepThread(const StepThread&) = delete;
  StepThread& operator=(const StepThread&) = delete;

  // Starts one step. Precondition: none running (busy() false).
  void start();
  bool busy() const { return busy_; }
  // Waits for the started step: its result, and in `ms` its duration (milliseconds) measured
  // on the thread. Rethrows what the step threw. Precondition: busy().
  bool wait(double* ms);

 private:
  void loop();

  std::function<bool()> step_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool requested_ = false, done_ = false, stop_ = false;
  bool busy_ = false;  // read and written by the viewer's thread only
  bool result_ = false;
  double ms_ = 0;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace sinew::viewer
