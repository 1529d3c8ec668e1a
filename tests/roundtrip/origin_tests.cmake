# --origin floor and --root-bone through Blender (included from roundtrip/tests.cmake).
#
#   origin.export.<case>   smpl-export --motion with --origin floor (and --root-bone),
#                          the model's own skin (--max-influences 8 --skin-weights
#                          truncated keeps every influence of the fixture)
#   origin.blender.<case>  headless Blender plays it (blender_animation.py --check-floor):
#                          posed vertices and joints vs numpy moved by the metadata's
#                          offset (1e-5 m), numpy's lowest posed vertex over the clip at
#                          y = 0 (1e-6 m), the root bone at the pelvis' ground projection
#   origin.validator       Khronos glTF validator on the GLBs
foreach(variant floor root)
  foreach(format glb fbx)
    set(case smplh_small_amass_smplh_${variant}_${format})
    set(extra --origin floor)
    if(variant STREQUAL "root")
      set(extra --root-bone)
    endif()
    set(asset ${SMPL_ROUNDTRIP_DIR}/origin_${case}.${format})
    set(motion ${SMPL_FIXTURE_DIR}/motions/amass_smplh.npz)
    add_test(NAME origin.export.${case}
      COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/smplh_small.npz --motion ${motion}
              --max-influences 8 --skin-weights truncated ${extra} --out ${asset} --quiet)
    add_test(NAME origin.blender.${case}
      COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_animation.py --
              --asset ${asset} --model ${SMPL_FIXTURE_DIR}/models/smplh_small.npz
              --motion ${motion} --label smplh_${variant} --tol 1e-5 --check-floor)
    set_tests_properties(origin.export.${case} PROPERTIES
      FIXTURES_SETUP origin_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
    set_tests_properties(origin.blender.${case} PROPERTIES
      FIXTURES_REQUIRED "origin_${case};roundtrip_dir" LABELS blender TIMEOUT 600)
  endforeach()
endforeach()
add_test(NAME origin.validator
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js
          ${SMPL_ROUNDTRIP_DIR}/origin_smplh_small_amass_smplh_floor_glb.glb
          ${SMPL_ROUNDTRIP_DIR}/origin_smplh_small_amass_smplh_root_glb.glb)
set_tests_properties(origin.validator PROPERTIES
  FIXTURES_REQUIRED "origin_smplh_small_amass_smplh_floor_glb;origin_smplh_small_amass_smplh_root_glb"
  LABELS "blender;validator")
