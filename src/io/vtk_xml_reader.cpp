// VTK XML files (.vtu/.vtp, <VTKFile>): UnstructuredGrid or PolyData, DataArrays in "ascii" or
// base64 "binary" (uncompressed) format, in either byte order.
#include "io/vtk_common.h"

#include <array>
#include <map>
#include <optional>

#include "io/reader_text.h"

namespace sinew::io::internal {

namespace {

// How the binary arrays of a file are stored (attributes of <VTKFile>).
struct BinaryLayout {
  std::size_t header_size = 4;  // the byte count before each array: header_type UInt32 or UInt64
  bool swap = false;            // byte_order is the other one than this machine's (BigEndian)
};

// --- minimal XML for VTK files

struct XmlElem {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;
  std::vector<XmlElem> children;
  const XmlElem* child(const std::string& n) const {
    for (const auto& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
  std::string attr(const std::string& n, const std::string& def = {}) const {
    auto it = attrs.find(n);
    return it == attrs.end() ? def : it->second;
  }
};

struct XmlParser {
  const std::string& s;
  std::size_t i = 0;
  std::string error;
  void skip_ws() {
    while (i < s.size() && is_space(s[i])) ++i;
  }
  void skip_misc() {
    for (;;) {
      skip_ws();
      if (s.compare(i, 4, "<!--") == 0) {
        auto e = s.find("-->", i);
        i = e == std::string::npos ? s.size() : e + 3;
      } else if (s.compare(i, 2, "<?") == 0) {
        auto e = s.find("?>", i);
        i = e == std::string::npos ? s.size() : e + 2;
      } else {
        return;
      }
    }
  }
  bool parse(XmlElem& e) {
    skip_misc();
    if (i >= s.size() || s[i] != '<') return (error = "element expected"), false;
    ++i;
    std::size_t b = i;
    while (i < s.size() && !is_space(s[i]) && s[i] != '>' && s[i] != '/') ++i;
    e.name = s.substr(b, i - b);
    for (;;) {
      skip_ws();
      if (i >= s.size()) return (error = "unterminated tag <" + e.name + ">"), false;
      if (s[i] == '/') {
        if (s.compare(i, 2, "/>") != 0) return (error = "bad tag <" + e.name + ">"), false;
        i += 2;
        return true;
      }
      if (s[i] == '>') {
        ++i;
        break;
      }
      b = i;
      while (i < s.size() && s[i] != '=' && !is_space(s[i])) ++i;
      std::string key = s.substr(b, i - b);
      skip_ws();
      if (i >= s.size() || s[i] != '=') return (error = "bad attribute in <" + e.name + ">"), false;
      ++i;
      skip_ws();
      if (i >= s.size() || (s[i] != '"' && s[i] != '\'')) return (error = "bad attribute in <" + e.name + ">"), false;
      const char q = s[i++];
      b = i;
      while (i < s.size() && s[i] != q) ++i;
      e.attrs[key] = s.substr(b, i - b);
      ++i;
    }
    for (;;) {
      b = i;
      while (i < s.size() && s[i] != '<') ++i;
      e.text += s.substr(b, i - b);
      if (i >= s.size()) return (error = "unterminated element <" + e.name + ">"), false;
      if (s.compare(i, 2, "</") == 0) {
        auto end = s.find('>', i);
        if (end == std::string::npos) return (error = "unterminated closing tag"), false;
        i = end + 1;
        return true;
      }
      if (s.compare(i, 4, "<!--") == 0 || s.compare(i, 2, "<?") == 0) {
        skip_misc();
        continue;
      }
      e.children.emplace_back();
      if (!parse(e.children.back())) return false;
    }
  }
};

// Base64 with whitespace allowed and '=' padding inside: VTK may encode the byte-count header and
// the values as two blocks, one after the other.
bool base64_decode(std::string_view in, std::vector<unsigned char>& out) {
  static const std::array<int, 256> table = [] {
    std::array<int, 256> t;
    t.fill(-1);
    const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int k = 0; k < 64; ++k) t[static_cast<unsigned char>(a[k])] = k;
    return t;
  }();
  unsigned buf = 0;
  int bits = 0;
  for (char ch : in) {
    if (is_space(ch)) continue;
    if (ch == '=') {  // padding: a new block may start after it
      bits = 0;
      buf = 0;
      continue;
    }
    const int v = table[static_cast<unsigned char>(ch)];
    if (v < 0) return false;
    buf = (buf << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buf >> bits) & 0xFF));
    }
  }
  return true;
}

