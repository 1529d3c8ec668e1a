# Round-trip tests through real readers (included from tests/CMakeLists.txt).
#
#   roundtrip.export.<case>      smpl-export writes <build>/roundtrip/<case>.<ext>,
#                                case = <model>_m<M>_<format>, M = 4 and 8
#   roundtrip.reference.<model>_m<M>  smpl-reference writes the C++ forward pass
#   roundtrip.blender.<case>     headless Blender imports the asset, poses it with
#                                20 seeded poses, drives the correctives with the
#                                add-on and compares with the reference (1e-5 m)
#   roundtrip.validator          Khronos glTF validator on every exported GLB
#   blender.addon.*              the add-on alone, on GLBs written by numpy
#                                (synthetic_asset.py), and installed from its zip;
#                                blender.addon.ground: feet on ground and the timeline on import
#
# Blender and node are required: when missing the tests fail, they never skip.
# Labels: blender, validator.

set(SMPL_ROUNDTRIP_DIR ${CMAKE_BINARY_DIR}/roundtrip)
set(SMPL_ROUNDTRIP_SRC ${CMAKE_CURRENT_LIST_DIR})
find_program(SMPL_NODE node)
if(NOT SMPL_NODE)
  set(SMPL_NODE node)
endif()
option(SMPL_ROUNDTRIP_FBX "Also round-trip FBX output through Blender" ON)

# The Blender add-on zip (blender_addon, <build>/smpl_correctives.zip) is
# built by blender/CMakeLists.txt.

# smpl-reference (the C++ forward pass for seeded random poses) is built by
# tools/CMakeLists.txt.

# SMPL_BLENDER_RUN (headless Blender running a script) is set in tests/CMakeLists.txt.

