# Unity builds: CMake compiles the sources of each target in batches of 16, one
# translation unit per batch. A clean build parses each header and instantiates
# each template once per batch instead of once per file: about 2.5x less compiler
# time, which is what keeps CI's two clean builds (Release, then the sanitizer
# build of scripts/validate) inside its time limit on two cores. scripts/build and
# scripts/validate turn it on; a developer's incremental build (ccache, one file
# changed) is faster without it, hence the default.
option(SINEW_UNITY "Unity (jumbo) build of Sinew's own targets" OFF)
if(SINEW_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 16)
  # A batch includes .cpp files: GCC then sees their anonymous-namespace types as
  # coming from a header (-Wsubobject-linkage), which is only true of the batch file.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-subobject-linkage)
  endif()
endif()

# Files compiled on their own even in a unity build: they define file-local
# helpers whose names collide with a neighbour's, or need macros set before their
# system headers (GL_GLEXT_PROTOTYPES). Both build modes compile every file, so a
# file that leaves this list must still build alone.
set(SINEW_UNITY_SKIP
  python/src/handles.cpp
  python/src/linear_system.cpp
  src/constraint/solver/lcp_constraint_solver.cpp
  src/engine/difference_engine.cpp
  src/engine/generate/generate_grid.cpp
  src/engine/generate/mesh_tetra_stuffing.cpp
  src/engine/transform_position.cpp
  src/forcefield/fem/tetra_fem.cpp
  src/forcefield/fem/triangular_fem_force_field_optim.cpp
  src/forcefield/spring/triangular_quadratic_springs_force_field.cpp
  src/io/mesh_trian_loader.cpp
  src/io/vtk_writer.cpp
  src/mapping/barycentric_mapping_rigid.cpp
  src/mapping/deformable_on_rigid_frame_mapping.cpp
  src/render/gl_renderer.cpp
  src/scene/xml_tree.cpp
  src/topology/algorithm/triangle_incision_split.cpp
  src/visual/data_display.cpp
  src/visual/ogl_model.cpp
  src/visual/shader/render_passes.cpp
  tests/collision/min_proximity_test.cpp
  tests/collision/new_proximity_test.cpp
  tests/conformance/mapping_battery_test.cpp
  tests/conformance/mass_battery_test.cpp
  tests/constraint/constraint_allocation_test.cpp
  tests/core/link_cycle_test.cpp
  tests/core/node_test.cpp
  tests/core/path_test.cpp
  tests/core/value_text_test.cpp
  tests/engine/select_engines_test.cpp
  tests/forcefield/fast_tetrahedral_corotational_test.cpp
  tests/forcefield/fem_tetrahedron_test.cpp
  tests/forcefield/hexa_simd_test.cpp
  tests/forcefield/hyperelastic_component_test.cpp
  tests/forcefield/nfem_components_test.cpp
  tests/forcefield/nfem_element_fem_test.cpp
  tests/forcefield/quad_bending_test.cpp
  tests/forcefield/spring_force_fields_test.cpp
  tests/forcefield/tetra_fem_test.cpp
  tests/forcefield/tetra_parallel_test.cpp
  tests/forcefield/tetra_simd_test.cpp
  tests/forcefield/tri_triangle_force_fields_test.cpp
  tests/forcefield/triangle_fem_test.cpp
  tests/forcefield/triangular_biquadratic_springs_test.cpp
  tests/forcefield/triangular_quadratic_springs_test.cpp
  tests/forcefield/triangular_tensor_mass_test.cpp
  tests/io/io_loaders_test.cpp
  tests/mapping/deformable_on_rigid_frame_mapping_test.cpp
  tests/mapping/measure_mappings_test.cpp
  tests/mapping/subset_multi_mapping_scene_test.cpp
  tests/mapping/tubular_mapping_test.cpp
  tests/mass/mass_diagonal_test.cpp
  tests/mass/mass_mesh_matrix_test.cpp
  tests/projective/direction_constraint_test.cpp
  tests/projective/oscillator_constraint_test.cpp
  tests/projective/trajectory_constraints_test.cpp
  tests/scene/badinput_link_cycles_test.cpp
  tests/scene/badinput_sizes_test.cpp
  tests/scene/badinput_values_test.cpp
  tests/scene/resource_paths_test.cpp
  tests/scene/xml_tree_test.cpp
  tests/solver/dense_direct_solvers_test.cpp
  tests/solver/linsys_assembly_test.cpp
  tests/solver/pcg_preconditioners_test.cpp
  tests/solver/pcg_solvers_test.cpp
  tests/solver/variational_symplectic_solver_test.cpp
  tests/topology/topo_hexa_quad_test.cpp
  tests/topology/topo_points_test.cpp
  tests/topology/topo_removal_test.cpp
  tests/topology/topo_sparse_grid_ramification_test.cpp
  tests/topology/topology_examples_test.cpp
)

# sinew_apply_unity_skips(DIR...): called once the targets exist. Source file
# properties belong to a directory, so they are set in each one that has targets.
function(sinew_apply_unity_skips)
  if(NOT SINEW_UNITY)
    return()
  endif()
  set(paths)
  foreach(f ${SINEW_UNITY_SKIP})
    list(APPEND paths ${CMAKE_SOURCE_DIR}/${f})
  endforeach()
  set(dirs)
  foreach(d ${ARGN})
    list(APPEND dirs ${CMAKE_SOURCE_DIR}/${d})
  endforeach()
  set_source_files_properties(${paths} DIRECTORY ${dirs} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
