#include "engine/transform_position.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/registry.h"
#include "io/sofa_quat.h"

namespace sinew {

namespace {
FlatVec flat3() {
  FlatVec v;
  v.width = 3;
  return v;
}
VecN<16> identity4() {
  VecN<16> m = VecN<16>::Zero();
  for (int i = 0; i < 4; ++i) m[i * 5] = 1.0;
  return m;
}
// Whitespace-separated tokens of a line.
std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream is(line);
  for (std::string t; is >> t;) out.push_back(t);
  return out;
}
bool to_number(const std::string& t, double& v) {
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end != t.c_str() && *end == '\0' && std::isfinite(v);
}
}  // namespace

TransformPosition::TransformPosition()
    : input_position(this, "input_position", flat3(), "points to transform", "Inputs"),
      output_position(this, "output_position", flat3(), "transformed points", "Outputs"),
      matrix(this, "matrix", identity4(), "4x4 affine matrix, row by row (affine)", "Inputs") {
  input_position.add_alias("inputPosition");
  output_position.add_alias("outputPosition");
  filename.set_file(true);
  for (BaseField* f : std::initializer_list<BaseField*>{&input_position, &origin, &normal, &translation, &rotation,
                                                        &scale, &matrix, &fixed_indices, &method, &filename,
                                                        &seed_value, &max_random_displacement})
    add_input(f);
  add_output(&output_position);
}

void TransformPosition::init() {
  const Vec3 n = normal.get();
  const double n2 = n.squaredNorm();
  if (std::fabs(n2 - 1.0) > 1e-10) {
    if (n2 > 0) normal.set(n / std::sqrt(n2));
    else if (method.get() == "projectOnPlane")
      msg_warning("'normal' is zero: projectOnPlane leaves the points where they are (SOFA gives NaN)");
  }
  set_dirty();
  update();
}

TransformPosition::Method TransformPosition::select_method() {
  const std::string& m = method.get();
  if (m == "projectOnPlane") return Method::project_on_plane;
  if (m == "translation") return Method::translation;
  if (m == "rotation") return Method::rotation;
  if (m == "random") return Method::random;
  if (m == "scale") return Method::scale;
  if (m == "scaleTranslation") return Method::scale_translation;
  if (m == "scaleRotationTranslation") return Method::scale_rotation_translation;
  if (m == "affine") return Method::affine;
  if (m == "fromFile") {
    const std::string& f = filename.get();
    auto ends = [&](const char* ext) { return f.size() >= 4 && f.compare(f.size() - 4, 4, ext) == 0; };
    if (!filename.is_set() || f.empty()) msg_error("method fromFile without 'filename': the affine matrix is used");
    else if (ends(".trm")) read_trm(f);
    else if (ends(".txt") || ends(".xfm")) read_xfm(f);
    else if (ends(".tfm")) read_tfm(f);
    else msg_error("unknown extension of '" + f + "' (.tfm, .trm, .xfm or .txt): the affine matrix is used");
    return Method::affine;
  }
  msg_error("unknown method '" + m +
            "' (projectOnPlane, translation, rotation, scale, scaleTranslation, scaleRotationTranslation, affine, "
            "fromFile): translation is used");
  return Method::translation;
}

// .tfm (ITK): the first line containing "Parameters" holds 12 numbers, the
// 3x3 matrix row by row then the translation, which SOFA reads backwards
// (row i takes the (12-i)-th number).
void TransformPosition::read_tfm(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    msg_error("cannot open '" + path + "': the matrix is set to identity");
    return;
  }
  VecN<16> m = identity4();
  bool found = false;
  for (std::string line; !found && std::getline(in, line);) {
    if (line.find("Parameters") == std::string::npos) continue;
    found = true;
    std::vector<double> v;
    for (const std::string& t : tokens(line)) {
      if (t.find_first_of("1234567890.-") == std::string::npos) continue;
      double x;
      if (to_number(t, x)) v.push_back(x);
      else msg_error("'" + path + "': cannot read the value '" + t + "'");
    }
    if (v.size() != 12) {
      msg_error("'" + path + "': " + std::to_string(v.size()) + " parameters instead of 12");
    } else {
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i * 4 + j] = v[i * 3 + j];
        m[i * 4 + 3] = v[v.size() - 1 - i];
      }
    }
  }
  if (!found) msg_error("'" + path + "': no line with \"Parameters\"");
  matrix.set(m);
}

