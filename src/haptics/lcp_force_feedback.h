// LCPForceFeedback (templates Vec1d, Rigid3d): the force of the contacts of
// the last simulation step, re-solved at the device rate with the device's
// current pose (SOFA's Sofa.Component.Haptics LCPForceFeedback,
// spec/interaction.md §6.2).
//
// Simulation thread, at AnimateEndEvent: a snapshot of the scene's
// LCPConstraintSolver problem (W, dfree, λ as warm start, the solver's mu and
// tolerance), the tool state's freePosition and its constraint rows (J
// accumulated onto the tool's DoFs) is written into a free buffer and
// published (a lock-free triple buffer: the writer never reuses the buffer
// the servo thread reads or the one waiting for it, so neither thread waits).
//
// Servo thread, compute_force / compute_wrench / compute_state_force:
//   1. take the newest published snapshot (its λ is the step's solution; on
//      later calls with the same snapshot, the last haptic solution);
//   2. dx = device pose − stored free position (Rigid: translation only,
//      unless derivRotations: the rotation vector too);
//   3. dfree_i += J_i·dx for every stored row (all columns read dx of DoF 0
//      with localHapticConstraintAllFrames);
//   4. Gauss-Seidel NLCP from λ with tolerance = solver tolerance × 0.001,
//      at most solverMaxIt sweeps, stopped after solverTimeout seconds;
//   5. dfree restored; force_dof = forceCoef · Σ_rows J_iᵀ λ_i (into DoF 0 with
//      the all-frames option).
// The force has the sign of the constraint force on the tool (SOFA's): it pushes
// the device out of the obstacle. Nothing in this path allocates once the
// buffers have grown to the problem's size (the simulation thread sizes them).
#pragma once

#include <array>
#include <atomic>
#include <mutex>
#include <span>
#include <vector>

#include "constraint/solver/lcp_gauss_seidel.h"
#include "haptics/force_feedback.h"

namespace sinew {
class LCPConstraintSolver;
class MechanicalState;
}  // namespace sinew

namespace sinew::haptics {

// One constraint problem as the servo thread solves it (plain data).
struct HapticProblem {
  int n = 0;                  // rows of W
  double mu = 0;              // the solver's friction coefficient
  double tolerance = 0;       // the solver's tolerance
  std::vector<double> W;      // n×n row-major
  std::vector<double> dfree;  // free violation
  std::vector<double> f;      // λ: the step's solution, then the last haptic one
  // The tool state's constraint rows (compressed): row r has id row_id[r] and
  // entries [row_begin[r], row_begin[r+1]) of (entry_dof, entry_value · width).
  std::vector<int> row_id, row_begin, entry_dof;
  std::vector<double> entry_value;
  int width = 0;                       // deriv scalars per DoF (Vec1: 1, Rigid3: 6)
  std::vector<double> free_position;   // coord scalars of every DoF
  std::size_t dofs = 0;
  // Servo work, sized by the simulation thread with the snapshot.
  std::vector<double> dx, force;
  bool valid = false;
};

class LCPForceFeedback final : public ForceFeedback {
 public:
  explicit LCPForceFeedback(bool rigid);
  ~LCPForceFeedback() override;

  Field<double> force_coef{this, "forceCoef", 0.03, "multiplies the haptic force", "Haptics"};
  Field<double> solver_timeout{this, "solverTimeout", 0.0008, "longest time one haptic solve may take", "Haptics",
                               "time"};
  Field<int> solver_max_it{this, "solverMaxIt", 100, "most Gauss-Seidel sweeps of one haptic solve", "Haptics"};
  Field<bool> deriv_rotations{this, "derivRotations", false,
                              "include the rotation of the tool (rotation vector) in the violation update",
                              "Haptics"};
  Field<bool> local_haptic_constraint_all_frames{
      this, "localHapticConstraintAllFrames", false,
      "every constraint column reads the displacement of DoF 0, and every force goes to DoF 0", "Haptics"};

  void init() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }

  // Rigid3d: the tool at p with identity orientation; the translational force.
  // Vec1d: zero (SOFA's Vec1 template answers nothing there).
  Vec3 compute_force(const Vec3& p, const Quat& q) override;
  // Rigid3d: the tool at (p, q); force and torque. Vec1d: zero.
  void compute_wrench(const Vec3& p, const Quat& q, const Vec3& v, const Vec3& w, Vec3& force,
                      Vec3& torque) override;
  // SOFA's computeForce(VecCoord, VecDeriv): `pose` holds the coord scalars of
  // pose.size()/coord_width DoFs; `forces` receives the deriv scalars of as many
  // DoFs (zero when inactive or without a problem). Thread-safe.
  void compute_state_force(std::span<const double> pose, std::span<double> forces);

  // Statistics of the servo side (atomics, any thread).
  std::uint64_t solves() const { return solves_.load(std::memory_order_relaxed); }
  std::uint64_t timeouts() const { return timeouts_.load(std::memory_order_relaxed); }
  int last_rows() const { return last_rows_.load(std::memory_order_relaxed); }
  // Snapshots published by the simulation thread.
  std::uint64_t snapshots() const { return snapshots_.load(std::memory_order_relaxed); }

 private:
  void take_snapshot();
  void solve(HapticProblem& p, std::span<const double> pose, std::span<double> forces);

  const bool rigid_;
  LCPConstraintSolver* solver_ = nullptr;
  MechanicalState* tool_ = nullptr;
  // Triple buffer: back_ belongs to the simulation thread, front_ to the servo
  // thread; shared_ holds the third index, with kFresh set when the writer
  // published it after the reader's last take.
  static constexpr unsigned kFresh = 4;
  std::array<HapticProblem, 3> buffers_;
  unsigned back_ = 0, front_ = 1;
  std::atomic<unsigned> shared_{2};
  std::mutex servo_mutex_;  // one servo-side computation at a time (SOFA's lockForce)
  std::atomic<std::uint64_t> solves_{0}, timeouts_{0}, snapshots_{0};
  std::atomic<int> last_rows_{0};
};

}  // namespace sinew::haptics
