# --skeleton-names through Blender's own importers (included from roundtrip/tests.cmake).
#
#   skeleton_names.export.<model>_<fmt>_<names>  smpl-export --motion writes
#                       <build>/roundtrip/sn_<model>_<fmt>_<names>.<fmt>, names = smpl
#                       (the option given), plain (none), mixamo and ue5
#   skeleton_names.same.<model>_<fmt>   --skeleton-names smpl writes the bytes of no option
#   skeleton_names.schema.<model>_<fmt>_<names>  the sidecar conforms to
#                       docs/sidecar.schema.json (tests/conformance/check_schema.py --files)
#   skeleton_names.blender.<model>_<fmt>_<names>  headless Blender imports the plain and
#                       the renamed file: bones by the table, the evaluated mesh (FBX,
#                       GLB) or every joint (BVH) at 3 frames within 1e-5 m
#                       (blender_skeleton_names.py)
#
# Blender is required: when missing the tests fail, they never skip.

# smpl_skeleton_names_case(<model> <motion> <fmt>)
function(smpl_skeleton_names_case model motion fmt)
  if(model STREQUAL "builtin")
    set(model_arg builtin)
  else()
    set(model_arg ${SMPL_FIXTURE_DIR}/models/${model}.npz)
  endif()
  set(base ${SMPL_ROUNDTRIP_DIR}/sn_${model}_${fmt})
  foreach(names plain smpl mixamo ue5)
    set(names_args)
    if(NOT names STREQUAL "plain")
      set(names_args --skeleton-names ${names})
    endif()
    add_test(NAME skeleton_names.export.${model}_${fmt}_${names}
      COMMAND smpl-export --model ${model_arg} --motion ${SMPL_FIXTURE_DIR}/motions/${motion}.npz
              ${names_args} --out ${base}_${names}.${fmt} --quiet)
    set_tests_properties(skeleton_names.export.${model}_${fmt}_${names} PROPERTIES
      FIXTURES_SETUP sn_${model}_${fmt}_${names} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
    add_test(NAME skeleton_names.schema.${model}_${fmt}_${names}
      COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/tests/conformance/check_schema.py
              ${PROJECT_SOURCE_DIR}/docs/sidecar.schema.json --files ${base}_${names}.${fmt}.smpl.json)
    set_tests_properties(skeleton_names.schema.${model}_${fmt}_${names} PROPERTIES
      FIXTURES_REQUIRED sn_${model}_${fmt}_${names} LABELS blender)
  endforeach()
  add_test(NAME skeleton_names.same.${model}_${fmt}
    COMMAND ${CMAKE_COMMAND} -E compare_files ${base}_plain.${fmt} ${base}_smpl.${fmt})
  set_tests_properties(skeleton_names.same.${model}_${fmt} PROPERTIES
    FIXTURES_REQUIRED "sn_${model}_${fmt}_plain;sn_${model}_${fmt}_smpl" LABELS blender)
  foreach(names mixamo ue5)
    add_test(NAME skeleton_names.blender.${model}_${fmt}_${names}
      COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_skeleton_names.py --
              --plain ${base}_plain.${fmt} --renamed ${base}_${names}.${fmt} --names ${names}
              --tol 1e-5 --label ${model}_${fmt}_${names})
    set_tests_properties(skeleton_names.blender.${model}_${fmt}_${names} PROPERTIES
      FIXTURES_REQUIRED "sn_${model}_${fmt}_plain;sn_${model}_${fmt}_${names};roundtrip_dir"
      LABELS blender TIMEOUT 600)
  endforeach()
endfunction()

# The built-in SMPL body with an SMPL-H motion (fingers dropped), and SMPL-X with
# its fingers, jaw and eyes (the joints without a Mixamo/UE5 bone keep their names).
foreach(fmt fbx bvh glb)
  smpl_skeleton_names_case(builtin amass_smplh ${fmt})
  smpl_skeleton_names_case(smplx_small amass_smplx ${fmt})
endforeach()
