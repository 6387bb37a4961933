// PrecomputedConstraintCorrection (spec/interaction.md §5.3): the full
// compliance of one body, precomputed once from unit forces and kept dense.
//
// At initialisation every DoF component gets a unit external force in turn; the
// node's EulerImplicitSolver integrates one step from rest (velocity 0,
// positions as loaded, gravity off in this node, a CGLinearSolver pushed to
// 1e-20 / 5000 iterations) and the resulting velocity, scaled by
// position factor / dt (1 for implicit Euler), is the column of
// C = h·A⁻¹ (A: the ODE solver's system matrix at the initial positions). C is
// cached in a file (compliance_cache.h) and shared in memory between
// corrections of one simulation with the same file name, as SOFA does.
//
// Role (Vec1d, Vec3d, Rigid3d):
//  * W += f·J·C·Jᵀ, f = 1 for position orders, 1/dt for velocity ones, plus
//    regularizationTerm on a diagonal entry once per Jacobian entry of the row
//    (SOFA's loop);
//  * correction c = C·Jᵀλ: x = xf ⊕ c, v = vf + c/dt (position order: x only;
//    velocity order: v = vf + c/dt);
//  * LCP path: the same through the state's force and dx vectors;
//  * unbuilt solvers: J·C·Jᵀ over this body's rows is built at the reset, the
//    displacement of a row is Σ over rows with force of W_ik·f_k.
// `rotations`: SOFA's code meant to express J in the frames of the FEM's
// rotations and rotate the response back, but since 2023 its rotation of J
// works on a copy (no effect) and the response rotation acts on the state's
// dx vector, which only the LCP path applies. Sinew reproduces exactly that.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "constraint/correction/dense_compliance.h"
#include "core/constraint_problem.h"
#include "math/types.h"

namespace sinew {

class PrecomputedConstraintCorrection final : public ConstraintCorrection {
 public:
  PrecomputedConstraintCorrection();

  Field<bool> rotations{this, "rotations", false,
                        "rotate the response by the FEM rotations (SOFA: effective on the LCP path only)",
                        "Correction"};
  Field<bool> rest_deformations{this, "restDeformations", false,
                                "Rigid3d rotations relative to the rest orientation", "Correction"};
  Field<bool> recompute{this, "recompute", false, "always recompute the compliance (do not read a cache file)",
                        "Correction"};
  Field<double> regularization_term{this, "regularizationTerm", 0.0,
                                    "added to the diagonal of W on the rows of this body", "Correction"};
  Field<double> debug_view_frame_scale{this, "debugViewFrameScale", 1.0, "scale of the drawn frames (viewer)",
                                       "Visualization", "length"};
  Field<std::string> file_compliance{this, "fileCompliance", "",
                                     "precomputed compliance file to read (SOFA's raw n×n doubles)", "Correction"};
  Field<std::string> file_dir{this, "fileDir", "",
                              "folder of the compliance cache (default: the first data folder; a temp folder "
                              "when that is not writable)",
                              "Correction"};

  void init() override;
  void bwd_init() override;  // checks the state (SOFA computes here, see ensure_compliance)
  // The compliance is loaded or precomputed when the simulation's
  // initialisation is done (SOFA does it in bwdInit, but in Sinew some
  // components the ODE solver drives, springs and preconditioners, finish
  // their set-up in their own bwd_init, which may come after this one); a
  // correction added to a running simulation does it at its first use.
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;

  void add_compliance(const ConstraintParams& p, ConstraintProblem& problem) override;
  void apply_correction(const ConstraintParams& p, const std::vector<double>& lambda, int x_out, int v_out,
                        int dx_out) override;

  bool has_constraint_row(int row) const override;
  bool supports_unbuilt() const override { return true; }
  void reset_for_unbuilt(const ConstraintParams& p, const std::vector<double>& f, std::vector<int>& sequence) override;
  void add_block_diagonal_compliance(ConstraintProblem& problem, int begin, int end) override;
  void add_constraint_displacement(std::vector<double>& d, int begin, int end) override;
  void set_constraint_dforce(const std::vector<double>& df, int begin, int end) override;

  void reset_contact_force() override;
  void apply_contact_force(const ConstraintParams& p, const std::vector<double>& f) override;

  // C (n×n row-major, n = DoFs × derivative width); empty until initialised.
  std::span<const double> compliance() const {
    return c_ ? std::span<const double>(*c_) : std::span<const double>();
  }
  std::size_t compliance_rows() const { return n_; }
  // The cache file written or read ("" when none) and how C was obtained.
  const std::string& cache_path() const { return cache_path_; }
  enum class Source { none, memory, file, computed };
  Source source() const { return source_; }

 private:
  bool ensure_compliance();
  bool obtain_compliance();
  bool load_from_files(const std::string& name);
  bool precompute(std::vector<double>& c);
  void save(const std::string& name);
  double dt() const;
  // SOFA's rotateConstraints: no change to J (see the header comment); warns
  // once when no rotation finder is found for a Vec3d state.
  void rotate_constraints();
  // SOFA's rotateResponse on `dx` (the state's dx vector of the LCP path).
  void rotate_response(std::vector<double>& dx);

  std::shared_ptr<const std::vector<double>> c_;
  std::size_t n_ = 0, dofs_ = 0;
  int w_ = 3;
  std::string cache_path_;
  Source source_ = Source::none;
  bool warned_rotation_ = false;
  bool attempted_ = false;  // ensure_compliance ran (once, success or not)
  bool warned_size_ = false;

  // Step scratch (no allocation once warm).
  dense_compliance::Work work_;
  std::vector<double> force_, corr_;
  std::vector<int> active_, mark_;
  std::vector<Mat3> rot_;
  // Unbuilt resolution: J·C·Jᵀ on this body's rows (local numbering).
  std::vector<int> id_to_local_, local_to_id_, active_local_;
  std::vector<double> local_w_;
  const std::vector<double>* unbuilt_force_ = nullptr;  // the solver's forces, updated in place
};

}  // namespace sinew
