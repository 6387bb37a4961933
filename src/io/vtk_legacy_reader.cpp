// Legacy VTK files (.vtk, "# vtk DataFile"): ASCII or BINARY, POLYDATA or UNSTRUCTURED_GRID,
// read as SOFA's LegacyVTKReader does (binary read natively, then swapped when it looks swapped).
#include "io/vtk_common.h"

#include <algorithm>

#include "io/reader_text.h"

namespace sinew::io::internal {

namespace {

// One legacy VTK array: values widened to double, plus whether it was float32.
struct VtkArray {
  std::vector<double> v;
  bool is_float = false;
  bool ok = false;
  std::size_t bad_line = 0;  // text arrays: line of the token that could not be read (0: ran out of data)
  // Legacy binary arrays: the raw bytes, to decode again if the data turn out byte-swapped.
  std::string raw;
  int size = 0;
  bool is_signed = true;
  void redecode_swapped() {
    if (raw.empty()) return;
    const auto* p = reinterpret_cast<const unsigned char*>(raw.data());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = decode_value(p + i * size, size, is_float, is_signed, true);
  }
};

// Legacy-file reader state: a position in the whole file buffer.
struct LegacyIn {
  const std::string& s;
  std::size_t pos = 0;
  std::size_t line = 1;
  bool eof() const { return pos >= s.size(); }
  std::string_view getline() {
    if (pos >= s.size()) {
      pos = s.size() + 1;  // mark eof after an empty read
      return {};
    }
    std::size_t e = s.find('\n', pos);
    if (e == std::string::npos) e = s.size();
    std::string_view r(s.data() + pos, e - pos);
    pos = e + 1;
    ++line;
    return r;
  }
  std::string_view next_nonempty() {
    std::string_view l;
    do l = getline();
    while (pos <= s.size() && l.empty());
    return l;
  }
};

// Reads n values (ASCII: line by line, the rest of the last line dropped; binary: raw big-endian bytes).
VtkArray legacy_read(LegacyIn& in, std::size_t n, const std::string& type, int binary) {
  VtkArray a;
  bool is_signed = true;
  const int size = vtk_type_size(type, &a.is_float, &is_signed);
  if (size == 0) return a;
  // Each value takes at least one byte (binary) or two characters (text): larger counts cannot be satisfied.
  if (n > in.s.size()) return a;
  a.v.resize(n);
  if (binary) {
    const std::size_t bytes = n * static_cast<std::size_t>(size);
    if (in.pos + bytes > in.s.size()) return a;
    const auto* p = reinterpret_cast<const unsigned char*>(in.s.data() + in.pos);
    // Read natively (little-endian) like SOFA; read_vtk_legacy detects byte-swapped (big-endian) files afterwards.
    for (std::size_t i = 0; i < n; ++i) a.v[i] = decode_value(p + i * size, size, a.is_float, is_signed, false);
    a.raw.assign(in.s.data() + in.pos, bytes);
    a.size = size;
    a.is_signed = is_signed;
    for (std::size_t k = 0; k < bytes; ++k)
      if (in.s[in.pos + k] == '\n') ++in.line;
    in.pos += bytes;
  } else {
    std::size_t i = 0;
    while (i < n && !in.eof()) {
      Cursor c{in.getline()};
      for (std::string_view t = c.next(); i < n && !t.empty(); t = c.next()) {
        bool ok = false;
        if (a.is_float && size == 4) {
          float f;
          if ((ok = to_number(t, f))) a.v[i++] = f;
        } else if (a.is_float) {
          double d;
          if ((ok = to_number(t, d))) a.v[i++] = d;
        } else {
          long long k;
          if ((ok = to_number(t, k))) a.v[i++] = static_cast<double>(k);
        }
        if (!ok) {
          a.bad_line = in.line - 1;  // the line just read
          return a;
        }
      }
    }
    if (i < n) return a;
  }
  a.ok = true;
  return a;
}

}  // namespace

std::optional<MeshData> read_vtk_legacy(const std::string& path, const std::string& text, std::string* error,
                                        const ReadOptions& opt) {
  LegacyIn in{text, 0, 1};
  auto err = [&](const std::string& what) {
    if (error) *error = where(path, in.line) + what;
    return std::nullopt;
  };
  // A text array that could not be read: the line of the bad value, else "end of data".
  auto arr_err = [&](const VtkArray& a, const std::string& what) {
    if (error)
      *error = a.bad_line ? where(path, a.bad_line) + "bad value while reading " + what
                          : where(path, std::min(in.line, static_cast<std::size_t>(std::count(in.s.begin(), in.s.end(), '\n') + 1))) +
                                "unexpected end of data while reading " + what;
    return std::nullopt;
  };
  std::string_view line = in.getline();
  if (line.substr(0, 23) != "# vtk DataFile Version ") return err("unrecognized VTK header");
  in.getline();  // title
  line = trim(in.getline());
  int binary = 0;
  if (line == "BINARY") binary = 1;
  else if (line == "ASCII") binary = 0;
  else return err("unrecognized format '" + std::string(line) + "' (ASCII or BINARY expected)");
  do line = in.getline();
  while (line.empty() && !in.eof());
  line = trim(line);
  if (line != "DATASET POLYDATA" && line != "DATASET UNSTRUCTURED_GRID")
    return err("unsupported dataset '" + std::string(line) + "' (POLYDATA or UNSTRUCTURED_GRID expected)");

  MeshData m;
  VtkCells vc;
  VtkArray points, normals, polygons, cells, types;
  bool has_points = false;
  while (!in.eof()) {
    line = in.next_nonempty();
    Cursor c{line};
    const std::string kw(c.next());
    if (kw.empty()) break;
    if (kw == "POINTS") {
      long long n = 0;
      if (!to_number(c.next(), n) || n < 0) return err("bad POINTS line");
      const std::string type(c.next());
      bool f = false, s = true;
      const int size = vtk_type_size(type, &f, &s);
      if (size == 0 || !f) return err("type of coordinates '" + type + "' not supported (float or double)");
      points = legacy_read(in, static_cast<std::size_t>(3 * n), type, binary);
      if (!points.ok) return arr_err(points, std::to_string(n) + " points");
      has_points = true;
    } else if (kw == "POLYGONS") {
      long long n = 0, ni = 0;
      if (!to_number(c.next(), n) || !to_number(c.next(), ni) || ni < 0) return err("bad POLYGONS line");
      polygons = legacy_read(in, static_cast<std::size_t>(ni), "int", binary);
      if (!polygons.ok) return arr_err(polygons, "polygons");
      vc.has_polygons = true;
    } else if (kw == "CELLS" || kw == "LINES") {
      long long n = 0, ni = 0;
      if (!to_number(c.next(), n) || !to_number(c.next(), ni) || ni < 0 || n < 0) return err("bad " + kw + " line");
      cells = legacy_read(in, static_cast<std::size_t>(ni), "int", binary);
      if (!cells.ok) return arr_err(cells, "cells");
      vc.has_cells = true;
      vc.number_of_cells = static_cast<std::size_t>(n);
      if (kw == "LINES") {
        types = VtkArray{};
        types.v.assign(static_cast<std::size_t>(n), 4.0);
        types.ok = true;
        vc.has_types = true;
      }
    } else if (kw == "CELL_TYPES") {
      long long n = 0;
      if (!to_number(c.next(), n) || n < 0) return err("bad CELL_TYPES line");
      types = legacy_read(in, static_cast<std::size_t>(n), "int", binary);
      if (!types.ok) return arr_err(types, "cell types");
      vc.has_types = true;
    } else if (kw == "CELL_DATA" || kw == "POINT_DATA") {
      const bool cell = kw == "CELL_DATA";
      long long nb = 0;
      to_number(c.next(), nb);
      auto& out = cell ? m.cell_data : m.point_data;
      while (!in.eof()) {
        const std::size_t save_pos = in.pos, save_line = in.line;
        std::string_view l = in.next_nonempty();
        if (l.empty()) break;
        Cursor d{l};
        const std::string ds(d.next());
        if (ds == "SCALARS") {
          const std::string name(d.next()), type(d.next());
          long long comps = 1;
          if (!to_number(d.next(), comps) || comps < 1) comps = 1;
          const std::size_t p2 = in.pos, l2 = in.line;
          Cursor lk{in.getline()};
          if (lk.next() != "LOOKUP_TABLE") in.pos = p2, in.line = l2;
          auto a = legacy_read(in, static_cast<std::size_t>(nb), type, binary);
          if (a.ok) out.push_back({name, 1, std::move(a.v)});
        } else if (ds == "NORMALS" || ds == "VECTORS") {
          const std::string name(d.next()), type(d.next());
          auto a = legacy_read(in, static_cast<std::size_t>(3 * nb), type, binary);
          if (!a.ok) return arr_err(a, ds + " '" + name + "'");
          if (ds == "NORMALS") normals = std::move(a);
          else out.push_back({name, 3, std::move(a.v)});
        } else if (ds == "FIELD") {
          std::string fname(d.next());
          long long arrays = 0;
          to_number(d.next(), arrays);
          for (long long k = 0; k < arrays; ++k) {
            Cursor fl{in.next_nonempty()};
            const std::string name(fl.next());
            long long comps = 1, count = 0;
            to_number(fl.next(), comps);
            to_number(fl.next(), count);
            const std::string type(fl.next());
            auto a = legacy_read(in, static_cast<std::size_t>(comps * count), type, binary);
            if (!a.ok) return arr_err(a, "field array '" + name + "'");
            out.push_back({name, static_cast<int>(comps), std::move(a.v)});
          }
        } else if (ds == "LOOKUP_TABLE") {
          std::string tname(d.next());
          long long n = 0;
          to_number(d.next(), n);
          legacy_read(in, static_cast<std::size_t>(4 * n), binary ? "UInt8" : "Float32", binary);
        } else {
          in.pos = save_pos;
          in.line = save_line;
          break;
        }
      }
    }
    // other keywords (METADATA, ...) are skipped
  }
  if (!has_points) return err("no POINTS section");
  if (binary) {
    // SOFA's check: the data are byte-swapped when the first polygon size / cell type read natively is larger
    // than its byte-swapped value (always the case for standard big-endian files).
    const VtkArray* probe = vc.has_polygons ? &polygons : (vc.has_cells && vc.has_types) ? &types : nullptr;
    if (probe && !probe->raw.empty() && probe->raw.size() >= 4) {
      const auto* p = reinterpret_cast<const unsigned char*>(probe->raw.data());
      const auto native = static_cast<uint32_t>(static_cast<int32_t>(decode_value(p, 4, false, true, false)));
      const auto swapped = static_cast<uint32_t>(static_cast<int32_t>(decode_value(p, 4, false, true, true)));
      if (native > swapped)
        for (VtkArray* a : {&points, &normals, &polygons, &cells, &types}) a->redecode_swapped();
    }
  }
  vc.polygons = std::move(polygons.v);
  vc.cells = std::move(cells.v);
  vc.types = std::move(types.v);
  if (!set_points(m, points.v, path, error)) return std::nullopt;
  if (normals.ok) {
    m.normals.resize(normals.v.size() / 3);
    for (std::size_t i = 0; i < m.normals.size(); ++i)
      m.normals[i] = Vec3(normals.v[3 * i], normals.v[3 * i + 1], normals.v[3 * i + 2]);
    std::size_t bad = 0;
    if (!all_finite(m.normals, &bad)) return err("normal " + std::to_string(bad) + " is not finite");
  }
  if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
  return m;
}

}  // namespace sinew::io::internal
