# The runtime conformance kit (docs/conformance.md; included from
# tests/CMakeLists.txt, label unit). One generator, smpl-reference
# --conformance-kit, writes the cases at test time; every runtime's loader
# runs them against the manifest's one tolerance table, and runs once more on
# a kit with one wrong expected value, where it must fail (conformance.*.perturbed).
#   conformance.kit / .kit_perturbed   the kit and the perturbed kit (smpl_small fixture)
#   conformance.numpy                  the expected values recomputed with numpy/scipy
#   conformance.schema                 docs/sidecar.schema.json vs every sidecar of the kit
#   conformance.cpp                    the Unreal core and the exporter's baked weights
# The other runtimes' loaders are registered beside their tests
# (tests/runtimes/tests.cmake, tests/unity/tests.cmake, tests/web/CMakeLists.txt)
# with SMPL_CONFORMANCE_KIT and SMPL_CONFORMANCE_PERTURBED below.

set(SMPL_CONFORMANCE_KIT ${CMAKE_BINARY_DIR}/conformance/kit)
set(SMPL_CONFORMANCE_PERTURBED ${CMAKE_BINARY_DIR}/conformance/kit_perturbed)
set(SMPL_CONFORMANCE_MODEL ${SMPL_FIXTURE_DIR}/models/smpl_small.npz)
# The perturbed value and the line every loader must print for it.
set(SMPL_CONFORMANCE_PERTURB identity_rest.split:weights)
set(SMPL_CONFORMANCE_FAILURE "identity_rest[.]split.*weights")
set(SMPL_CONFORMANCE_DIR ${CMAKE_CURRENT_LIST_DIR})
set(SMPL_EXPECT_FAILURE ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/expect_failure.py
    ${SMPL_CONFORMANCE_FAILURE})
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/conformance)

add_test(NAME conformance.kit
  COMMAND smpl-reference --model ${SMPL_CONFORMANCE_MODEL} --conformance-kit ${SMPL_CONFORMANCE_KIT})
add_test(NAME conformance.kit_perturbed
  COMMAND smpl-reference --model ${SMPL_CONFORMANCE_MODEL} --conformance-kit ${SMPL_CONFORMANCE_PERTURBED}
          --perturb ${SMPL_CONFORMANCE_PERTURB})
set_tests_properties(conformance.kit PROPERTIES LABELS unit FIXTURES_SETUP conformance_kit)
set_tests_properties(conformance.kit_perturbed PROPERTIES LABELS unit FIXTURES_SETUP conformance_perturbed)

add_test(NAME conformance.numpy
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/kit_numpy_check.py ${SMPL_CONFORMANCE_KIT})
add_test(NAME conformance.schema
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_schema.py
          ${PROJECT_SOURCE_DIR}/docs/sidecar.schema.json ${SMPL_CONFORMANCE_KIT})
add_test(NAME conformance.numpy.perturbed
  COMMAND ${SMPL_EXPECT_FAILURE} ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/kit_numpy_check.py
          ${SMPL_CONFORMANCE_PERTURBED})
set_tests_properties(conformance.numpy conformance.schema PROPERTIES LABELS unit
  FIXTURES_REQUIRED conformance_kit)
set_tests_properties(conformance.numpy.perturbed PROPERTIES LABELS unit
  FIXTURES_REQUIRED conformance_perturbed)

add_executable(conformance_tests ${CMAKE_CURRENT_LIST_DIR}/conformance_test.cpp)
target_link_libraries(conformance_tests PRIVATE smpl_exporter smpl_models smpl_motions GTest::gtest_main)
add_dependencies(conformance_tests fixtures)
add_test(NAME conformance.cpp COMMAND conformance_tests)
add_test(NAME conformance.cpp.perturbed COMMAND ${SMPL_EXPECT_FAILURE} $<TARGET_FILE:conformance_tests>)
set_tests_properties(conformance.cpp PROPERTIES LABELS unit FIXTURES_REQUIRED conformance_kit
  ENVIRONMENT "SMPL_CONFORMANCE_KIT=${SMPL_CONFORMANCE_KIT};SMPL_CONFORMANCE_MODEL=${SMPL_CONFORMANCE_MODEL}")
set_tests_properties(conformance.cpp.perturbed PROPERTIES LABELS unit FIXTURES_REQUIRED conformance_perturbed
  ENVIRONMENT "SMPL_CONFORMANCE_KIT=${SMPL_CONFORMANCE_PERTURBED};SMPL_CONFORMANCE_MODEL=${SMPL_CONFORMANCE_MODEL}")
