// The Gauss-Seidel kernels of LCPConstraintSolver (spec/interaction.md §5.5),
// free functions over plain arrays (W row-major n×n): SOFA's
// helper::nlcp_gaussseidel, gaussSeidelLCP1 and the 3×3 contact updates
// (LocalBlock33::GS_State / New_GS_State) the unbuilt solver also uses.
#pragma once

#include <chrono>
#include <vector>

namespace sinew {

struct LcpResult {
  int iterations = 0;  // sweeps done (SOFA's "GS iterations")
  double error = 0.0;  // error of the last sweep
  bool converged = false;
  bool timed_out = false;  // nlcp_gauss_seidel_timed: stopped by its deadline
};

// The six distinct entries of a symmetric 3×3 contact block: W00 W01 W02 W11 W12 W22.
struct ContactBlock33 {
  double w[6] = {};
};

// Built update of one contact (normal, t, s) from its old forces (fn, ft, fs)
// and the violation (dn, dt, ds) without its own contribution: normal
// projection, tangential update with the averaged compliance (W11+W22)/2,
// Coulomb cone |(ft,fs)| ≤ mu·fn. On return (dn, dt, ds) include the new
// forces, except when the contact separates (forces zero, d unchanged).
void contact_gs_state(const ContactBlock33& b, double mu, double& dn, double& dt, double& ds, double& fn, double& ft,
                      double& fs);

// Unbuilt update: (dn, dt, ds) already include the old forces; on return
// they include the change of force.
void contact_new_gs_state(const ContactBlock33& b, double mu, double& dn, double& dt, double& ds, double& fn,
                          double& ft, double& fs);

// Nonlinear (friction) LCP by Gauss-Seidel over contacts of 3 rows. f holds
// the initial guess when use_initial_f (else it is zeroed). Converged when
// the sum over contacts of |d_new − d_old| < tol·(contacts + 1). min_w ≠ 0:
// contacts with |W_nn| ≤ min_w get no force; max_f ≠ 0: after convergence,
// contacts with |fn| ≥ max_f are released. n must be a multiple of 3.
LcpResult nlcp_gauss_seidel(int n, const double* dfree, const double* W, double* f, double mu, double tol, int max_it,
                            bool use_initial_f, double min_w, double max_f);

// SOFA's nlcp_gaussseidelTimed, the haptic re-solve of LCPForceFeedback: the
// same sweeps starting from f as given (warm start, always), without the
// min_w / max_f rules; converged when the error of a sweep is below `tol`
// (not scaled by the contact count); stops as soon as the clock passes
// `deadline` (checked after each contact, so f may be half a sweep newer).
// Allocates nothing. n must be a multiple of 3 (else f is left as it is).
LcpResult nlcp_gauss_seidel_timed(int n, const double* dfree, const double* W, double* f, double mu, double tol,
                                  int max_it, std::chrono::steady_clock::time_point deadline);

// Frictionless LCP (1 row per constraint), SOFA's gaussSeidelLCP1: starts
// from zero forces; converged when Σ|W_ii Δf_i| < tol (not scaled).
// `work` is a 2n buffer reused between calls.
LcpResult gauss_seidel_lcp1(int n, const double* q, const double* M, double* f, double tol, int max_it, double min_w,
                            double max_f, std::vector<double>& work);

}  // namespace sinew
