#include "haptics/scripted_device.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace sinew::haptics {

bool parse_trajectory(const std::string& text, std::vector<TrajectorySample>& out, std::string& error) {
  out.clear();
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool first_data = true;
  while (std::getline(in, line)) {
    ++line_no;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream cols(line);
    std::vector<double> v;
    std::string tok;
    bool numeric = true;
    while (cols >> tok) {
      char* end = nullptr;
      const double d = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != 0) {
        numeric = false;
        break;
      }
      v.push_back(d);
    }
    if (v.empty() && numeric) continue;  // blank line
    if (!numeric) {
      if (first_data) {  // a header
        first_data = false;
        continue;
      }
      error = "line " + std::to_string(line_no) + ": '" + tok + "' is not a number";
      return false;
    }
    first_data = false;
    if (v.size() != 9) {
      error = "line " + std::to_string(line_no) + ": " + std::to_string(v.size()) +
              " columns; expected 9 (time, x y z, qx qy qz qw, buttons)";
      return false;
    }
    TrajectorySample s;
    s.t = v[0];
    s.p = Vec3(v[1], v[2], v[3]);
    const double n = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
    if (!(n > 0) || !std::isfinite(n) || !std::isfinite(v[0]) || !s.p.allFinite()) {
      error = "line " + std::to_string(line_no) + ": non-finite value or zero quaternion";
      return false;
    }
    s.q = {v[4] / n, v[5] / n, v[6] / n, v[7] / n};
    if (v[8] < 0 || v[8] != std::floor(v[8])) {
      error = "line " + std::to_string(line_no) + ": buttons must be a non-negative integer bitmask";
      return false;
    }
    s.buttons = static_cast<unsigned>(v[8]);
    if (!out.empty() && !(s.t > out.back().t)) {
      error = "line " + std::to_string(line_no) + ": time " + std::to_string(s.t) +
              " does not increase (previous " + std::to_string(out.back().t) + ")";
      return false;
    }
    out.push_back(s);
  }
  if (out.empty()) {
    error = "no sample";
    return false;
  }
  return true;
}

namespace {
// Spherical linear interpolation along the shortest arc.
Quat slerp(const Quat& a, Quat b, double u) {
  double c = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  if (c < 0) {
    b = {-b.x, -b.y, -b.z, -b.w};
    c = -c;
  }
  double wa = 1 - u, wb = u;
  if (c < 1 - 1e-12) {
    const double th = std::acos(c), s = std::sin(th);
    wa = std::sin((1 - u) * th) / s;
    wb = std::sin(u * th) / s;
  }
  Quat r{wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w};
  const double n = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z + r.w * r.w);
  return {r.x / n, r.y / n, r.z / n, r.w / n};
}
}  // namespace

DeviceState sample_trajectory(const std::vector<TrajectorySample>& s, double t) {
  DeviceState d;
  d.timestamp = t;
  if (t <= s.front().t || s.size() == 1) {
    d.position = s.front().p;
    d.orientation = s.front().q;
    d.buttons = s.front().buttons;
    return d;
  }
  if (t >= s.back().t) {
    d.position = s.back().p;
    d.orientation = s.back().q;
    d.buttons = s.back().buttons;
    return d;
  }
  // Last sample at or before t (binary search: no allocation).
  std::size_t lo = 0, hi = s.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (s[mid].t <= t ? lo : hi) = mid;
  }
  const TrajectorySample& a = s[lo];
  const TrajectorySample& b = s[hi];
  const double h = b.t - a.t, u = (t - a.t) / h;
  d.position = a.p + u * (b.p - a.p);
  d.orientation = slerp(a.q, b.q, u);
  d.buttons = a.buttons;
  d.linear_velocity = (b.p - a.p) / h;
  d.angular_velocity = quat_to_rotation_vector(quat_mul(b.q, quat_inverse(a.q))) / h;
  return d;
}

bool ScriptedDevice::open(std::string& why) {
  if (!samples_.empty()) return true;
  std::ifstream f(path_);
  if (!f) {
    why = "cannot read the trajectory file '" + path_ + "'";
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  std::string err;
  if (!parse_trajectory(ss.str(), samples_, err)) {
    why = "trajectory file '" + path_ + "': " + err;
    return false;
  }
  return true;
}

}  // namespace sinew::haptics
