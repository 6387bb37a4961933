// The state comparer and its verdict (regression-protocol.md §5, §6).
//
// Metric, per compared block and per X=/V= line of the reference, for a live
// state of P points: the live scalars are rounded to 6 significant digits
// (format_g6, read back), K = length of the common prefix of the reference and
// live sequences (each ends at its first non-number such as nan/inf),
// e = sum |ref_i - cur_i| / K (0 if K = 0), and the file error E_f gets e / P
// (skipped if P = 0). The scene value is the node-weighted mean of the E_f.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "regression/block_schedule.h"
#include "regression/state_file.h"

namespace sinew::regression {

// Mean absolute difference e between a reference line and live values (the
// first step of the metric above). `live` holds raw (unrounded) values; they
// are rounded here. Arithmetic is in double (all stored scenes are double).
double mean_abs_difference(std::span<const double> reference, std::span<const double> live);

// One reference file being compared against one live state.
class StateComparer {
 public:
  // `blocks`: the parsed reference file; `dt`: the root time step, which sets
  // the reading margin 0.001*dt.
  StateComparer(std::vector<StateBlock> blocks, double dt);

  // Call at the start of every step (before solving) with the event time t
  // (accumulated as t(k+1) = t(k) + dt, starting at 0) and the live state:
  // positions x (nx scalars), velocities v (nv scalars; null if the state has
  // none: V= lines then compare nothing), `npoints` points.
  // Compares the last reference block that became due, if any.
  void on_step_begin(double t, const double* x, std::size_t nx, const double* v, std::size_t nv,
                     std::size_t npoints);

  // Compare the file again from its start when its end is reached (CompareState's `loop`;
  // BlockSchedule::set_loop).
  void set_loop(bool on) { schedule_.set_loop(on); }

  // E_f: sum over compared blocks and lines of e / P. This decides the verdict.
  double error() const { return error_; }
  // Sum of the plain e values (reported by SOFA, not used for the verdict).
  double total_error() const { return total_error_; }
  int compared_blocks() const { return static_cast<int>(results_.size()); }

  // What happened at each comparison, for diagnostics.
  struct BlockResult {
    double block_time;    // printed time of the reference block
    double event_time;    // clock at which it was compared
    double contribution;  // sum over its lines of e / P
  };
  const std::vector<BlockResult>& results() const { return results_; }

 private:
  std::vector<StateBlock> blocks_;
  BlockSchedule schedule_;
  double margin_;
  double error_ = 0.0;
  double total_error_ = 0.0;
  std::vector<BlockResult> results_;
};

// Scene value from (E_f, weight) pairs, weight = number of graph nodes whose
// nearest comparer is f: sum(w*E) / sum(w). NaN when there is no comparer
// (or all weights are 0), which passes (see scene_passes).
double scene_value(const std::vector<std::pair<double, int>>& errors_and_weights);

// The state verdict: passes unless value > epsilon (so NaN passes).
bool scene_passes(double value, double epsilon);

}  // namespace sinew::regression
