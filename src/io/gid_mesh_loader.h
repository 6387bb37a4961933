// GIDMeshLoader: volumetric meshes written by GiD (SOFA's IO/Mesh). Header
// "MESH dimension D ElemType T Nnode N" (T: Linear, Triangle,
// Quadrilateral, Tetrahedra, Hexahedra; Prism, Pyramid, Sphere and Circle
// are refused as in SOFA), then "Coordinates" … "End Coordinates" lines
// "id x y [z]", then "Elements" … "End Elements" lines "id n1 n2 …" with
// 1-based node ids; only the first nodes of quadratic elements are kept
// (a warning, as SOFA). Keywords are case-insensitive.
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class GIDMeshLoader final : public MeshLoader {
 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
};

}  // namespace sinew
