// libFuzzer target: the field value parsers (core/parse.h through Field<T>::read)
// of every value type a component declares, the value-count check and the
// shortened quotes of messages, and data links between fields of different types
// (copy_from / row copies).
//
// Oracle besides sanitizers: a value written back as text reads back to the same
// text (SOFA's writer and reader agree), and quoting never returns more than a
// bounded number of characters.
#include <stdlib.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/component.h"
#include "core/parse.h"
#include "core/value_text.h"
#include "fuzz_support.h"

using namespace sinew;

namespace {

class AllTypes final : public Component {
 public:
  Field<double> d{this, "d", 0.0, ""};
  Field<float> f{this, "f", 0.0f, ""};
  Field<int> i{this, "i", 0, ""};
  Field<unsigned> u{this, "u", 0u, ""};
  Field<bool> b{this, "b", false, ""};
  Field<std::string> s{this, "s", "", ""};
  Field<std::vector<double>> vd{this, "vd", {}, ""};
  Field<std::vector<int>> vi{this, "vi", {}, ""};
  Field<std::vector<unsigned>> vu{this, "vu", {}, ""};
  Field<std::vector<std::string>> vs{this, "vs", {}, ""};
  Field<Vec3> v3{this, "v3", Vec3::Zero(), ""};
  Field<VecN<7>> v7{this, "v7", VecN<7>::Zero(), ""};
  Field<VecNi<3>> v3i{this, "v3i", VecNi<3>::Zero(), ""};
  Field<Mat3> m3{this, "m3", Mat3::Identity(), ""};
  Field<std::vector<Vec3>> lv3{this, "lv3", {}, ""};
  Field<std::vector<VecN<2>>> lv2{this, "lv2", {}, ""};
  Field<std::vector<std::array<unsigned, 2>>> edges{this, "edges", {}, ""};
  Field<std::vector<std::array<unsigned, 4>>> tetras{this, "tetras", {}, ""};
  Field<FlatVec> flat{this, "flat", FlatVec{7, {}}, ""};
};

// Lists of strings are left out of the text oracle: an element with spaces
// ("['a b']") is written space-separated, as SOFA writes it, and reads back as two.
template <class T>
void round_trip(Field<T>& f, std::string_view text) {
  if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    f.read(text);
    (void)f.text();
    return;
  }
  f.read(text);
  const std::string once = f.text();
  Field<T> again{nullptr, "again", f.get(), ""};
  again.read(once);
  if (again.text() != once) __builtin_trap();  // written text does not read back
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Index ranges ("8466385e-005" is 8466385 down to 5) expand up to the memory budget;
  // 8 MB keeps one input under the 10 s timeout with ASan while still exercising the check.
  ::setenv("SINEW_MEMORY_LIMIT_MB", "8", 0);
  fuzz::limit_scene_memory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  AllTypes c;
  round_trip(c.d, text);
  round_trip(c.f, text);
  round_trip(c.i, text);
  round_trip(c.u, text);
  round_trip(c.b, text);
  round_trip(c.s, text);
  round_trip(c.vd, text);
  round_trip(c.vi, text);
  round_trip(c.vu, text);
  round_trip(c.vs, text);
  round_trip(c.v3, text);
  round_trip(c.v7, text);
  round_trip(c.v3i, text);
  round_trip(c.m3, text);
  round_trip(c.lv3, text);
  round_trip(c.lv2, text);
  round_trip(c.edges, text);
  round_trip(c.tetras, text);
  round_trip(c.flat, text);

  std::vector<double> mass;
  parse::read_rigid3_mass(text, mass);
  parse::count_list_numbers(text);
  parse::first_partial_number(text, size % 2 == 0);
  for (BaseField* f : c.fields()) (void)value_count_problem(*f, text);
  if (quote_value(text).size() > 200) __builtin_trap();

  // A data link between fields of different types copies through rows or text.
  AllTypes other;
  BaseField* from[] = {&c.lv3, &c.vd, &c.flat, &c.edges, &c.v3, &c.s};
  BaseField* to[] = {&other.lv2, &other.flat, &other.vu, &other.lv3, &other.vd, &other.m3};
  for (std::size_t k = 0; k < std::size(from); ++k) {
    to[k]->set_parent(from[k]);
    to[k]->update();
  }
  return 0;
}
