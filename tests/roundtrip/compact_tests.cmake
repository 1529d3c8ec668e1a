# Compact glTF encodings: the CLI writes the builtin
# body and smpl_small.npz with each encoding (--corrective-epsilon, sparse;
# --quantize-morphs, KHR_mesh_quantization; --draco, KHR_draco_mesh_compression;
# all three; --meshopt, EXT_meshopt_compression, static and with a motion; the
# three --preset bundles with a motion: quantised animation keys), then the Khronos validator checks every file (no errors, no
# warnings). Included from tests.cmake; uses its SMPL_ROUNDTRIP_DIR and SMPL_NODE.
set(SMPL_COMPACT_GLBS)
set(SMPL_COMPACT_FIXTURES)
foreach(name builtin smpl_small)
  set(model ${SMPL_FIXTURE_DIR}/models/${name}.npz)
  if(name STREQUAL "builtin")
    set(model builtin)
  endif()
  set(motion ${SMPL_FIXTURE_DIR}/motions/amass_smplh.npz)
  foreach(encoding sparse quantized draco all meshopt meshopt_anim web engine archive)
    if(encoding STREQUAL "sparse")
      set(args --corrective-epsilon 1e-4)
    elseif(encoding STREQUAL "quantized")
      set(args --quantize-morphs)
    elseif(encoding STREQUAL "draco")
      set(args --draco)
    elseif(encoding STREQUAL "meshopt")
      set(args --meshopt)
    elseif(encoding STREQUAL "meshopt_anim")  # float keys, meshopt-compressed
      set(args --meshopt --motion ${motion})
    elseif(encoding MATCHES "^(web|engine|archive)$")  # the presets, with quantised keys
      set(args --preset ${encoding} --motion ${motion})
    else()
      set(args --corrective-epsilon 1e-5 --quantize-morphs --draco)
    endif()
    set(case compact_${name}_${encoding})
    add_test(NAME roundtrip.export.${case}
      COMMAND smpl-export --model ${model} --betas ${SMPL_RT_BETAS} --out ${SMPL_ROUNDTRIP_DIR}/${case}.glb
              --quiet ${args})
    set_tests_properties(roundtrip.export.${case} PROPERTIES
      FIXTURES_SETUP roundtrip_${case} FIXTURES_REQUIRED roundtrip_dir LABELS validator)
    list(APPEND SMPL_COMPACT_GLBS ${SMPL_ROUNDTRIP_DIR}/${case}.glb)
    list(APPEND SMPL_COMPACT_FIXTURES roundtrip_${case})
  endforeach()
endforeach()
add_test(NAME roundtrip.validator.compact
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_COMPACT_GLBS})
set_tests_properties(roundtrip.validator.compact PROPERTIES
  FIXTURES_REQUIRED "${SMPL_COMPACT_FIXTURES}" LABELS validator)

# Blender 3.4 reads sparse accessors and KHR_mesh_quantization (not Draco: the
# Debian build lacks Blender's draco library). Tolerances: quantized deltas are
# within s_n/65534 of posedirs (s_n = the target's largest component), sparse
# ones within epsilon; posed vertices within 5e-5 m (the summed effect over all
# targets at these poses; measured values are printed).
foreach(name builtin smpl_small)
  set(model ${SMPL_FIXTURE_DIR}/models/${name}.npz)
  if(name STREQUAL "builtin")
    set(model builtin)
  endif()
  smpl_roundtrip_case(${name} glb ${model} 8 ${SMPL_RT_BETAS} SUFFIX _quantized
                      TOL 5e-5 DELTA_TOL 1e-6 EXPORT_ARGS --quantize-morphs)
  smpl_roundtrip_case(${name} glb ${model} 8 ${SMPL_RT_BETAS} SUFFIX _sparse
                      TOL 5e-5 DELTA_TOL 1.1e-5 EXPORT_ARGS --corrective-epsilon 1e-5)
endforeach()
