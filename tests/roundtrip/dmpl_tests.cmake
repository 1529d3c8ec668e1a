# DMPL soft tissue (included from roundtrip/tests.cmake). Fixtures:
# tests/fixtures/make_dmpl.py (<build>/fixtures/dmpl).
#
#   dmpl.export.<fmt>_<joints>   smpl-export --motion amass_smplh_dmpl --dmpl basis
#                                --dmpl-joints fixed|regressed -> <build>/roundtrip/dmpl_<fmt>_<joints>.<fmt>
#   dmpl.blender.<fmt>_<joints>  headless Blender plays it with no script: first/middle/last
#                                frame vs numpy's published math (blender_dmpl.py), 1e-4 m
#   dmpl.validator               Khronos glTF validator on both GLBs
#   dmpl.cost                    the fixed-joint cost the CLI prints vs numpy over every frame
set(SMPL_DMPL_FIXTURES ${SMPL_FIXTURE_DIR}/dmpl)
set(SMPL_DMPL_GLBS)
set(SMPL_DMPL_GLB_FIXTURES)
foreach(format glb fbx)
  foreach(joints fixed regressed)
    set(case ${format}_${joints})
    set(asset ${SMPL_ROUNDTRIP_DIR}/dmpl_${case}.${format})
    add_test(NAME dmpl.export.${case}
      COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/smplh_small.npz
              --motion ${SMPL_DMPL_FIXTURES}/amass_smplh_dmpl.npz --dmpl ${SMPL_DMPL_FIXTURES}/dmpl_smplh_small.npz
              --dmpl-joints ${joints} --skin-weights truncated --corrective-refit off --out ${asset} --quiet)
    add_test(NAME dmpl.blender.${case}
      COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_dmpl.py --
              --asset ${asset} --model ${SMPL_FIXTURE_DIR}/models/smplh_small.npz
              --motion ${SMPL_DMPL_FIXTURES}/amass_smplh_dmpl.npz --dmpl ${SMPL_DMPL_FIXTURES}/dmpl_smplh_small.npz
              --joints ${joints} --tol 1e-4)
    set_tests_properties(dmpl.export.${case} PROPERTIES
      FIXTURES_SETUP dmpl_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
    set_tests_properties(dmpl.blender.${case} PROPERTIES
      FIXTURES_REQUIRED "dmpl_${case};roundtrip_dir" LABELS blender TIMEOUT 600)
    if(format STREQUAL "glb")
      list(APPEND SMPL_DMPL_GLBS ${asset})
      list(APPEND SMPL_DMPL_GLB_FIXTURES dmpl_${case})
    endif()
  endforeach()
endforeach()
add_test(NAME dmpl.validator
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_DMPL_GLBS})
set_tests_properties(dmpl.validator PROPERTIES
  FIXTURES_REQUIRED "${SMPL_DMPL_GLB_FIXTURES}" LABELS "blender;validator")
