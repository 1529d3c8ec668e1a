# BVH output through Blender's own BVH importer (included from roundtrip/tests.cmake,
# which defines SMPL_ROUNDTRIP_DIR, SMPL_ROUNDTRIP_SRC and SMPL_BLENDER_RUN).
#
#   bvh.export.<case>   smpl-export --motion writes <build>/roundtrip/bvh_<case>.bvh,
#                       case = <model>_<motion>_<units>[_fps<F>][_floor|_root][_resta]
#   bvh.blender.<case>  headless Blender imports it (bpy.ops.import_anim.bvh, options in
#                       blender_bvh.py) and compares every joint's world position with
#                       numpy's posed joints at the first, middle and last frame (1e-5 m)
#
# Blender is required: when missing the tests fail, they never skip.

# smpl_bvh_case(<model> <motion> <units> [FPS f])
function(smpl_bvh_case model motion units)
  cmake_parse_arguments(B "" "FPS;PLACE;REST" "" ${ARGN})
  set(case ${model}_${motion}_${units})
  set(fps_args)
  set(place_args)
  set(check_args)
  if(B_FPS)
    set(case ${case}_fps${B_FPS})
    set(fps_args --fps ${B_FPS})
  endif()
  if(B_PLACE STREQUAL "floor")
    set(case ${case}_floor)
    set(place_args --origin floor)
    set(check_args --placed)
  elseif(B_PLACE STREQUAL "root")
    set(case ${case}_root)
    set(place_args --root-bone)
    set(check_args --placed)
  endif()
  if(B_REST)
    set(case ${case}_rest${B_REST})
    list(APPEND place_args --rest-pose ${B_REST})
    list(APPEND check_args --rest-pose ${B_REST})
  endif()
  set(bvh ${SMPL_ROUNDTRIP_DIR}/bvh_${case}.bvh)
  add_test(NAME bvh.export.${case}
    COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/${model}.npz
            --motion ${SMPL_FIXTURE_DIR}/motions/${motion}.npz --bvh-units ${units} ${fps_args}
            ${place_args} --out ${bvh} --quiet)
  add_test(NAME bvh.blender.${case}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_bvh.py --
            --bvh ${bvh} --model ${SMPL_FIXTURE_DIR}/models/${model}.npz
            --motion ${SMPL_FIXTURE_DIR}/motions/${motion}.npz --units ${units} --tol 1e-5
            --label ${case} ${fps_args} ${check_args})
  set_tests_properties(bvh.export.${case} PROPERTIES
    FIXTURES_SETUP bvh_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(bvh.blender.${case} PROPERTIES
    FIXTURES_REQUIRED "bvh_${case};roundtrip_dir" LABELS blender TIMEOUT 600)
endfunction()

# AMASS SMPL-H (120 fps, Z-up world, trans, 16 betas) in metres and centimetres;
# AMASS SMPL-X resampled 60 -> 30 fps; SMPL-H motion on SMPL (fingers dropped).
smpl_bvh_case(smplh_small amass_smplh m)
smpl_bvh_case(smplh_small amass_smplh cm)
smpl_bvh_case(smplx_small amass_smplx m FPS 30)
smpl_bvh_case(smpl_small amass_smplh cm)
# --origin floor (one offset in y, from the sidecar) and --root-bone (a `root` joint carrying
# the pelvis' ground projection, the pelvis its height): the same joints, moved as the file
# contract says ("Where the body stands").
smpl_bvh_case(smplh_small amass_smplh m PLACE floor)
smpl_bvh_case(smplh_small amass_smplh cm PLACE root)
# --rest-pose a: the offsets of the A-pose rest (numpy's A pose, Blender's rest heads) and
# every key re-expressed: the same posed joints as the T rest, within 1e-5 m.
smpl_bvh_case(smplh_small amass_smplh m REST a)
smpl_bvh_case(smplx_small amass_smplx cm FPS 30 REST a)
smpl_bvh_case(smplh_small amass_smplh cm PLACE root REST a)