// .trm: a line of 3 numbers (translation) then 3 lines of 3 (rotation rows).
void TransformPosition::read_trm(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    msg_error("cannot open '" + path + "': the matrix is set to identity");
    return;
  }
  VecN<16> m = identity4();
  int lines = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    if (++lines > 4) {
      msg_error("'" + path + "' has more than 4 lines");
      break;
    }
    const std::vector<std::string> t = tokens(line);
    if (t.size() < 3) {
      msg_error("'" + path + "' line " + std::to_string(lines) + ": 3 values expected");
      continue;
    }
    if (t.size() > 3) msg_error("'" + path + "' line " + std::to_string(lines) + ": 3 values expected");
    Vec3 tr = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
      double x;
      if (!to_number(t[i], x)) {
        msg_error("'" + path + "': invalid number '" + t[i] + "'");
        x = 0.0;
      }
      if (lines == 1) tr[i] = m[i * 4 + 3] = x;
      else m[(lines - 2) * 4 + i] = x;
    }
    if (lines == 1) translation.set(tr);
  }
  matrix.set(m);
}

// .xfm / .txt: 4 lines of 4 numbers.
void TransformPosition::read_xfm(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    msg_error("cannot open '" + path + "': the matrix is set to identity");
    return;
  }
  VecN<16> m = identity4();
  int lines = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    if (++lines > 4) {
      msg_error("'" + path + "': the matrix is not 4x4");
      break;
    }
    const std::vector<std::string> t = tokens(line);
    if (t.size() != 4) msg_error("'" + path + "': the matrix is not 4x4");
    if (t.size() < 4) continue;
    for (int i = 0; i < 4; ++i) {
      double x;
      if (!to_number(t[i], x)) {
        msg_error("'" + path + "': invalid number '" + t[i] + "'");
        x = 0.0;
      }
      m[(lines - 1) * 4 + i] = x;
    }
  }
  matrix.set(m);
}

void TransformPosition::do_update() {
  const Method how = select_method();
  const FlatVec& in = input_position.get();
  FlatVec& out = output_position.edit();
  const std::size_t n = in.size();
  out.width = 3;
  out.data.resize(n * 3);  // SOFA resizes: points the affine method cannot map keep their old value
  auto p_in = [&](std::size_t i) { return Vec3(in.data[3 * i], in.data[3 * i + 1], in.data[3 * i + 2]); };
  auto put = [&](std::size_t i, const Vec3& p) {
    for (int k = 0; k < 3; ++k) out.data[3 * i + k] = p[k];
  };
  const Vec3 o = origin.get(), nrm = normal.get(), t = translation.get(), s = scale.get();
  auto rot = [&] {
    const Vec3 r = rotation.get() * M_PI / 180.0;  // SOFA: (angles·π)/180
    return io::SQuat::from_euler(r);
  };
  switch (how) {
    case Method::project_on_plane:
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = p_in(i);
        put(i, p + nrm * (o - p).dot(nrm));
      }
      break;
    case Method::random:
      msg_error("the random method (SOFA's random generator) is not available: points copied unchanged");
      out.data = in.data;
      break;
    case Method::translation:
      for (std::size_t i = 0; i < n; ++i) put(i, p_in(i) + t);
      break;
    case Method::scale:
      for (std::size_t i = 0; i < n; ++i) put(i, o + (p_in(i) - o).cwiseProduct(s));
      break;
    case Method::scale_translation:
      for (std::size_t i = 0; i < n; ++i) put(i, p_in(i).cwiseProduct(s) + t);
      break;
    case Method::rotation: {
      const io::SQuat q = rot();
      for (std::size_t i = 0; i < n; ++i) put(i, q.rotate(p_in(i)));
      break;
    }
    case Method::scale_rotation_translation: {
      const io::SQuat q = rot();
      for (std::size_t i = 0; i < n; ++i) put(i, q.rotate(p_in(i).cwiseProduct(s)) + t);
      break;
    }
    case Method::affine: {
      const VecN<16>& m = matrix.get();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = p_in(i);
        double h[4];
        for (int r = 0; r < 4; ++r) h[r] = m[r * 4] * p[0] + m[r * 4 + 1] * p[1] + m[r * 4 + 2] * p[2] + m[r * 4 + 3];
        if (std::fabs(h[3]) > 1e-10) put(i, Vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
      }
      break;
    }
  }
  for (unsigned id : fixed_indices.get()) {
    if (id >= n) {
      msg_error("fixedIndices: " + std::to_string(id) + " is beyond the " + std::to_string(n) + " input points");
      continue;
    }
    for (int k = 0; k < 3; ++k) out.data[3 * id + k] = in.data[3 * id + k];
  }
}

void register_transform_position(Registry& r) {
  ComponentInfo info;
  info.name = "TransformPosition";
  info.category = "Engine/Transform";
  info.description =
      "transforms 3-D points: plane projection, translation, rotation, scale, their combinations, or an affine "
      "matrix (given or read from a file)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<TransformPosition>(); };
  r.add(std::move(info));
}

}  // namespace sinew
