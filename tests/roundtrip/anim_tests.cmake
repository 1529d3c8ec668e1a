# Baked animation through real readers (included from roundtrip/tests.cmake,
# which defines SMPL_ROUNDTRIP_DIR, SMPL_BLENDER_RUN, SMPL_NODE).
#
#   anim.export.<case>    smpl-export --motion writes <build>/roundtrip/anim_<case>.<fmt>,
#                         case = <model>_<motion>_m<M>_<fmt>[_fps<F>]
#   anim.blender.<case>   headless Blender imports it and plays it with no runtime
#                         script: first/middle/last frame vs numpy (1e-4 m); _qanim:
#                         --quantize-animation
#   anim.validator        Khronos glTF validator on every animated GLB
#   cli.batch             --motion-dir batch mode (tests/cli/batch_test.sh)
#
# Blender and node are required: when missing the tests fail, they never skip.

set(SMPL_ANIM_MOTIONS ${SMPL_FIXTURE_DIR}/motions)
set(SMPL_ANIM_GLBS)
set(SMPL_ANIM_GLB_FIXTURES)

# smpl_anim_case(<model> <motion> <M> <format> [FPS f] [REPORT] [QANIM])
# QANIM: --quantize-animation (normalised int16 rotation and weight keys).
function(smpl_anim_case model motion m format)
  cmake_parse_arguments(A "REPORT;QANIM" "FPS" "" ${ARGN})
  set(case ${model}_${motion}_m${m}_${format})
  set(fps_args)
  if(A_FPS)
    set(case ${case}_fps${A_FPS})
    set(fps_args --fps ${A_FPS})
  endif()
  set(export_args)
  if(A_QANIM)
    set(case ${case}_qanim)
    set(export_args --quantize-animation)
  endif()
  set(asset ${SMPL_ROUNDTRIP_DIR}/anim_${case}.${format})
  set(report)
  if(A_REPORT)
    set(report --subframe-report)
  endif()
  add_test(NAME anim.export.${case}
    COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/${model}.npz
            --motion ${SMPL_ANIM_MOTIONS}/${motion}.npz --max-influences ${m} ${fps_args}
            --out ${asset} --quiet ${export_args})
  add_test(NAME anim.blender.${case}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_animation.py --
            --asset ${asset} --model ${SMPL_FIXTURE_DIR}/models/${model}.npz
            --motion ${SMPL_ANIM_MOTIONS}/${motion}.npz --label ${model} --tol 1e-4 ${fps_args} ${report})
  set_tests_properties(anim.export.${case} PROPERTIES
    FIXTURES_SETUP anim_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(anim.blender.${case} PROPERTIES
    FIXTURES_REQUIRED "anim_${case};roundtrip_dir" LABELS blender TIMEOUT 600)
  if(format STREQUAL "glb")
    set(SMPL_ANIM_GLBS ${SMPL_ANIM_GLBS} ${asset} PARENT_SCOPE)
    set(SMPL_ANIM_GLB_FIXTURES ${SMPL_ANIM_GLB_FIXTURES} anim_${case} PARENT_SCOPE)
  endif()
endfunction()

# SMPL-H and SMPL-X motions on their own layouts, and SMPL-H on SMPL (fingers
# dropped, SMPL's hand joints at rest). M = 8 keeps every influence of the
# fixtures; M = 4 is the engines' limit.
foreach(pair smplh_small:amass_smplh smplx_small:amass_smplx smpl_small:amass_smplh)
  string(REPLACE ":" ";" pair ${pair})
  list(GET pair 0 model)
  list(GET pair 1 motion)
  foreach(m 8 4)
    foreach(format glb fbx)
      smpl_anim_case(${model} ${motion} ${m} ${format})
    endforeach()
  endforeach()
  smpl_anim_case(${model} ${motion} 8 glb QANIM)  # Blender reads normalised keys
endforeach()

# Resampling: 120 -> 30 fps keys fall on every 4th source frame (exact; the
# report shows the error half-way between keys); 120 -> 50 fps keys fall
# between source frames, so Blender must match numpy's slerp there.
foreach(format glb fbx)
  smpl_anim_case(smplh_small amass_smplh 8 ${format} FPS 30 REPORT)
  smpl_anim_case(smplh_small amass_smplh 8 ${format} FPS 50 REPORT)
endforeach()

add_test(NAME anim.validator
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_ANIM_GLBS})
set_tests_properties(anim.validator PROPERTIES
  FIXTURES_REQUIRED "${SMPL_ANIM_GLB_FIXTURES}" LABELS "blender;validator")

add_test(NAME cli.batch
  COMMAND ${PROJECT_SOURCE_DIR}/tests/cli/batch_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.batch PROPERTIES LABELS "blender;cli")

# Other motion layouts (tests/fixtures/make_motion_formats.py) on SMPL-X: a
# SMPLCodec .smpl motion and a SMPLify-X fit with PCA hands (one frame);
# anim.validator.formats runs the Khronos validator on both GLBs.
set(SMPL_FORMAT_GLBS)
set(SMPL_FORMAT_FIXTURES)
foreach(motion codec_root.smpl fit_pca.pkl)
  string(REPLACE "." "_" case smplx_small_${motion})
  set(asset ${SMPL_ROUNDTRIP_DIR}/anim_${case}.glb)
  add_test(NAME anim.export.${case}
    COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/smplx_small.npz
            --motion ${SMPL_FIXTURE_DIR}/formats/${motion} --max-influences 8 --out ${asset} --quiet)
  add_test(NAME anim.blender.${case}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_animation.py --
            --asset ${asset} --model ${SMPL_FIXTURE_DIR}/models/smplx_small.npz
            --motion ${SMPL_FIXTURE_DIR}/formats/${motion} --label smplx_${motion} --tol 1e-4)
  set_tests_properties(anim.export.${case} PROPERTIES
    FIXTURES_SETUP anim_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(anim.blender.${case} PROPERTIES
    FIXTURES_REQUIRED "anim_${case};roundtrip_dir" LABELS blender TIMEOUT 600)
  list(APPEND SMPL_FORMAT_GLBS ${asset})
  list(APPEND SMPL_FORMAT_FIXTURES anim_${case})
endforeach()
add_test(NAME anim.validator.formats
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_FORMAT_GLBS})
set_tests_properties(anim.validator.formats PROPERTIES
  FIXTURES_REQUIRED "${SMPL_FORMAT_FIXTURES}" LABELS "blender;validator")
