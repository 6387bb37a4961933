// A list of Rigid3d masses as SOFA reads a vector<RigidMass<3>> (DiagonalMass on
// Rigid3d states): masses one after the other, each "mass volume" then the 3×3
// inertia as parse::read_rigid3_mass takes it, and the matrix's closing ']'
// consumed ("15 15 [20 0 0,0 20 0,0 0 20] 1 1 [1 0 0,0 1 0,0 0 1]").
#pragma once

#include <string_view>
#include <vector>

namespace sinew::parse {

// 11 values per complete mass go into `v`; an incomplete or unreadable last mass
// is dropped (SOFA's vector reader stops at the element that fails). False when
// the text did not end there.
bool read_rigid3_mass_list(std::string_view text, std::vector<double>& v);

}  // namespace sinew::parse
