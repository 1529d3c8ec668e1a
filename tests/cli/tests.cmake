add_test(NAME cli_behaviour
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/cli_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli_behaviour PROPERTIES LABELS cli)
add_test(NAME cli_released_layouts
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/released_layouts_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli_released_layouts PROPERTIES LABELS cli)

add_test(NAME cli.motion_formats
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/motion_formats_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.motion_formats PROPERTIES LABELS cli)

add_test(NAME cli.dmpl
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/dmpl_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.dmpl PROPERTIES LABELS cli)

# The README's option table and docs/cli.md agree with --help (cli/options.cpp).
add_test(NAME cli.docs
  COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/check-cli-docs.py $<TARGET_FILE:smpl-export>
  ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.docs PROPERTIES LABELS cli)
