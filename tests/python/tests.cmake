# The Python module (python/, `import smpl_export`): pytest (Debian python3-pytest)
# on the module of this build tree, one CTest test per file, label `python`.
# They compare with this tree's smpl-export and read the synthetic fixtures.
if(TARGET smpl_export_python)
  file(GLOB SMPL_PYTHON_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/test_*.py)
  foreach(test ${SMPL_PYTHON_TESTS})
    get_filename_component(stem ${test} NAME_WE)
    string(REGEX REPLACE "^test_" "" stem ${stem})
    add_test(NAME python.${stem}
      COMMAND ${SMPL_SYSTEM_PYTHON} -m pytest -q -p no:cacheprovider ${test})
    set_tests_properties(python.${stem} PROPERTIES LABELS python
      ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python;SMPL_EXPORT_EXE=$<TARGET_FILE:smpl-export>;SMPL_FIXTURE_DIR=${SMPL_FIXTURE_DIR};SMPL_SOURCE_DIR=${PROJECT_SOURCE_DIR};SMPL_BUILD_DIR=${CMAKE_BINARY_DIR}")
  endforeach()
endif()
