// The one place listing every built-in component, module by module.
// Explicit calls (rather than static initialisers) keep static libraries
// from silently dropping components at link time.
#include "components/register_all.h"

#include "core/registry.h"

namespace sinew {

// core
void register_required_plugin(Registry&);
// state
void register_mechanical_object(Registry&);
// topology
void register_regular_grid_topology(Registry&);
// mass
void register_uniform_mass(Registry&);
// forcefield
void register_hexahedron_fem_force_field(Registry&);
// projective
void register_fixed_projective_constraint(Registry&);
// engine
void register_box_roi(Registry&);
// solver
void register_euler_implicit_solver(Registry&);
void register_cg_linear_solver(Registry&);
// animation
void register_default_animation_loop(Registry&);
// visual
void register_viewer_only(Registry&);

void register_all_components() {
  static bool done = false;
  if (done) return;
  done = true;
  Registry& r = registry();
  register_required_plugin(r);
  register_mechanical_object(r);
  register_regular_grid_topology(r);
  register_uniform_mass(r);
  register_hexahedron_fem_force_field(r);
  register_fixed_projective_constraint(r);
  register_box_roi(r);
  register_euler_implicit_solver(r);
  register_cg_linear_solver(r);
  register_default_animation_loop(r);
  register_viewer_only(r);
}

}  // namespace sinew
