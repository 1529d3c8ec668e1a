# The runtimes' shared corrective cores and their engine glue, tested without
# the engines (included from tests/CMakeLists.txt; label unit):
#   runtime.reference        smpl-reference --dump-model on the smpl_small fixture
#   runtime.python_core      blender/smpl_correctives/core.py (Blender + Maya) vs the reference
#   runtime.maya_glue        the staged Maya package against a stand-in of maya.cmds/OpenMaya
#   runtime.*.conformance    the same as loaders of the conformance kit (+ .perturbed: must fail)
#   runtime.unreal_glue      the Unreal plugin's adapter compiled against stand-in UE types
# The C++ core itself (unreal/.../SmplCorrectivesCore.h) is tested in unit_tests
# (tests/unit/unreal/runtime_core_test.cpp, RuntimeCore.*).

set(SMPL_RUNTIME_DIR ${CMAKE_BINARY_DIR}/runtimes)
set(SMPL_RUNTIME_REF ${SMPL_RUNTIME_DIR}/smpl_small_ref)
file(MAKE_DIRECTORY ${SMPL_RUNTIME_DIR})

add_test(NAME runtime.reference
  COMMAND smpl-reference --model ${SMPL_FIXTURE_DIR}/models/smpl_small.npz --poses 6 --seed 3
          --dump-model --out ${SMPL_RUNTIME_REF})
set_tests_properties(runtime.reference PROPERTIES LABELS unit FIXTURES_SETUP runtime_reference)

add_test(NAME runtime.python_core
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/python_core_test.py
          --core ${PROJECT_SOURCE_DIR}/blender/smpl_correctives/core.py --reference ${SMPL_RUNTIME_REF})
add_test(NAME runtime.maya_glue
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/maya_glue_test.py
          --package ${SMPL_MAYA_DIR} --reference ${SMPL_RUNTIME_REF})
set_tests_properties(runtime.python_core runtime.maya_glue PROPERTIES
  LABELS unit FIXTURES_REQUIRED runtime_reference)

# The same two as loaders of the conformance kit (tests/conformance/tests.cmake,
# docs/conformance.md), and each on the perturbed kit, where it must fail.
set(SMPL_PYTHON_CORE_LOADER ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/python_core_conformance.py
    --core ${PROJECT_SOURCE_DIR}/blender/smpl_correctives/core.py --kit)
set(SMPL_MAYA_LOADER ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/maya_glue_conformance.py
    --package ${SMPL_MAYA_DIR} --kit)
add_test(NAME runtime.python_core.conformance COMMAND ${SMPL_PYTHON_CORE_LOADER} ${SMPL_CONFORMANCE_KIT})
add_test(NAME runtime.maya_glue.conformance COMMAND ${SMPL_MAYA_LOADER} ${SMPL_CONFORMANCE_KIT})
add_test(NAME runtime.python_core.conformance.perturbed
  COMMAND ${SMPL_EXPECT_FAILURE} ${SMPL_PYTHON_CORE_LOADER} ${SMPL_CONFORMANCE_PERTURBED})
add_test(NAME runtime.maya_glue.conformance.perturbed
  COMMAND ${SMPL_EXPECT_FAILURE} ${SMPL_MAYA_LOADER} ${SMPL_CONFORMANCE_PERTURBED})
set_tests_properties(runtime.python_core.conformance runtime.maya_glue.conformance PROPERTIES
  LABELS unit FIXTURES_REQUIRED conformance_kit)
set_tests_properties(runtime.python_core.conformance.perturbed runtime.maya_glue.conformance.perturbed
  PROPERTIES LABELS unit FIXTURES_REQUIRED conformance_perturbed)

# The Unreal plugin's glue sources compiled against stand-in Unreal headers
# (unreal_standin/: CoreMinimal.h, AnimNodeBase.h, ... with Unreal's names and
# call shapes) and run on a stand-in skeleton. Not the engine: unreal/README.md.
set(SMPL_UNREAL_SOURCE ${PROJECT_SOURCE_DIR}/unreal/SmplCorrectives/Source)
add_executable(unreal_standin_test ${CMAKE_CURRENT_LIST_DIR}/unreal_standin_test.cpp
  ${SMPL_UNREAL_SOURCE}/SmplCorrectives/Private/AnimNode_SmplCorrectives.cpp
  ${SMPL_UNREAL_SOURCE}/SmplCorrectives/Private/SmplCorrectivesModule.cpp
  ${SMPL_UNREAL_SOURCE}/SmplCorrectivesEditor/Private/AnimGraphNode_SmplCorrectives.cpp
  ${SMPL_UNREAL_SOURCE}/SmplCorrectivesEditor/Private/SmplCorrectivesEditorModule.cpp)
target_include_directories(unreal_standin_test PRIVATE ${CMAKE_CURRENT_LIST_DIR}/unreal_standin
  ${SMPL_UNREAL_SOURCE}/SmplCorrectives/Public ${SMPL_UNREAL_SOURCE}/SmplCorrectivesEditor/Public)
target_compile_definitions(unreal_standin_test PRIVATE SMPL_FIXTURE_DIR="${SMPL_FIXTURE_DIR}")
target_link_libraries(unreal_standin_test PRIVATE smpl_models smpl_motions GTest::gtest_main)
add_dependencies(unreal_standin_test fixtures)
add_test(NAME runtime.unreal_glue COMMAND unreal_standin_test)
set_tests_properties(runtime.unreal_glue PROPERTIES LABELS unit)
