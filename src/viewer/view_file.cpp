#include "viewer/view_file.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <Eigen/Geometry>
#include <tinyxml2.h>

namespace sinew::viewer {

namespace {

bool exists(const std::string& p) {
  std::ifstream f(p);
  return f.good();
}

bool read_numbers(const char* text, double* out, int n) {
  if (!text) return false;
  std::istringstream in(text);
  for (int i = 0; i < n; ++i)
    if (!(in >> out[i]) || !std::isfinite(out[i])) return false;
  return true;
}

Mat3 rotation_of(const double q[4]) {  // x y z w
  Eigen::Quaterniond e(q[3], q[0], q[1], q[2]);
  if (e.norm() < 1e-12) return Mat3::Identity();
  return e.normalized().toRotationMatrix();
}

}  // namespace

std::string view_file_for(const std::string& scene) {
  if (exists(scene + ".view")) return scene + ".view";
  if (exists(scene + ".qglviewer.view")) return scene + ".qglviewer.view";
  return {};
}

std::optional<render::CameraFrame> read_view_file(const std::string& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    if (error) *error = "cannot open " + path;
    return std::nullopt;
  }
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  render::CameraFrame f;
  double p[3], q[4];
  if (text.find('<') == std::string::npos) {  // two lines: position, quaternion
    std::istringstream lines(text);
    std::string l1, l2;
    std::getline(lines, l1);
    std::getline(lines, l2);
    if (!read_numbers(l1.c_str(), p, 3) || !read_numbers(l2.c_str(), q, 4)) {
      if (error) *error = path + ": expected a position line and a quaternion line";
      return std::nullopt;
    }
    f.position = Vec3(p[0], p[1], p[2]);
    f.rotation = rotation_of(q);
    f.look_at = f.position - f.rotation.col(2) * f.position.norm();
    return f;
  }
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) {
    if (error) *error = path + ": not a camera file (" + (doc.ErrorStr() ? doc.ErrorStr() : "no root element") + ")";
    return std::nullopt;
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  auto value = [&](const char* name) -> const char* {
    const tinyxml2::XMLElement* e = root->FirstChildElement(name);
    return e ? e->Attribute("value") : nullptr;
  };
  if (!read_numbers(value("position"), p, 3) || !read_numbers(value("orientation"), q, 4)) {
    if (error) *error = path + ": <position> and <orientation> need 3 and 4 numbers";
    return std::nullopt;
  }
  f.position = Vec3(p[0], p[1], p[2]);
  f.rotation = rotation_of(q);
  double v = 0;
  if (read_numbers(value("fieldOfView"), &v, 1) && v > 0 && v < 180) f.fov_deg = v;
  double distance = 0;
  if (!read_numbers(value("distance"), &distance, 1) || distance <= 0) distance = f.position.norm();
  f.look_at = f.position - f.rotation.col(2) * distance;
  if (const char* t = value("projectionType")) {
    const std::string s = t;
    f.ortho = s == "1" || s == "Orthographic";
  }
  return f;
}

bool write_view_file(const std::string& path, const render::CameraFrame& f, std::string* error) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  const Eigen::Quaterniond q(f.rotation);
  const double distance = (f.position - f.look_at).norm();
  std::fprintf(out, "<?xml version=\"1.0\" ?>\n<Camera version=\"1.0\">\n");
  std::fprintf(out, "    <position value=\"%.9g %.9g %.9g\" />\n", f.position[0], f.position[1], f.position[2]);
  std::fprintf(out, "    <orientation value=\"%.9g %.9g %.9g %.9g\" />\n", q.x(), q.y(), q.z(), q.w());
  std::fprintf(out, "    <lookAt value=\"%.9g %.9g %.9g\" />\n", f.look_at[0], f.look_at[1], f.look_at[2]);
  std::fprintf(out, "    <fieldOfView value=\"%.9g\" />\n", f.fov_deg);
  std::fprintf(out, "    <distance value=\"%.9g\" />\n", distance);
  std::fprintf(out, "    <projectionType value=\"%s\" />\n</Camera>\n", f.ortho ? "Orthographic" : "Perspective");
  const bool ok = std::fclose(out) == 0;
  if (!ok && error) *error = "cannot write " + path;
  return ok;
}

}  // namespace sinew::viewer
