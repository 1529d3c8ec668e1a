# --corrective-basis K through Blender (included from roundtrip/tests.cmake,
# which defines SMPL_ROUNDTRIP_DIR, SMPL_BLENDER_RUN and the smpl-reference
# fixtures roundtrip_ref_<model>_m4 this file reuses).
#
#   basis.export.<case>    smpl-export --corrective-basis K writes <build>/roundtrip/basis_<case>.<fmt>,
#                          case = <model>_k<K>_<weights>_<fmt>
#   basis.blender.<case>   Blender imports it, poses it, drives the basis keys with
#                          smpl_correctives.apply and compares with numpy: rank-K
#                          posedirs (numpy's SVD) always within 1e-5 m, the full
#                          model within 1e-5 m when K = P; prints the error K costs.

# smpl_basis_case(<model> <K> <weights signed|unit> <format>)
function(smpl_basis_case name k weights format)
  set(model ${SMPL_FIXTURE_DIR}/models/${name}.npz)
  set(numpy_model --model ${model})
  if(name STREQUAL "builtin")
    set(model builtin)
    set(numpy_model)
  endif()
  set(case ${name}_k${k}_${weights}_${format})
  set(asset ${SMPL_ROUNDTRIP_DIR}/basis_${case}.${format})
  add_test(NAME basis.export.${case}
    COMMAND smpl-export --model ${model} --betas ${SMPL_RT_BETAS} --max-influences 4
            --corrective-basis ${k} --corrective-weights ${weights} --out ${asset} --quiet)
  add_test(NAME basis.blender.${case}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_basis.py --
            --asset ${asset} --addon-dir ${PROJECT_SOURCE_DIR}/blender
            --reference ${SMPL_ROUNDTRIP_DIR}/${name}_m4_ref --betas=${SMPL_RT_BETAS}
            --label ${name} --tol 1e-5 ${numpy_model})
  set_tests_properties(basis.export.${case} PROPERTIES
    FIXTURES_SETUP basis_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(basis.blender.${case} PROPERTIES
    FIXTURES_REQUIRED "basis_${case};roundtrip_ref_${name}_m4;roundtrip_dir" LABELS blender TIMEOUT 600)
endfunction()

foreach(name smpl_small builtin)
  smpl_basis_case(${name} 32 signed glb)
  smpl_basis_case(${name} 207 signed glb)
endforeach()
# Unit weights shift the base mesh by the offsets: through glTF and FBX.
smpl_basis_case(smpl_small 207 unit glb)
if(SMPL_ROUNDTRIP_FBX)
  smpl_basis_case(smpl_small 207 unit fbx)
  smpl_basis_case(builtin 32 unit fbx)
endif()