# smpl_roundtrip_reference(<name> <model> <M> <betas>): the C++ forward pass
# for 20 seeded poses, shared by the formats. model: a fixture .npz (read by
# numpy in Blender too) or "builtin" (arrays dumped for numpy).
function(smpl_roundtrip_reference name model m betas)
  set(dump)
  if(model STREQUAL "builtin")
    set(dump --dump-model)
  endif()
  add_test(NAME roundtrip.reference.${name}_m${m}
    COMMAND smpl-reference --model ${model} --betas ${betas} --max-influences ${m}
            --poses 20 --seed 7 --out ${SMPL_ROUNDTRIP_DIR}/${name}_m${m}_ref ${dump})
  set_tests_properties(roundtrip.reference.${name}_m${m} PROPERTIES
    FIXTURES_SETUP roundtrip_ref_${name}_m${m} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
endfunction()

# smpl_roundtrip_case(<name> <format> <model> <M> <betas> [SUFFIX s] [TOL m] [DELTA_TOL m]
#                     [EXPORT_ARGS ...] [IMPORT_ARGS key=value ...] [SCRIPT_ARGS ...]): export, then Blender
# (IMPORT_ARGS go to Blender's importer, e.g. automatic_bone_orientation=True; TOL is the
# posed vertex tolerance, DELTA_TOL the decoded morph delta tolerance).
function(smpl_roundtrip_case name format model m betas)
  cmake_parse_arguments(RT "" "SUFFIX;TOL;DELTA_TOL" "EXPORT_ARGS;IMPORT_ARGS;SCRIPT_ARGS" ${ARGN})
  if(NOT RT_TOL)
    set(RT_TOL 1e-5)
  endif()
  if(NOT RT_DELTA_TOL)
    set(RT_DELTA_TOL 1e-6)
  endif()
  set(import_args)
  foreach(option ${RT_IMPORT_ARGS})
    list(APPEND import_args --import-option ${option})
  endforeach()
  set(case ${name}_m${m}_${format}${RT_SUFFIX})
  set(asset ${SMPL_ROUNDTRIP_DIR}/${case}.${format})
  set(numpy_model)
  if(NOT model STREQUAL "builtin")
    set(numpy_model --model ${model})
  endif()
  add_test(NAME roundtrip.export.${case}
    COMMAND smpl-export --model ${model} --betas ${betas} --max-influences ${m}
            --out ${asset} --quiet ${RT_EXPORT_ARGS})
  add_test(NAME roundtrip.blender.${case}
    COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_roundtrip.py --
            --asset ${asset} --addon-dir ${PROJECT_SOURCE_DIR}/blender
            --reference ${SMPL_ROUNDTRIP_DIR}/${name}_m${m}_ref
            --betas=${betas} --label ${name} --tol ${RT_TOL} --delta-tol ${RT_DELTA_TOL}
            ${numpy_model} ${import_args} ${RT_SCRIPT_ARGS})
  set_tests_properties(roundtrip.export.${case} PROPERTIES
    FIXTURES_SETUP roundtrip_${case} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
  set_tests_properties(roundtrip.blender.${case} PROPERTIES
    FIXTURES_REQUIRED "roundtrip_${case};roundtrip_ref_${name}_m${m};roundtrip_dir"
    LABELS blender TIMEOUT 600)
endfunction()

add_test(NAME roundtrip.mkdir COMMAND ${CMAKE_COMMAND} -E make_directory ${SMPL_ROUNDTRIP_DIR})
set_tests_properties(roundtrip.mkdir PROPERTIES FIXTURES_SETUP roundtrip_dir LABELS "blender;validator")

# M = 4 (engines' limit, lossy) and M = 8, the CLI's maximum, which keeps every
# influence of these models (at most 7 per vertex), so Blender must then match
# the unpruned model too.
set(SMPL_RT_MODELS smpl_small smplx_small builtin)
set(SMPL_RT_INFLUENCES 4 8)
set(SMPL_RT_BETAS "0.8,-0.5,0.3,1.2")
set(SMPL_RT_FORMATS glb)
if(SMPL_ROUNDTRIP_FBX)
  list(APPEND SMPL_RT_FORMATS fbx)
endif()
set(SMPL_RT_GLBS)
set(SMPL_RT_GLB_FIXTURES)
foreach(i RANGE 2)
  list(GET SMPL_RT_MODELS ${i} name)
  set(model ${SMPL_FIXTURE_DIR}/models/${name}.npz)
  if(name STREQUAL "builtin")
    set(model builtin)
  endif()
  foreach(m ${SMPL_RT_INFLUENCES})
    smpl_roundtrip_reference(${name} ${model} ${m} ${SMPL_RT_BETAS})
    foreach(format ${SMPL_RT_FORMATS})
      smpl_roundtrip_case(${name} ${format} ${model} ${m} ${SMPL_RT_BETAS})
      if(format STREQUAL "glb")
        list(APPEND SMPL_RT_GLBS ${SMPL_ROUNDTRIP_DIR}/${name}_m${m}_glb.glb)
        list(APPEND SMPL_RT_GLB_FIXTURES roundtrip_${name}_m${m}_glb)
      endif()
    endforeach()
  endforeach()
endforeach()

if(SMPL_ROUNDTRIP_FBX)
  # Centimetre FBX: the importer scales the armature object; C must not care.
  smpl_roundtrip_case(smpl_small fbx ${SMPL_FIXTURE_DIR}/models/smpl_small.npz 4
                      ${SMPL_RT_BETAS} SUFFIX _cm EXPORT_ARGS --fbx-units cm)
  # Bones re-oriented on import: the runtime formula must not care.
  foreach(name smpl_small smplx_small)
    smpl_roundtrip_case(${name} fbx ${SMPL_FIXTURE_DIR}/models/${name}.npz 8 ${SMPL_RT_BETAS}
                        SUFFIX _autobones IMPORT_ARGS automatic_bone_orientation=True)
  endforeach()
endif()
# --skeleton-names: the bones carry Mixamo / UE5 names; the add-on finds them through the
# metadata's bone_names and drives the correctives as with the model's names.
smpl_roundtrip_case(smplx_small glb ${SMPL_FIXTURE_DIR}/models/smplx_small.npz 8 ${SMPL_RT_BETAS}
                    SUFFIX _ue5 EXPORT_ARGS --skeleton-names ue5 SCRIPT_ARGS --skeleton-names ue5)
if(SMPL_ROUNDTRIP_FBX)
  smpl_roundtrip_case(smpl_small fbx ${SMPL_FIXTURE_DIR}/models/smpl_small.npz 4 ${SMPL_RT_BETAS}
                      SUFFIX _mixamo EXPORT_ARGS --skeleton-names mixamo SCRIPT_ARGS --skeleton-names mixamo)
endif()
# .gltf with its buffer in a separate .bin (the default) and embedded: both
# import in Blender and pass the validator.
smpl_roundtrip_case(smpl_small gltf ${SMPL_FIXTURE_DIR}/models/smpl_small.npz 4 ${SMPL_RT_BETAS})
smpl_roundtrip_case(smpl_small gltf ${SMPL_FIXTURE_DIR}/models/smpl_small.npz 4 ${SMPL_RT_BETAS}
                    SUFFIX _embed EXPORT_ARGS --gltf-embed)
list(APPEND SMPL_RT_GLBS ${SMPL_ROUNDTRIP_DIR}/smpl_small_m4_gltf.gltf ${SMPL_ROUNDTRIP_DIR}/smpl_small_m4_gltf_embed.gltf)
list(APPEND SMPL_RT_GLB_FIXTURES roundtrip_smpl_small_m4_gltf roundtrip_smpl_small_m4_gltf_embed)
foreach(heuristic TEMPERANCE FORTUNE)
  smpl_roundtrip_case(smplx_small glb ${SMPL_FIXTURE_DIR}/models/smplx_small.npz 8 ${SMPL_RT_BETAS}
                      SUFFIX _${heuristic} IMPORT_ARGS bone_heuristic=${heuristic})
endforeach()

# --- Khronos validator over every GLB the round trip writes (npm install is
# done beforehand by the CI script in tests/validator).
add_test(NAME roundtrip.validator
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js ${SMPL_RT_GLBS})
set_tests_properties(roundtrip.validator PROPERTIES
  FIXTURES_REQUIRED "${SMPL_RT_GLB_FIXTURES}" LABELS validator)

# --- the add-on alone, against GLBs written by numpy from the contract
foreach(joints 24 55)
  foreach(m 4 ${joints})
    set(stem ${SMPL_ROUNDTRIP_DIR}/synthetic_${joints})
    add_test(NAME blender.addon.synthetic_${joints}_m${m}.write
      COMMAND ${SMPL_SYSTEM_PYTHON} ${SMPL_ROUNDTRIP_SRC}/synthetic_asset.py ${SMPL_ROUNDTRIP_DIR}
              --joints ${joints} --max-influences ${m})
    add_test(NAME blender.addon.synthetic_${joints}_m${m}
      COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_roundtrip.py --
              --asset ${stem}_m${m}.glb --addon-dir ${PROJECT_SOURCE_DIR}/blender
              --model ${stem}_m${m}.npz --metadata-betas --label synthetic_${joints} --tol 1e-5)
    set_tests_properties(blender.addon.synthetic_${joints}_m${m}.write PROPERTIES
      FIXTURES_SETUP synthetic_${joints}_m${m} FIXTURES_REQUIRED roundtrip_dir LABELS blender)
    set_tests_properties(blender.addon.synthetic_${joints}_m${m} PROPERTIES
      FIXTURES_REQUIRED "synthetic_${joints}_m${m};roundtrip_dir" LABELS blender)
  endforeach()
endforeach()

# Installed from the zip: registration, the import operator, the frame-change
# handler with a keyframed action, disable.
add_test(NAME blender.addon.install
  COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${SMPL_ROUNDTRIP_DIR}/blender_user_scripts
          ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_addon_test.py --
          --zip ${SMPL_ADDON_ZIP} --asset ${SMPL_ROUNDTRIP_DIR}/synthetic_55_m55.glb
          --model ${SMPL_ROUNDTRIP_DIR}/synthetic_55_m55.npz)
set_tests_properties(blender.addon.install PROPERTIES
  FIXTURES_REQUIRED "synthetic_55_m55;roundtrip_dir" LABELS blender)
add_dependencies(smpl-reference blender_addon)  # the install test needs the zip built

# The import options "Feet on ground" and "Set timeline to clip"
# (blender_addon_ground.py): a 60-frame clip and a static body, the model's
# own weights (all influences, truncated = unchanged) so numpy is the reference.
set(SMPL_GROUND_COMMON --model ${SMPL_FIXTURE_DIR}/models/smpl_small.npz --max-influences all
    --skin-weights truncated --quiet)
add_test(NAME blender.addon.ground.export_anim
  COMMAND smpl-export ${SMPL_GROUND_COMMON} --motion ${SMPL_FIXTURE_DIR}/motions/smpl_72.npz
          --out ${SMPL_ROUNDTRIP_DIR}/ground_anim.glb)
add_test(NAME blender.addon.ground.export_static
  COMMAND smpl-export ${SMPL_GROUND_COMMON} --out ${SMPL_ROUNDTRIP_DIR}/ground_static.glb)
set_tests_properties(blender.addon.ground.export_anim blender.addon.ground.export_static PROPERTIES
  FIXTURES_SETUP addon_ground FIXTURES_REQUIRED roundtrip_dir LABELS blender)
add_test(NAME blender.addon.ground
  COMMAND ${SMPL_BLENDER_RUN} ${SMPL_ROUNDTRIP_SRC}/blender_addon_ground.py --
          --addon-dir ${PROJECT_SOURCE_DIR}/blender --model ${SMPL_FIXTURE_DIR}/models/smpl_small.npz
          --motion ${SMPL_FIXTURE_DIR}/motions/smpl_72.npz --asset ${SMPL_ROUNDTRIP_DIR}/ground_anim.glb
          --static ${SMPL_ROUNDTRIP_DIR}/ground_static.glb)
set_tests_properties(blender.addon.ground PROPERTIES
  FIXTURES_REQUIRED "addon_ground;roundtrip_dir" LABELS blender TIMEOUT 600)

# Baked animation (motions) through Blender and the validator; batch CLI.
include(${CMAKE_CURRENT_LIST_DIR}/anim_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/origin_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/compact_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/basis_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/dmpl_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/video_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/bvh_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/skeleton_names_tests.cmake)

# --- --max-influences all: every joint an influence (SMPL-X: 55, 14 JOINTS/WEIGHTS
# sets in glTF; FBX has no limit). Blender reads them all; the validator checks the GLB.
smpl_roundtrip_reference(smplx_small ${SMPL_FIXTURE_DIR}/models/smplx_small.npz all ${SMPL_RT_BETAS})
foreach(format ${SMPL_RT_FORMATS})
  smpl_roundtrip_case(smplx_small ${format} ${SMPL_FIXTURE_DIR}/models/smplx_small.npz all ${SMPL_RT_BETAS})
endforeach()
add_test(NAME roundtrip.validator.all_influences
  COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js
          ${SMPL_ROUNDTRIP_DIR}/smplx_small_mall_glb.glb)
set_tests_properties(roundtrip.validator.all_influences PROPERTIES
  FIXTURES_REQUIRED roundtrip_smplx_small_mall_glb LABELS validator)
