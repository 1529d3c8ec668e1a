# The FBX writer's own Blender import check on a synthetic asset (5 joints,
# 3 morph targets, a 10-frame clip): unit_tests writes the files, Blender
# checks bones, weights, shape keys, units, up axis and animation.
add_test(NAME fbx.write_roundtrip_inputs
  COMMAND unit_tests --gtest_filter=FbxWriter.WritesBlenderRoundTripInputs)
set_tests_properties(fbx.write_roundtrip_inputs PROPERTIES FIXTURES_SETUP fbx_synthetic LABELS blender)
foreach(name synthetic synthetic_cm synthetic_stored)  # stored: --fbx-compress-level 0
  add_test(NAME fbx.blender_import.${name}
    COMMAND ${SMPL_BLENDER_RUN} ${CMAKE_CURRENT_LIST_DIR}/blender_fbx_import_check.py --
            ${SMPL_FIXTURE_DIR}/fbx/${name}.fbx ${SMPL_FIXTURE_DIR}/fbx/synthetic.expect.json)
  set_tests_properties(fbx.blender_import.${name} PROPERTIES FIXTURES_REQUIRED fbx_synthetic LABELS blender)
endforeach()
