#include "dynamic_data.h"

#include <functional>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/roles.h"
#include "data.h"

namespace sinew::python {

namespace {

std::unordered_map<const Base*, std::vector<std::unique_ptr<BaseField>>>& store() {
  static std::unordered_map<const Base*, std::vector<std::unique_ptr<BaseField>>> map;
  return map;
}

using Maker = std::function<std::unique_ptr<BaseField>(Base*, const std::string&, const std::string&, const std::string&)>;

template <class T>
Maker maker() {
  return [](Base* o, const std::string& n, const std::string& h, const std::string& g) {
    if constexpr (requires { T::Zero(); }) return std::make_unique<Field<T>>(o, n, T::Zero(), h, g);
    else return std::make_unique<Field<T>>(o, n, T{}, h, g);
  };
}

const std::map<std::string, Maker, std::less<>>& makers() {
  static const std::map<std::string, Maker, std::less<>> m = {
      {"double", maker<double>()},
      {"float", maker<double>()},  // SofaPython3's "float" Data holds a double-precision value
      {"f", maker<double>()},
      {"d", maker<double>()},
      {"int", maker<int>()},
      {"i", maker<int>()},
      {"unsigned int", maker<unsigned>()},
      {"bool", maker<bool>()},
      {"b", maker<bool>()},
      {"string", maker<std::string>()},
      {"str", maker<std::string>()},
      {"s", maker<std::string>()},
      {"Vec2d", maker<Vec2>()},
      {"Vec3d", maker<Vec3>()},
      {"Vec3", maker<Vec3>()},
      {"Vec4d", maker<VecN<4>>()},
      {"Vec6d", maker<VecN<6>>()},
      {"Vec3i", maker<VecNi<3>>()},
      {"vector<double>", maker<std::vector<double>>()},
      {"vector<float>", maker<std::vector<double>>()},
      {"vector<int>", maker<std::vector<int>>()},
      {"vector<unsigned int>", maker<std::vector<unsigned>>()},
      {"vector<string>", maker<std::vector<std::string>>()},
      {"vector<Vec2d>", maker<std::vector<Vec2>>()},
      {"vector<Vec3d>", maker<std::vector<Vec3>>()},
      {"Vec3d::VecCoord", maker<std::vector<Vec3>>()},
      {"Vec3d::VecDeriv", maker<std::vector<Vec3>>()},
      {"vector<Edge>", maker<std::vector<Edge>>()},
      {"vector<Triangle>", maker<std::vector<Triangle>>()},
      {"vector<Tetra>", maker<std::vector<Tetra>>()},
  };
  return m;
}

std::string infer_type(py::handle v) {
  if (v.is_none()) return "string";
  if (py::isinstance<py::bool_>(v)) return "bool";
  if (py::isinstance<py::int_>(v)) return "int";
  if (py::isinstance<py::float_>(v)) return "double";
  if (py::isinstance<py::str>(v)) return "string";
  if ((py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) && py::len(v) > 0 &&
      py::isinstance<py::str>(py::reinterpret_borrow<py::sequence>(v)[0]))
    return "vector<string>";
  py::array a = py::array::ensure(v);
  if (a && a.ndim() == 1)
    return a.dtype().kind() == 'i' || a.dtype().kind() == 'u' ? "vector<int>" : "vector<double>";
  if (a && a.ndim() == 2 && a.shape(1) == 3) return "vector<Vec3d>";
  if (a && a.ndim() == 2 && a.shape(1) == 2) return "vector<Vec2d>";
  return "string";
}

}  // namespace

BaseField& add_dynamic_field(Base& owner, const std::string& name, std::string type, py::handle value,
                             py::handle default_value, const std::string& help, const std::string& group) {
  if (owner.find_field(name) || owner.find_link(name))
    throw py::value_error("there is already a Data or link named '" + name + "'");
  py::handle init = !value.is_none() ? value : default_value;
  if (type.empty()) type = infer_type(init);
  auto it = makers().find(type);
  if (it == makers().end()) {
    std::string known;
    for (const auto& [k, _] : makers()) known += (known.empty() ? "" : ", ") + k;
    throw py::type_error("addData: unknown type '" + type + "' (known: " + known + ")");
  }
  auto f = it->second(&owner, name, help, group);
  BaseField& ref = *f;
  store()[&owner].push_back(std::move(f));
  if (!init.is_none()) set_field_value(ref, init);
  return ref;
}

void forget_dynamic_fields(const Base* owner) { store().erase(owner); }

}  // namespace sinew::python
