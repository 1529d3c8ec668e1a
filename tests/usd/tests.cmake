# USD (UsdSkel) exports read back by an independent reader (included from tests/CMakeLists.txt).
#
#   usd.export.<case>         smpl-export writes <build>/usd/<case>.<usda|usdz|glb>, the GLB with
#                             the same options as the USD files
#   usd.read.<case>           tinyusdz (npm, WebAssembly, under node: usd_read.mjs) loads the
#                             .usda / .usdz: Tydra's UsdSkel checks and mesh, the parsed layer's
#                             skeleton, skin, blend shapes and animation -> <case>.json
#   usd.reference.<model>     numpy's forward pass of the motion (tests/web/anim_reference.py)
#   usd.check.<case>          usdskel_eval.py: the .usdz container (stored, 64-byte aligned); points, joints, weights, blend shape offsets and
#                             animated weights equal the GLB's; with a motion, numpy's UsdSkel
#                             evaluation within 1e-5 m of the model at the first, middle and
#                             last frame, and the (x,y,z,w)-quaternion and column-vector-matrix
#                             readings of the same file must miss it
#   usd.read.rejects_non_usd  the reader fails (exit 1) on a file that is no USD
#
# node and web/node_modules (npm ci in web/: tinyusdz) are required: when missing the
# tests fail, they never skip. Label usd.

set(SMPL_USD_DIR ${CMAKE_BINARY_DIR}/usd)
set(SMPL_USD_SRC ${CMAKE_CURRENT_LIST_DIR})
find_program(SMPL_USD_NODE node)
if(NOT SMPL_USD_NODE)
  set(SMPL_USD_NODE node)  # the tests then fail with "not found": no silent skip
endif()

add_test(NAME usd.mkdir COMMAND ${CMAKE_COMMAND} -E make_directory ${SMPL_USD_DIR})
set_tests_properties(usd.mkdir PROPERTIES FIXTURES_SETUP usd_dir LABELS usd)

# smpl_usd_case(<case> <model> [MOTION file FRAMES a,b,c]): exports (usda, usdz, glb), reads, checks.
function(smpl_usd_case case model)
  cmake_parse_arguments(U "" "MOTION;FRAMES" "" ${ARGN})
  set(args --model ${SMPL_FIXTURE_DIR}/models/${model}.npz --max-influences 4
           --skin-weights truncated --corrective-refit off)
  set(reference)
  if(U_MOTION)
    list(APPEND args --motion ${U_MOTION})
    set(reference --reference ${SMPL_USD_DIR}/${case}_ref.json --frames ${U_FRAMES})
    # anim_reference.py prunes by truncation: the same weights as the exports' --skin-weights truncated.
    add_test(NAME usd.reference.${case}
      COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/tests/web/anim_reference.py
              --model ${SMPL_FIXTURE_DIR}/models/${model}.npz --motion ${U_MOTION} --max-influences 4
              --frames ${U_FRAMES} --out ${SMPL_USD_DIR}/${case}_ref)
    set_tests_properties(usd.reference.${case} PROPERTIES
      FIXTURES_SETUP usd_ref_${case} FIXTURES_REQUIRED usd_dir LABELS usd)
  endif()
  foreach(ext glb usda usdz)
    add_test(NAME usd.export.${case}_${ext} COMMAND smpl-export ${args} --out ${SMPL_USD_DIR}/${case}.${ext} --quiet)
    set_tests_properties(usd.export.${case}_${ext} PROPERTIES
      FIXTURES_SETUP usd_${case}_${ext} FIXTURES_REQUIRED usd_dir LABELS usd)
  endforeach()
  foreach(ext usda usdz)
    add_test(NAME usd.read.${case}_${ext}
      COMMAND ${SMPL_USD_NODE} ${SMPL_USD_SRC}/usd_read.mjs ${SMPL_USD_DIR}/${case}.${ext}
              ${SMPL_USD_DIR}/${case}_${ext}.json)
    set_tests_properties(usd.read.${case}_${ext} PROPERTIES
      FIXTURES_SETUP usd_read_${case}_${ext} FIXTURES_REQUIRED "usd_${case}_${ext};usd_dir" LABELS usd TIMEOUT 300)
    set(needs "usd_read_${case}_${ext};usd_${case}_glb;usd_dir")
    set(container)
    if(ext STREQUAL "usdz")
      set(container --usdz ${SMPL_USD_DIR}/${case}.usdz)
    endif()
    if(U_MOTION)
      list(APPEND needs usd_ref_${case})
    endif()
    add_test(NAME usd.check.${case}_${ext}
      COMMAND ${SMPL_SYSTEM_PYTHON} ${SMPL_USD_SRC}/usdskel_eval.py --usd ${SMPL_USD_DIR}/${case}_${ext}.json
              --glb ${SMPL_USD_DIR}/${case}.glb ${reference} ${container})
    set_tests_properties(usd.check.${case}_${ext} PROPERTIES FIXTURES_REQUIRED "${needs}" LABELS usd)
  endforeach()
endfunction()

smpl_usd_case(smpl_small smpl_small)
smpl_usd_case(smplx_small smplx_small)
smpl_usd_case(smpl_small_motion smpl_small MOTION ${SMPL_FIXTURE_DIR}/motions/amass_smplh.npz FRAMES 0,120,239)
smpl_usd_case(smplx_small_motion smplx_small MOTION ${SMPL_FIXTURE_DIR}/motions/amass_smplx.npz FRAMES 0,60,119)

# A file tinyusdz cannot load must fail the reader (exit 1), not give an empty reading.
add_test(NAME usd.read.rejects_non_usd
  COMMAND ${SMPL_USD_NODE} ${SMPL_USD_SRC}/usd_read.mjs ${SMPL_USD_DIR}/smpl_small.glb
          ${SMPL_USD_DIR}/rejects_non_usd.json)
set_tests_properties(usd.read.rejects_non_usd PROPERTIES WILL_FAIL TRUE
  FIXTURES_REQUIRED "usd_smpl_small_glb;usd_dir" LABELS usd)
