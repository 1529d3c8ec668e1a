# Reliability suite (tests/reliability/*_cases.py, harness.py): bad, hostile and
# interrupted runs of smpl-export; each case checks exit code, one error line
# naming the file, no output or temporary file left, inputs unchanged and
# peak memory (README "Errors").
#
# It needs a product build of smpl-export: peak memory is only meaningful
# without sanitizers, and the out-of-memory cases limit the address space
# (ulimit -v), which AddressSanitizer cannot run under. scripts/test.sh runs
# it in its Release build (SMPL_TEST_SET=integration), on this build's
# smpl-export; SMPL_RELIABILITY_EXE may name another product binary.
set(SMPL_RELIABILITY_EXE "" CACHE FILEPATH
    "smpl-export binary for the reliability suite (default: this build's; must not be sanitized)")
if(SMPL_RELIABILITY_EXE)
  set(smpl_reliability_exe ${SMPL_RELIABILITY_EXE})
else()
  set(smpl_reliability_exe $<TARGET_FILE:smpl-export>)
endif()
file(GLOB SMPL_RELIABILITY_CASES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*_cases.py)
foreach(script ${SMPL_RELIABILITY_CASES})
  get_filename_component(stem ${script} NAME_WE)
  string(REPLACE "_cases" "" stem ${stem})
  add_test(NAME reliability.${stem}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${script} ${smpl_reliability_exe} ${SMPL_FIXTURE_DIR}
            ${CMAKE_BINARY_DIR}/reliability/${stem})
  set_tests_properties(reliability.${stem} PROPERTIES LABELS cli)
endforeach()
