# Unity runtime (unity/Runtime/*.cs) tested without Unity: compiled by mono's
# mcs with unity/Tests/*.cs (not Tests/Editor: the NUnit wrappers) against a
# hand-written stub of the UnityEngine types it uses, and run as a loader of
# the runtime conformance kit (tests/conformance/tests.cmake,
# docs/conformance.md): every case, the bad sidecars, and the component tests
# on the kit's Unity cases. Included from tests/CMakeLists.txt.

find_program(SMPL_MCS mcs)
find_program(SMPL_MONO mono)
set(SMPL_CSHARP_DIR ${CMAKE_CURRENT_BINARY_DIR}/csharp)

file(MAKE_DIRECTORY ${SMPL_CSHARP_DIR})

if(SMPL_MCS AND SMPL_MONO)
  file(GLOB SMPL_UNITY_RUNTIME CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/unity/Runtime/*.cs)
  file(GLOB SMPL_UNITY_TEST_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/unity/Tests/*.cs)
  set(SMPL_CSHARP_EXE ${SMPL_CSHARP_DIR}/SmplCorrectivesTests.exe)
  add_custom_command(OUTPUT ${SMPL_CSHARP_EXE}
    COMMAND ${SMPL_MCS} -nologo -warnaserror+ -optimize+ -define:SMPL_EXPORT_MONO_TESTS
            -out:${SMPL_CSHARP_EXE} ${CMAKE_CURRENT_LIST_DIR}/UnityEngineStub.cs ${CMAKE_CURRENT_LIST_DIR}/UnityAnimationStub.cs
            ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES}
    DEPENDS ${CMAKE_CURRENT_LIST_DIR}/UnityEngineStub.cs ${CMAKE_CURRENT_LIST_DIR}/UnityAnimationStub.cs
            ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES}
    COMMENT "Compiling the Unity runtime and its tests with mcs")
  add_custom_target(smpl-csharp-tests ALL DEPENDS ${SMPL_CSHARP_EXE})
  add_test(NAME unity_csharp COMMAND ${SMPL_MONO} ${SMPL_CSHARP_EXE} ${SMPL_CONFORMANCE_KIT})
  add_test(NAME unity_csharp.perturbed
    COMMAND ${SMPL_EXPECT_FAILURE} ${SMPL_MONO} ${SMPL_CSHARP_EXE} ${SMPL_CONFORMANCE_PERTURBED})
else()
  # A missing toolchain must show up as a failure, not as a silently absent test.
  add_test(NAME unity_csharp COMMAND ${CMAKE_COMMAND} -E false)
  add_test(NAME unity_csharp.perturbed COMMAND ${CMAKE_COMMAND} -E false)
  message(WARNING "mcs/mono not found: test unity_csharp will fail (apt-get install mono-mcs mono-runtime)")
endif()
set_tests_properties(unity_csharp PROPERTIES LABELS csharp FIXTURES_REQUIRED conformance_kit)
set_tests_properties(unity_csharp.perturbed PROPERTIES LABELS csharp FIXTURES_REQUIRED conformance_perturbed)

# The package's EditMode tests (unity/Tests/Editor), Editor code (unity/Editor)
# and sample (unity/Samples~) compiled by mcs against the UnityEngine,
# UnityEditor and NUnit stubs, and run by a small [Test] runner
# (EditModeRunner.cs) with the conformance kit ($SMPL_CONFORMANCE_KIT). Not
# Unity's Test Runner: no Unity on CI. Without -define:SMPL_EXPORT_MONO_TESTS
# (the console harness and benchmark are left out, as in Unity).
if(SMPL_MCS AND SMPL_MONO)
  file(GLOB SMPL_UNITY_EDITOR_SOURCES CONFIGURE_DEPENDS
       ${PROJECT_SOURCE_DIR}/unity/Editor/*.cs ${PROJECT_SOURCE_DIR}/unity/Tests/Editor/*.cs
       ${PROJECT_SOURCE_DIR}/unity/Samples~/Demo/*.cs)
  set(SMPL_EDITMODE_STUB_SOURCES ${CMAKE_CURRENT_LIST_DIR}/UnityEngineStub.cs ${CMAKE_CURRENT_LIST_DIR}/UnityAnimationStub.cs
      ${CMAKE_CURRENT_LIST_DIR}/UnityEditorStub.cs ${CMAKE_CURRENT_LIST_DIR}/EditModeRunner.cs
      ${CMAKE_CURRENT_LIST_DIR}/DemoTests.cs ${CMAKE_CURRENT_LIST_DIR}/HumanoidTests.cs)
  set(SMPL_EDITMODE_EXE ${SMPL_CSHARP_DIR}/SmplEditModeTests.exe)
  add_custom_command(OUTPUT ${SMPL_EDITMODE_EXE}
    COMMAND ${SMPL_MCS} -nologo -warnaserror+ -out:${SMPL_EDITMODE_EXE} -r:System.Core.dll
            ${SMPL_EDITMODE_STUB_SOURCES} ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES} ${SMPL_UNITY_EDITOR_SOURCES}
    DEPENDS ${SMPL_EDITMODE_STUB_SOURCES} ${SMPL_UNITY_RUNTIME} ${SMPL_UNITY_TEST_SOURCES} ${SMPL_UNITY_EDITOR_SOURCES}
    COMMENT "Compiling the Unity package's EditMode tests, Editor code and sample with mcs")
  add_custom_target(smpl-csharp-editmode ALL DEPENDS ${SMPL_EDITMODE_EXE})
  add_test(NAME unity_editmode_stub COMMAND ${SMPL_MONO} ${SMPL_EDITMODE_EXE} ${PROJECT_SOURCE_DIR}/unity)
else()
  add_test(NAME unity_editmode_stub COMMAND ${CMAKE_COMMAND} -E false)
endif()

# The bodies the Humanoid tests (HumanoidTests.cs, in the EditMode exe) read:
# the SMPL, SMPL-H and SMPL-X fixtures exported with default options.
set(SMPL_HUMANOID_DIR ${SMPL_CSHARP_DIR}/humanoid)
file(MAKE_DIRECTORY ${SMPL_HUMANOID_DIR})
foreach(kind smpl smplh smplx)
  add_test(NAME unity_humanoid_export.${kind}
    COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/${kind}_small.npz --out ${SMPL_HUMANOID_DIR}/${kind}.glb)
  set_tests_properties(unity_humanoid_export.${kind} PROPERTIES LABELS csharp FIXTURES_SETUP unity_humanoid_bodies)
endforeach()
# and SMPL-X with Mixamo's bone names (--skeleton-names mixamo): the avatar maps through bone_names
add_test(NAME unity_humanoid_export.smplx_mixamo
  COMMAND smpl-export --model ${SMPL_FIXTURE_DIR}/models/smplx_small.npz --skeleton-names mixamo
          --out ${SMPL_HUMANOID_DIR}/smplx_mixamo.glb)
set_tests_properties(unity_humanoid_export.smplx_mixamo PROPERTIES LABELS csharp FIXTURES_SETUP unity_humanoid_bodies)
set_tests_properties(unity_editmode_stub PROPERTIES LABELS csharp
  FIXTURES_REQUIRED "unity_humanoid_bodies;conformance_kit"
  ENVIRONMENT "SMPL_HUMANOID_DIR=${SMPL_HUMANOID_DIR};SMPL_CONFORMANCE_KIT=${SMPL_CONFORMANCE_KIT}")

# Every asset of the Unity package has its committed, current .meta file
# (scripts/unity-meta.py; Unity ignores assets without one in a git package).
add_test(NAME unity_meta_files COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/unity-meta.py --check
         ${PROJECT_SOURCE_DIR}/unity)
set_tests_properties(unity_meta_files PROPERTIES LABELS unit)
