// Checks that open the init() of many force fields and masses: a Vec3d state,
// a topology (linked, else the node's), element indices inside the state.
// They were written out again in each component with the same messages; one
// copy keeps the wording identical across components.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/roles.h"

namespace sinew {

// False, with an error and the component marked invalid, unless the state
// holds Vec3d points (the kernels of these components only handle 3D points).
bool require_vec3_state(ForceField& c);

// Binds `topology` to the node's mesh topology when the scene links none
// (SOFA's default look-up). False, with "no topology found (<requirement>)"
// and the component marked invalid, when there is none.
bool bind_node_topology(ForceField& c, Link<MeshTopologyBase>& topology, std::string_view requirement);

// True when every point of every element (a list of index arrays) is below
// `n_points`; otherwise reports the first offending element as
// "<element_name> i refers to point v but the state has n_points points" and
// returns false (the caller decides what becomes of the component).
template <class Elements>
bool element_points_in_state(const ForceField& c, const Elements& elements, std::string_view element_name,
                             std::size_t n_points) {
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (unsigned v : elements[i])
      if (v >= n_points) {
        c.msg_error(std::string(element_name) + " " + std::to_string(i) + " refers to point " + std::to_string(v) +
                    " but the state has " + std::to_string(n_points) + " points");
        return false;
      }
  return true;
}

// The same check for loops that fill element data as they go: false, with
// "triangle i refers to a point >= n_points (the number of points of the
// state)", when a corner of triangle `i` lies outside the state.
bool triangle_in_state(const ForceField& c, std::size_t i, const Triangle& t, std::size_t n_points);

}  // namespace sinew