// The values of one <DataArray>, widened to double. ASCII Float32 values are rounded to float as
// SOFA stores them, unless `ascii_as_double` (SOFA reads point coordinates as Float64).
bool read_data_array(const XmlElem& da, const BinaryLayout& layout, std::vector<double>& out, std::string& why,
                     bool ascii_as_double = false) {
  const std::string type = da.attr("type");
  bool is_float = false, is_signed = true;
  const int size = vtk_type_size(type, &is_float, &is_signed);
  if (size == 0) return (why = "unsupported DataArray type '" + type + "'"), false;
  const std::string format = da.attr("format", "ascii");
  const std::string& text = da.text;
  out.clear();
  if (format == "ascii") {
    Cursor c{text};
    for (std::string_view t = c.next(); !t.empty(); t = c.next()) {
      if (is_float && size == 4 && !ascii_as_double) {
        float f;
        if (!to_number(t, f)) return (why = "bad number '" + std::string(t) + "'"), false;
        out.push_back(f);
      } else if (is_float) {
        double d;
        if (!to_number(t, d)) return (why = "bad number '" + std::string(t) + "'"), false;
        out.push_back(d);
      } else {
        long long k;
        if (!to_number(t, k)) return (why = "bad integer '" + std::string(t) + "'"), false;
        out.push_back(static_cast<double>(k));
      }
    }
  } else if (format == "binary") {
    std::vector<unsigned char> bytes;
    if (!base64_decode(text, bytes)) return (why = "bad base64 data"), false;
    const std::size_t hs = layout.header_size;
    if (bytes.size() < hs) return (why = "truncated binary DataArray"), false;
    uint64_t nbytes = 0;
    for (std::size_t k = 0; k < hs; ++k) nbytes |= uint64_t{bytes[layout.swap ? hs - 1 - k : k]} << (8 * k);
    if (nbytes > bytes.size() - hs) return (why = "truncated binary DataArray"), false;
    const std::size_t n = nbytes / static_cast<std::size_t>(size);
    out.resize(n);
    for (std::size_t k = 0; k < n; ++k)
      out[k] = decode_value(bytes.data() + hs + k * size, size, is_float, is_signed, layout.swap);
  } else {
    return (why = "DataArray format '" + format + "' is not supported (ascii or binary)"), false;
  }
  return true;
}

}  // namespace

std::optional<MeshData> read_vtk_xml(const std::string& path, const std::string& text, std::string* error,
                                     const ReadOptions& opt) {
  auto err = [&](const std::string& what) {
    if (error) *error = path + ": " + what;
    return std::nullopt;
  };
  XmlParser p{text, 0, {}};
  XmlElem root_elem;
  if (!p.parse(root_elem)) return err("XML error: " + p.error);
  const XmlElem* root = &root_elem;
  const std::string root_name = root->name;
  if (root_name != "VTKFile") return err("root element is <" + root_name + ">, <VTKFile> expected");
  if (!root->attr("compressor").empty()) return err("compressed VTK XML files are not supported");
  // Binary arrays (and their byte-count headers) are in the file's byte order; ASCII arrays have none.
  const std::string byte_order = root->attr("byte_order", "LittleEndian");
  if (byte_order != "LittleEndian" && byte_order != "BigEndian")
    return err("unknown byte_order '" + byte_order + "' (LittleEndian or BigEndian expected)");
  const BinaryLayout layout{root->attr("header_type", "UInt32") == "UInt64" ? 8u : 4u, byte_order == "BigEndian"};
  const std::string type = root->attr("type");
  const XmlElem* grid = root->child(type);
  if (!grid || (type != "UnstructuredGrid" && type != "PolyData"))
    return err("VTK XML type '" + type + "' is not supported (UnstructuredGrid or PolyData)");
  const XmlElem* piece = grid->child("Piece");
  if (!piece) return err("no <Piece> element");
  MeshData m;
  std::string why;
  const XmlElem* pts = piece->child("Points");
  if (!pts || !pts->child("DataArray")) return err("no <Points> data");
  std::vector<double> points;
  // SOFA stores XML point coordinates as Float64 (ASCII values are not rounded to float).
  if (!read_data_array(*pts->child("DataArray"), layout, points, why, true)) return err("Points: " + why);
  set_points(m, points);
  VtkCells vc;
  // Connectivity, offsets and (unless every cell has `fixed_type`) types, by Name.
  auto read_cells = [&](const XmlElem& cells, int fixed_type) -> bool {
    std::optional<std::vector<double>> conn, offs, types;
    for (const XmlElem& da : cells.children) {
      const std::string name = da.attr("Name");
      auto* t = name == "connectivity" ? &conn : name == "offsets" ? &offs : name == "types" ? &types : nullptr;
      if (t && !read_data_array(da, layout, t->emplace(), why)) return false;
    }
    if (!conn || !offs) return (why = "missing connectivity or offsets"), false;
    if (fixed_type < 0 && !types) return (why = "missing cell types"), false;
    vc.cells = std::move(*conn);
    vc.offsets = std::move(*offs);
    vc.number_of_cells = vc.offsets.size();
    vc.types = fixed_type < 0 ? std::move(*types) : std::vector<double>(vc.offsets.size(), fixed_type);
    vc.has_cells = vc.has_types = true;
    return true;
  };
  if (type == "UnstructuredGrid") {
    const XmlElem* cells = piece->child("Cells");
    if (cells && !read_cells(*cells, -1)) return err("Cells: " + why);
    if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
  } else {
    // PolyData: only Polys are read (as SOFA): 2 vertices → line, 3 → triangle, 4 → quad, more → polyline.
    if (const XmlElem* polys = piece->child("Polys")) {
      if (!read_cells(*polys, 0)) return err("Polys: " + why);
      for (std::size_t c = 0; c < vc.offsets.size(); ++c) {
        const double n = c == 0 ? vc.offsets[0] : vc.offsets[c] - vc.offsets[c - 1];
        vc.types[c] = n == 2 ? 3 : n == 3 ? 5 : n == 4 ? 9 : 4;
      }
      if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
    }
  }
  for (const char* section : {"PointData", "CellData"}) {
    const XmlElem* s = piece->child(section);
    if (!s) continue;
    for (const XmlElem& da : s->children) {
      std::vector<double> values;
      if (!read_data_array(da, layout, values, why)) return err(std::string(section) + ": " + why);
      long long comps = 1;
      to_number(da.attr("NumberOfComponents", "1"), comps);
      const std::string name = da.attr("Name");  // normals too stay point data (SOFA's XML reader)
      (std::string(section) == "PointData" ? m.point_data : m.cell_data)
          .push_back({name, static_cast<int>(comps), std::move(values)});
    }
  }
  return m;
}

}  // namespace sinew::io::internal
