#include "constraint/solver/lcp_gauss_seidel.h"

#include <cmath>
#include <cstddef>

namespace sinew {

namespace {

double abs_error(double ax, double ay, double az, double bx, double by, double bz) {
  return std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay) + (bz - az) * (bz - az));
}

}  // namespace

void contact_gs_state(const ContactBlock33& b, double mu, double& dn, double& dt, double& ds, double& fn, double& ft,
                      double& fs) {
  const double* w = b.w;
  const double d0 = w[0] * fn + w[1] * ft + w[2] * fs + dn;
  fn -= d0 / w[0];
  if (fn < 0) {
    fn = ft = fs = 0.0;
    return;
  }
  const double d1 = w[1] * fn + w[3] * ft + w[4] * fs + dt;
  const double d2 = w[2] * fn + w[4] * ft + w[5] * fs + ds;
  ft -= 2 * d1 / (w[3] + w[5]);
  fs -= 2 * d2 / (w[3] + w[5]);
  const double norm_t = std::sqrt(ft * ft + fs * fs);
  if (norm_t > mu * fn) {
    ft *= mu * fn / norm_t;
    fs *= mu * fn / norm_t;
  }
  dn += w[0] * fn + w[1] * ft + w[2] * fs;
  dt += w[1] * fn + w[3] * ft + w[4] * fs;
  ds += w[2] * fn + w[4] * ft + w[5] * fs;
}

void contact_new_gs_state(const ContactBlock33& b, double mu, double& dn, double& dt, double& ds, double& fn,
                          double& ft, double& fs) {
  const double* w = b.w;
  const double f0[3] = {fn, ft, fs};
  fn -= dn / w[0];
  auto add_change = [&] {
    const double df0 = fn - f0[0], df1 = ft - f0[1], df2 = fs - f0[2];
    dn += w[0] * df0 + w[1] * df1 + w[2] * df2;
    dt += w[1] * df0 + w[3] * df1 + w[4] * df2;
    ds += w[2] * df0 + w[4] * df1 + w[5] * df2;
  };
  if (fn <= 0) {
    fn = ft = fs = 0.0;
    if (f0[0] > 0) add_change();  // the contact pushed before: d loses its force
    return;
  }
  const double d1 = w[1] * (fn - f0[0]) + dt;
  const double d2 = w[2] * (fn - f0[0]) + ds;
  ft -= 2 * d1 / (w[3] + w[5]);
  fs -= 2 * d2 / (w[3] + w[5]);
  const double norm_t = std::sqrt(ft * ft + fs * fs);
  if (norm_t > mu * fn) {
    ft *= mu * fn / norm_t;
    fs *= mu * fn / norm_t;
  }
  add_change();
}

namespace {

// One Gauss-Seidel update of contact c (rows 3c..3c+2), SOFA's loop body of
// nlcp_gaussseidel: returns the contact's error |d_new − d_old|.
double nlcp_contact_update(int n, int c, const double* dfree, const double* W, double* f, double mu, double min_w) {
  auto w = [W, n](int i, int j) { return W[static_cast<std::size_t>(i) * n + j]; };
  const int j = 3 * c;
  const double f1[3] = {f[j], f[j + 1], f[j + 2]};
  f[j] = f[j + 1] = f[j + 2] = 0.0;
  // Violation from the other contacts only. Contacts without force add
  // exact zeros: skipping them changes no bit and saves most of the work.
  double dn = dfree[j], dt = dfree[j + 1], ds = dfree[j + 2];
  const double* w0 = &W[static_cast<std::size_t>(j) * n];
  const double* w1 = w0 + n;
  const double* w2 = w1 + n;
  for (int i = 0; i < n; i += 3) {
    if (f[i] == 0.0 && f[i + 1] == 0.0 && f[i + 2] == 0.0) continue;
    for (int l = i; l < i + 3; ++l) {
      dn += w0[l] * f[l];
      dt += w1[l] * f[l];
      ds += w2[l] * f[l];
    }
  }
  double d1[3];
  for (int l = 0; l < 3; ++l) d1[l] = (l == 0 ? dn : l == 1 ? dt : ds) + w(j + l, j) * f1[0] +
                                      w(j + l, j + 1) * f1[1] + w(j + l, j + 2) * f1[2];
  double fn = 0.0, ft = 0.0, fs = 0.0;
  if (!(min_w != 0.0 && std::fabs(w(j, j)) <= min_w)) {
    ContactBlock33 b;
    b.w[0] = w(j, j);
    b.w[1] = w(j, j + 1);
    b.w[2] = w(j, j + 2);
    b.w[3] = w(j + 1, j + 1);
    b.w[4] = w(j + 1, j + 2);
    b.w[5] = w(j + 2, j + 2);
    fn = f1[0];
    ft = f1[1];
    fs = f1[2];
    contact_gs_state(b, mu, dn, dt, ds, fn, ft, fs);
  }
  f[j] = fn;
  f[j + 1] = ft;
  f[j + 2] = fs;
  return abs_error(dn, dt, ds, d1[0], d1[1], d1[2]);
}

}  // namespace

