# Video-to-motion layouts through Blender (included from roundtrip/tests.cmake):
# three of the tool files of tests/fixtures/make_video_layouts.py, exported as
# tests/cli/layouts/run_cases.py does, imported by headless Blender with no
# runtime script, and compared at the case's three clip frames with the numpy
# reference of the tool's conventions (tests/cli/layouts/video_cases.py) at 1e-5 m.
#
#   video.export.<case>     smpl-export writes <build>/roundtrip/video_<case>.glb
#   video.reference.<case>  video_reference.py writes its numpy reference (JSON)
#   video.blender.<case>    blender_video.py compares Blender's evaluated mesh
#   video.validator         Khronos glTF validator on the three GLBs
#
# Blender and node are required: when missing the tests fail, they never skip.

set(SMPL_VIDEO_GLBS)
set(SMPL_VIDEO_FIXTURES)

# smpl_video_case(<case> <model> <input flag> <fixture path under layouts/video>)
function(smpl_video_case name model flag fixture)
  set(asset ${SMPL_ROUNDTRIP_DIR}/video_${name}.glb)
  add_test(NAME video.export.${name}
    COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/${model}.npz
            ${flag} ${SMPL_FIXTURE_DIR}/layouts/video/${fixture} --out ${asset}
            --skin-weights truncated --corrective-refit off --max-influences 4 --quiet)
  add_test(NAME video.reference.${name}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${SMPL_ROUNDTRIP_SRC}/video_reference.py --case ${name}
            --fixtures ${SMPL_FIXTURE_DIR} --out ${asset}.ref.json)
  add_test(NAME video.blender.${name}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_video.py --
            --asset ${asset} --reference ${asset}.ref.json --tol 1e-5)
  set_tests_properties(video.export.${name} PROPERTIES
    FIXTURES_SETUP video_${name} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(video.reference.${name} PROPERTIES
    FIXTURES_SETUP video_ref_${name} FIXTURES_REQUIRED "video_${name};roundtrip_dir" LABELS blender)
  set_tests_properties(video.blender.${name} PROPERTIES
    FIXTURES_REQUIRED "video_${name};video_ref_${name};roundtrip_dir" LABELS blender TIMEOUT 600)
  set(SMPL_VIDEO_GLBS ${SMPL_VIDEO_GLBS} ${asset} PARENT_SCOPE)
  set(SMPL_VIDEO_FIXTURES ${SMPL_VIDEO_FIXTURES} video_${name} PARENT_SCOPE)
endfunction()

smpl_video_case(wham_world smpl_small --motion wham/wham_output.pkl)                # joblib
smpl_video_case(gvhmr_global smplx_small --motion gvhmr/hmr4d_results.pt)           # torch zip
smpl_video_case(smplerx_seq smplx_small --motion-sequence smplerx/smplx)            # per-frame npz

add_test(NAME video.validator
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_VIDEO_GLBS})
set_tests_properties(video.validator PROPERTIES
  FIXTURES_REQUIRED "${SMPL_VIDEO_FIXTURES}" LABELS "blender;validator")
