#include "viewer/step_thread.h"

#include <chrono>

namespace sinew::viewer {

StepThread::StepThread(std::function<bool()> step) : step_(std::move(step)), thread_([this] { loop(); }) {}

StepThread::~StepThread() {
  {
    std::unique_lock lock(mutex_);
    cv_.wait(lock, [&] { return !requested_ || done_; });
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void StepThread::start() {
  {
    std::lock_guard lock(mutex_);
    requested_ = true, done_ = false, error_ = nullptr;
  }
  busy_ = true;
  cv_.notify_all();
}

bool StepThread::wait(double* ms) {
  std::unique_lock lock(mutex_);
  cv_.wait(lock, [&] { return done_; });
  requested_ = done_ = false;
  busy_ = false;
  if (ms) *ms = ms_;
  if (error_) std::rethrow_exception(error_);
  return result_;
}

void StepThread::loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    cv_.wait(lock, [&] { return stop_ || (requested_ && !done_); });
    if (stop_) return;
    lock.unlock();
    bool ok = false;
    std::exception_ptr error;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      ok = step_();
    } catch (...) {
      error = std::current_exception();
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    lock.lock();
    result_ = ok, ms_ = ms, error_ = error, done_ = true;
    cv_.notify_all();
  }
}

}  // namespace sinew::viewer