LcpResult nlcp_gauss_seidel(int n, const double* dfree, const double* W, double* f, double mu, double tol, int max_it,
                            bool use_initial_f, double min_w, double max_f) {
  LcpResult r;
  if (n % 3 != 0) return r;
  const int contacts = n / 3;
  if (!use_initial_f)
    for (int i = 0; i < n; ++i) f[i] = 0.0;
  int it = 0;
  double error = 0.0;
  for (it = 0; it < max_it; ++it) {
    error = 0.0;
    for (int c = 0; c < contacts; ++c) error += nlcp_contact_update(n, c, dfree, W, f, mu, min_w);
    if (error < tol * (contacts + 1)) {
      if (max_f != 0.0)
        for (int c = 0; c < contacts; ++c)
          if (std::fabs(f[3 * c]) >= max_f) f[3 * c] = f[3 * c + 1] = f[3 * c + 2] = 0.0;
      r.iterations = it + 1;
      r.error = error;
      r.converged = true;
      return r;
    }
  }
  r.iterations = it;
  r.error = error;
  return r;
}

LcpResult nlcp_gauss_seidel_timed(int n, const double* dfree, const double* W, double* f, double mu, double tol,
                                  int max_it, std::chrono::steady_clock::time_point deadline) {
  LcpResult r;
  if (n % 3 != 0) return r;
  const int contacts = n / 3;
  int it = 0;
  double error = 0.0;
  for (it = 0; it < max_it; ++it) {
    error = 0.0;
    for (int c = 0; c < contacts; ++c) {
      error += nlcp_contact_update(n, c, dfree, W, f, mu, 0.0);
      if (std::chrono::steady_clock::now() > deadline) {
        r.iterations = it + 1;
        r.error = error;
        r.timed_out = true;
        return r;
      }
    }
    if (error < tol) {
      r.iterations = it + 1;
      r.error = error;
      r.converged = true;
      return r;
    }
  }
  r.iterations = it;
  r.error = error;
  return r;
}

LcpResult gauss_seidel_lcp1(int n, const double* q, const double* M, double* f, double tol, int max_it, double min_w,
                            double max_f, std::vector<double>& work) {
  // SOFA's layout: res[0..n) = violations, res[n..2n) = forces. SOFA reads
  // the forces from past the end of its n-vector; they are taken as zero.
  work.assign(2 * static_cast<std::size_t>(n), 0.0);
  double* res = work.data();
  auto m = [M, n](int i, int j) { return M[static_cast<std::size_t>(i) * n + j]; };
  LcpResult r;
  double error = 0.0;
  int it = 0;
  for (it = 0; it < max_it; ++it) {
    error = 0.0;
    for (int i = 0; i < n; ++i) {
      res[i] = q[i];
      for (int k = 0; k < n; ++k) res[i] += m(i, k) * res[n + k];
      res[i] -= m(i, i) * res[n + i];
      const double f1 = res[n + i];
      if (min_w != 0.0 && std::fabs(m(i, i)) <= min_w) res[n + i] = 0.0;
      else if (res[i] < 0) res[n + i] = -res[i] / m(i, i);
      else res[n + i] = 0.0;
      error += std::fabs(m(i, i) * (res[n + i] - f1));
    }
    if (error < tol) break;
  }
  r.converged = error < tol;
  r.iterations = it < max_it ? it + 1 : it;
  r.error = error;
  if (max_f != 0.0)
    for (int i = 0; i < n; ++i)
      if (std::fabs(res[n + i]) >= max_f) res[n + i] = 0.0;
  for (int i = 0; i < n; ++i) f[i] = res[n + i];
  return r;
}

}  // namespace sinew
