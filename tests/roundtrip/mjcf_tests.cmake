# MJCF output read by MuJoCo (tests/roundtrip/mjcf_test.sh, mjcf_check.cpp):
#   mjcf.builtin, mjcf.smplx, mjcf.smplx_ball   export, independent reference, MuJoCo checks
#   mjcf.motion, mjcf.motion_ball               --motion: .qpos.npz and keyframes against numpy
#   mjcf.mesh, mjcf.smplx_mesh                  --mjcf-geoms mesh: hull points against the GLB's skin
#   mjcf.refusals                               hostile values, inapplicable options, same bytes
# mjcf_check links MuJoCo (Debian libmujoco-dev, scripts/setup-deps.sh); smpl-export does not.
# Without MuJoCo the tests are still registered and fail (the checker path names the missing
# package): never a skip. Label: integration.
# The header and the library directly: Debian's mujocoConfig.cmake names
# /usr/include/libqhull_r/ (libqhull-dev, which libmujoco-dev does not pull in)
# in its include path, and CMake refuses the whole configure when it is missing.
find_path(SMPL_MUJOCO_INCLUDE mujoco/mujoco.h)
find_library(SMPL_MUJOCO_LIBRARY mujoco)
if(SMPL_MUJOCO_INCLUDE AND SMPL_MUJOCO_LIBRARY)
  add_executable(mjcf_check ${CMAKE_CURRENT_LIST_DIR}/mjcf_check.cpp)
  target_include_directories(mjcf_check PRIVATE ${SMPL_MUJOCO_INCLUDE})
  target_link_libraries(mjcf_check PRIVATE ${SMPL_MUJOCO_LIBRARY})
  set(SMPL_MJCF_CHECK $<TARGET_FILE:mjcf_check>)
else()
  message(WARNING "MuJoCo (libmujoco-dev) not found: the mjcf.* tests will fail; run scripts/setup-deps.sh")
  set(SMPL_MJCF_CHECK "mjcf_check-not-built:install-libmujoco-dev-with-scripts/setup-deps.sh")
endif()
foreach(case builtin smplx smplx_ball mesh smplx_mesh motion motion_ball refusals)
  add_test(NAME mjcf.${case}
    COMMAND ${CMAKE_CURRENT_LIST_DIR}/mjcf_test.sh $<TARGET_FILE:smpl-export> ${SMPL_MJCF_CHECK}
            ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR} ${SMPL_FIXTURE_DIR} ${CMAKE_BINARY_DIR}/mjcf ${case})
  set_tests_properties(mjcf.${case} PROPERTIES LABELS integration)
endforeach()
