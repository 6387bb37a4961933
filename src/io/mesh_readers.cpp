// The dispatch of the mesh readers: by extension (read_mesh), and between the two VTK formats
// by the first line (read_vtk). Each format has its own file: <format>_reader.cpp.
#include "io/mesh_readers.h"

#include <cctype>

#include "io/reader_text.h"
#include "io/vtk_common.h"

namespace sinew::io {

namespace {

std::string lower_ext(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return {};
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

std::optional<MeshData> read_mesh(const std::string& path, std::string* error, const ReadOptions& opt) {
  const std::string e = lower_ext(path);
  if (e == "obj") return read_obj(path, error, opt);
  if (e == "msh") return read_gmsh(path, error, opt);
  if (e == "vtk" || e == "vtu" || e == "vtp") return read_vtk(path, error, opt);
  if (e == "stl") return read_stl(path, error, opt);
  if (e == "sph") return read_sph(path, error);
  if (e == "off") return read_off(path, error, opt);
  if (error) *error = path + ": unknown mesh file extension '." + e + "'";
  return std::nullopt;
}

// As SOFA's MeshVTKLoader: the content decides, not the extension (Bunny.vtk is an XML file).
std::optional<MeshData> read_vtk(const std::string& path, std::string* error, const ReadOptions& opt) {
  std::string text;
  if (!internal::read_file(path, text, error)) return std::nullopt;
  const auto first_line = text.substr(0, text.find('\n'));
  if (first_line.find("<VTKFile") != std::string::npos ||
      (first_line.rfind("<?xml", 0) == 0 && text.find("<VTKFile") != std::string::npos))
    return internal::read_vtk_xml(path, text, error, opt);
  if (first_line.rfind("# vtk DataFile", 0) == 0) return internal::read_vtk_legacy(path, text, error, opt);
  if (error) *error = path + ":1: not a VTK file (neither '# vtk DataFile' nor <VTKFile>)";
  return std::nullopt;
}

}  // namespace sinew::io
