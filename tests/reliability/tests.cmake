# Reliability suite (tests/reliability/*_cases.py, harness.py): bad, hostile and
# interrupted runs of smpl-export; each case checks exit code, one error line
# naming the file, no output or temporary file left, inputs unchanged and
# peak memory (README "Errors").
file(GLOB SMPL_RELIABILITY_CASES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*_cases.py)
foreach(script ${SMPL_RELIABILITY_CASES})
  get_filename_component(stem ${script} NAME_WE)
  string(REPLACE "_cases" "" stem ${stem})
  add_test(NAME reliability.${stem}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${script} $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR}
            ${CMAKE_BINARY_DIR}/reliability/${stem})
  set_tests_properties(reliability.${stem} PROPERTIES LABELS cli)
endforeach()
