// What the legacy and the XML VTK readers share (internal to src/io): value types and their
// decoding, and SOFA's conversion of points and cells into MeshData (setInputsMesh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "io/mesh_readers.h"

namespace sinew::io::internal {

// Size in bytes of a VTK value type, legacy or XML name ("float" or "Float32"), case-insensitive;
// 0 when unknown.
int vtk_type_size(const std::string& t, bool* is_float, bool* is_signed);

// One binary value of `size` bytes widened to double; `swap` reverses the bytes first (the data
// are in the other byte order than this machine's little-endian one).
inline double decode_value(const unsigned char* p, int size, bool is_float, bool is_signed, bool swap) {
  unsigned char b[8];
  for (int k = 0; k < size; ++k) b[k] = swap ? p[size - 1 - k] : p[k];
  if (is_float) {
    if (size == 4) {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  switch (size) {
    case 1: return is_signed ? static_cast<double>(static_cast<int8_t>(b[0])) : b[0];
    case 2: {
      uint16_t u;
      std::memcpy(&u, b, 2);
      return is_signed ? static_cast<double>(static_cast<int16_t>(u)) : u;
    }
    case 4: {
      uint32_t u;
      std::memcpy(&u, b, 4);
      return is_signed ? static_cast<double>(static_cast<int32_t>(u)) : u;
    }
    default: {
      uint64_t u;
      std::memcpy(&u, b, 8);
      return is_signed ? static_cast<double>(static_cast<int64_t>(u)) : static_cast<double>(u);
    }
  }
}

// The element arrays of a file, values widened to double, before conversion to MeshData.
struct VtkCells {
  std::vector<double> polygons;  // legacy POLYGONS: n, i0..in-1, ...
  std::vector<double> cells;     // legacy CELLS (counts included) or XML connectivity
  std::vector<double> offsets;   // XML only
  std::vector<double> types;
  std::size_t number_of_cells = 0;
  bool has_polygons = false, has_cells = false, has_types = false;
};

// Adds the elements of `vc` to `m` (positions already set) as SOFA's setInputsMesh does; false
// with the reason in *error for an index beyond the points, a truncated or unknown cell.
bool vtk_to_mesh(MeshData& m, const VtkCells& vc, const std::string& path, std::string* error, bool flip);

// Positions from a flat x, y, z array; false with "<path>: point k has a non-finite
// coordinate" in *error when one is NaN or infinite (binary arrays carry raw floats).
bool set_points(MeshData& m, const std::vector<double>& xyz, const std::string& path, std::string* error);

// The two readers behind read_vtk, given the whole file text.
std::optional<MeshData> read_vtk_legacy(const std::string& path, const std::string& text, std::string* error,
                                        const ReadOptions& opt);
std::optional<MeshData> read_vtk_xml(const std::string& path, const std::string& text, std::string* error,
                                     const ReadOptions& opt);

}  // namespace sinew::io::internal
