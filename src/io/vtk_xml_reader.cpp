// VTK XML files (.vtu/.vtp, <VTKFile>): UnstructuredGrid or PolyData, DataArrays in "ascii" or
// base64 "binary" (uncompressed) format, in either byte order.
#include "io/vtk_common.h"

#include <array>
#include <optional>
#include <tinyxml2.h>

#include "io/reader_text.h"

namespace sinew::io::internal {

namespace {

namespace tx = tinyxml2;

// How the binary arrays of a file are stored (attributes of <VTKFile>).
struct BinaryLayout {
  std::size_t header_size = 4;  // the byte count before each array: header_type UInt32 or UInt64
  bool swap = false;            // byte_order is the other one than this machine's (BigEndian)
  bool compressed = false;      // a compressor is named: binary arrays are block-compressed
};

// tinyxml2's ErrorStr() is "Error=<NAME> ErrorID=<n> (0x..) Line number=<n>[: <detail>]"; the line
// goes in front of the message, so keep the name and the detail only.
std::string xml_error_text(const tx::XMLDocument& doc) {
  std::string text = std::string("XML error: ") + doc.ErrorName();
  const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
  const std::size_t line_pos = full.find("Line number=");
  const std::size_t detail = full.find(": ", line_pos == std::string::npos ? 0 : line_pos);
  if (detail != std::string::npos) text += " (" + full.substr(detail + 2) + ")";
  return text;
}

std::string attr(const tx::XMLElement& e, const char* name, const char* def = "") {
  const char* v = e.Attribute(name);
  return v ? v : def;
}

// The text of an element without that of its children (comments between numbers are skipped).
std::string text_of(const tx::XMLElement& e) {
  std::string s;
  for (const tx::XMLNode* n = e.FirstChild(); n; n = n->NextSibling())
    if (const tx::XMLText* t = n->ToText()) s += t->Value();
  return s;
}

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
bool read_data_array(const tx::XMLElement& da, const BinaryLayout& layout, std::vector<double>& out, std::string& why,
                     bool ascii_as_double = false) {
  const std::string type = attr(da, "type");
  bool is_float = false, is_signed = true;
  const int size = vtk_type_size(type, &is_float, &is_signed);
  if (size == 0) return (why = "unsupported DataArray type '" + type + "'"), false;
  const std::string format = attr(da, "format", "ascii");
  const std::string text = text_of(da);
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
    if (layout.compressed)
      return (why = "compressed binary DataArrays are not supported (ascii, or uncompressed binary)"), false;
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
  tx::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tx::XML_SUCCESS) {
    // Raw appended data is binary after '_': not XML text, so the parser stops in it.
    if (text.find("<AppendedData") != std::string::npos)
      return err("appended data (<AppendedData>) is not supported (ascii or binary DataArrays only)");
    if (error) *error = where(path, doc.ErrorLineNum()) + xml_error_text(doc);
    return std::nullopt;
  }
  const tx::XMLElement* root = doc.RootElement();
  if (!root) return err("XML error: no root element");
  const std::string root_name = root->Name();
  if (root_name != "VTKFile") return err("root element is <" + root_name + ">, <VTKFile> expected");
  // A compressor applies to binary arrays only: files that name one but store ASCII arrays
  // (SOFA's share/mesh/skull.vtp) read as any other.
  // Binary arrays (and their byte-count headers) are in the file's byte order; ASCII arrays have none.
  const std::string byte_order = attr(*root, "byte_order", "LittleEndian");
  if (byte_order != "LittleEndian" && byte_order != "BigEndian")
    return err("unknown byte_order '" + byte_order + "' (LittleEndian or BigEndian expected)");
  const BinaryLayout layout{attr(*root, "header_type", "UInt32") == "UInt64" ? 8u : 4u, byte_order == "BigEndian",
                            !attr(*root, "compressor").empty()};
  const std::string type = attr(*root, "type");
  const tx::XMLElement* grid = root->FirstChildElement(type.c_str());
  if (!grid || (type != "UnstructuredGrid" && type != "PolyData"))
    return err("VTK XML type '" + type + "' is not supported (UnstructuredGrid or PolyData)");
  const tx::XMLElement* piece = grid->FirstChildElement("Piece");
  if (!piece) return err("no <Piece> element");
  MeshData m;
  std::string why;
  const tx::XMLElement* pts = piece->FirstChildElement("Points");
  if (!pts || !pts->FirstChildElement("DataArray")) return err("no <Points> data");
  std::vector<double> points;
  // SOFA stores XML point coordinates as Float64 (ASCII values are not rounded to float).
  if (!read_data_array(*pts->FirstChildElement("DataArray"), layout, points, why, true)) return err("Points: " + why);
  if (!set_points(m, points, path, error)) return std::nullopt;
  VtkCells vc;
  // Connectivity, offsets and (unless every cell has `fixed_type`) types, by Name.
  auto read_cells = [&](const tx::XMLElement& cells, int fixed_type) -> bool {
    std::optional<std::vector<double>> conn, offs, types;
    for (const tx::XMLElement* da = cells.FirstChildElement(); da; da = da->NextSiblingElement()) {
      const std::string name = attr(*da, "Name");
      auto* t = name == "connectivity" ? &conn : name == "offsets" ? &offs : name == "types" ? &types : nullptr;
      if (t && !read_data_array(*da, layout, t->emplace(), why)) return false;
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
    const tx::XMLElement* cells = piece->FirstChildElement("Cells");
    if (cells && !read_cells(*cells, -1)) return err("Cells: " + why);
    if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
  } else {
    // PolyData: only Polys are read (as SOFA): 2 vertices → line, 3 → triangle, 4 → quad, more → polyline.
    if (const tx::XMLElement* polys = piece->FirstChildElement("Polys")) {
      if (!read_cells(*polys, 0)) return err("Polys: " + why);
      for (std::size_t c = 0; c < vc.offsets.size(); ++c) {
        const double n = c == 0 ? vc.offsets[0] : vc.offsets[c] - vc.offsets[c - 1];
        vc.types[c] = n == 2 ? 3 : n == 3 ? 5 : n == 4 ? 9 : 4;
      }
      if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
    }
  }
  for (const char* section : {"PointData", "CellData"}) {
    const tx::XMLElement* s = piece->FirstChildElement(section);
    if (!s) continue;
    for (const tx::XMLElement* da = s->FirstChildElement(); da; da = da->NextSiblingElement()) {
      std::vector<double> values;
      if (!read_data_array(*da, layout, values, why)) return err(std::string(section) + ": " + why);
      long long comps = 1;
      to_number(attr(*da, "NumberOfComponents", "1"), comps);
      const std::string name = attr(*da, "Name");  // normals too stay point data (SOFA's XML reader)
      (std::string(section) == "PointData" ? m.point_data : m.cell_data)
          .push_back({name, static_cast<int>(comps), std::move(values)});
    }
  }
  return m;
}

}  // namespace sinew::io::internal
