// CompareState (SOFA's Sofa.Component.Playback): reads a state file as ReadState does (same
// Data) but, instead of replaying it, compares the node's state with it at every
// AnimateBeginEvent: the last block due at time + shift (0.001·dt margin) adds, per X=/V=
// line, the mean absolute difference between the file's numbers and the live values as SOFA
// prints them (6 significant digits). The sums are SOFA's totalError_X/V and dofError;
// with printLog they are reported when the simulation closes. It is the regression metric
// (src/regression/state_compare.h), here as a scene component. With `loop` the file starts
// again after its end, its times shifted by the last time read (ReadState's rule).
#pragma once

#include <memory>

#include "exporter/playback/read_state.h"
#include "regression/state_compare.h"

namespace sinew {

class CompareState final : public ReadState {
 public:
  void init() override;
  void bwd_init() override {}
  void handle_event(Event& e) override;
  void cleanup() override;
  // Σ over compared lines of the error divided by the number of points (SOFA's getErrorByDof).
  double error_by_dof() const { return comparer_ ? comparer_->error() : 0.0; }
  // Σ of the plain errors (SOFA's getTotalError).
  double total_error() const { return comparer_ ? comparer_->total_error() : 0.0; }
  int compared_blocks() const { return comparer_ ? comparer_->compared_blocks() : 0; }

 private:
  std::unique_ptr<regression::StateComparer> comparer_;
};

}  // namespace sinew
