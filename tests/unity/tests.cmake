# Unity runtime (unity/Runtime/*.cs) tested without Unity: compiled by mono's
# mcs against a hand-written stub of the UnityEngine types it uses, and checked
# against features from the C++ reference (core/math/forward.h) for world rotations
# as Unity reports them. Included from tests/CMakeLists.txt.

add_executable(smpl-csharp-reference ${CMAKE_CURRENT_LIST_DIR}/csharp_reference.cpp)
target_link_libraries(smpl-csharp-reference PRIVATE smpl_exporter smpl_load)

find_program(SMPL_MCS mcs)
find_program(SMPL_MONO mono)
set(SMPL_CSHARP_DIR ${CMAKE_CURRENT_BINARY_DIR}/csharp)
set(SMPL_CSHARP_REFERENCE_JSON ${SMPL_CSHARP_DIR}/reference.json)
set(SMPL_CSHARP_MODELS ${SMPL_FIXTURE_DIR}/models/smpl_small.npz ${SMPL_FIXTURE_DIR}/models/smplx_small.npz)

file(MAKE_DIRECTORY ${SMPL_CSHARP_DIR})

add_test(NAME csharp_reference_data
  COMMAND $<TARGET_FILE:smpl-csharp-reference> ${SMPL_CSHARP_REFERENCE_JSON} ${SMPL_CSHARP_MODELS})
set_tests_properties(csharp_reference_data PROPERTIES LABELS csharp FIXTURES_SETUP csharp_reference)

if(SMPL_MCS AND SMPL_MONO)
  file(GLOB SMPL_UNITY_RUNTIME CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/unity/Runtime/*.cs)
  file(GLOB SMPL_UNITY_TEST_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/unity/Tests/*.cs)
  set(SMPL_CSHARP_EXE ${SMPL_CSHARP_DIR}/SmplCorrectivesTests.exe)
  add_custom_command(OUTPUT ${SMPL_CSHARP_EXE}
    COMMAND ${SMPL_MCS} -nologo -warnaserror+ -optimize+ -define:SMPL_EXPORT_MONO_TESTS
            -out:${SMPL_CSHARP_EXE} ${CMAKE_CURRENT_LIST_DIR}/UnityEngineStub.cs
            ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES}
    DEPENDS ${CMAKE_CURRENT_LIST_DIR}/UnityEngineStub.cs ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES}
    COMMENT "Compiling the Unity runtime and its tests with mcs")
  add_custom_target(smpl-csharp-tests ALL DEPENDS ${SMPL_CSHARP_EXE})
  add_test(NAME unity_csharp COMMAND ${SMPL_MONO} ${SMPL_CSHARP_EXE} ${SMPL_CSHARP_REFERENCE_JSON})
else()
  # A missing toolchain must show up as a failure, not as a silently absent test.
  add_test(NAME unity_csharp COMMAND ${CMAKE_COMMAND} -E false)
  message(WARNING "mcs/mono not found: test unity_csharp will fail (apt-get install mono-mcs mono-runtime)")
endif()
set_tests_properties(unity_csharp PROPERTIES LABELS csharp FIXTURES_REQUIRED csharp_reference)
