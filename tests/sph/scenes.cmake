# SofaSphFluid scenes as CTest cases (issue 17): the plugin's own regression
# list through `sinew regress` (its references path is relative to the list),
# and every scene of the plugin's examples/ loaded and run for 100 steps.
# Both skip (exit code 77) when the SOFA data folder is absent.
set(sph_examples ${SINEW_DATA_DIR}/plugins/SofaSphFluid/examples)
foreach(scene SPHFluidForceField.scn SPHFluidForceField_benchmarks.scn SPHFluidSurfaceMapping.scn
              SPHParticleSink.scn SPHParticleSource.scn)
  add_test(NAME sofa-sph:${scene}
           COMMAND ${sinew_regress_command} --data ${SINEW_DATA_DIR} --list ${sph_examples}/RegressionStateScenes.regression-tests
                   --filter "^${scene}$")
  set_tests_properties(sofa-sph:${scene} PROPERTIES SKIP_RETURN_CODE 77 LABELS sofa TIMEOUT 900)
endforeach()
# Meshes and XML macros (BoxConstraint) come from the data folder's share/.
foreach(scene OglFluidModel_SPH.scn OglFluidModel_SPHParticles.scn ParticleSink.scn ParticleSource.scn
              ParticlesRepulsionForceField.scn PointSplatModel.scn SPHDemo.scn SPHFluidForceField.scn
              SPHFluidForceField_benchmarks.scn SPHFluidSurfaceMapping.scn SPHParticleSink.scn
              SPHParticleSink_obstacle.scn SPHParticleSource.scn SpatialGridContainer.scn SpatialGridPointModel.scn)
  add_test(NAME sph-run:${scene}
           COMMAND sh -c "test -f \"$1\" || { echo \"SOFA data absent ($1): skipped\"; exit 77; }; exec \"$0\" run \"$1\" -n 100 --hideProgressBar --data-path \"$2\""
                   $<TARGET_FILE:sinew> ${sph_examples}/${scene} ${SINEW_DATA_DIR}/share)
  # From the source tree: XML macros (BoxConstraint) are looked up in the default data root.
  set_tests_properties(sph-run:${scene} PROPERTIES SKIP_RETURN_CODE 77 LABELS sofa TIMEOUT 900
                                                   WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
endforeach()
