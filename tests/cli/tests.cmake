add_test(NAME cli_behaviour
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/cli_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli_behaviour PROPERTIES LABELS cli)
add_test(NAME cli_released_layouts
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/released_layouts_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli_released_layouts PROPERTIES LABELS cli)

# Nothing a motion file carries is dropped silently (docs/motions.md "What a reader does not
# read"): every exportable motion fixture, with an extra_hand_pose array added, must export with
# a note naming it.
add_test(NAME cli.ignored_keys_walk
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/ignored_keys_walk.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --work ${CMAKE_CURRENT_BINARY_DIR}/ignored_keys_walk)
set_tests_properties(cli.ignored_keys_walk PROPERTIES LABELS cli)

add_test(NAME cli.motion_formats
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/motion_formats_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.motion_formats PROPERTIES LABELS cli)

add_test(NAME cli.dmpl
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/dmpl_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.dmpl PROPERTIES LABELS cli)

add_test(NAME cli.bvh
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/bvh_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.bvh PROPERTIES LABELS cli)

# Every smpl-export example of the README and the docs pages (samples/run.py: the
# README's former sections and every `<!-- runnable -->` block), run on synthetic files,
# and proof that the run fails when a README example or a runnable docs command breaks.
add_test(NAME cli.readme_samples
  COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/samples/run.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --work ${CMAKE_CURRENT_BINARY_DIR}/readme_samples)
add_test(NAME cli.readme_samples_detect_breakage
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/readme_samples_breakage_test.sh ${SMPL_SYSTEM_PYTHON}
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
add_test(NAME cli.docs_runnable_detect_breakage
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/docs_runnable_breakage_test.sh ${SMPL_SYSTEM_PYTHON}
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.readme_samples cli.readme_samples_detect_breakage cli.docs_runnable_detect_breakage
  PROPERTIES LABELS cli)

# Fitted skin weights checked by numpy (tests/roundtrip/skin_fit_check.py): the
# weights read from the exported GLB beat numpy's truncation on held-out poses
# (uniform +-0.6 rad). The fit trains on motion-like poses (core/math/motion_poses.h),
# not on this distribution: 27% lower mean and 58% lower max here, so the mean
# gain asked is 20% (it was 30% while the fit trained on uniform poses).
set(SMPL_SKIN_FIT_DIR ${CMAKE_BINARY_DIR})
foreach(method optimized truncated)
  add_test(NAME cli.skin_fit.${method}.export
    COMMAND $<TARGET_FILE:smpl-export>
            --model ${SMPL_FIXTURE_DIR}/models/smpl_small.npz --betas 0.8,-0.5,0.3,1.2
            --skin-weights ${method} --out ${SMPL_SKIN_FIT_DIR}/skin_fit_smpl_small_${method}.glb --quiet)
  add_test(NAME cli.skin_fit.${method}
    COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/roundtrip/skin_fit_check.py
            ${SMPL_FIXTURE_DIR}/models/smpl_small.npz ${SMPL_SKIN_FIT_DIR}/skin_fit_smpl_small_${method}.glb
            --betas 0.8,-0.5,0.3,1.2 --expect ${method} --min-gain 0.2)
  set_tests_properties(cli.skin_fit.${method}.export PROPERTIES LABELS cli FIXTURES_SETUP skin_fit_${method})
  set_tests_properties(cli.skin_fit.${method} PROPERTIES LABELS cli FIXTURES_REQUIRED skin_fit_${method})
endforeach()

# --origin floor and --root-bone on a static export, checked by numpy against the
# model's math (tests/roundtrip/origin_check.py): the lowest rest vertex at y = 0,
# the shape otherwise unchanged, the root bone on the floor below the pelvis.
foreach(variant floor root)
  set(extra)
  if(variant STREQUAL "root")
    set(extra --root-bone)
  endif()
  set(asset ${SMPL_SKIN_FIT_DIR}/origin_smpl_small_${variant}.glb)
  add_test(NAME cli.origin.${variant}.export
    COMMAND $<TARGET_FILE:smpl-export> --model ${SMPL_FIXTURE_DIR}/models/smpl_small.npz
            --betas 0.8,-0.5,0.3,1.2 --uv none --origin floor ${extra} --out ${asset} --quiet)
  add_test(NAME cli.origin.${variant}
    COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/roundtrip/origin_check.py
            ${SMPL_FIXTURE_DIR}/models/smpl_small.npz ${asset} --betas 0.8,-0.5,0.3,1.2 ${extra})
  set_tests_properties(cli.origin.${variant}.export PROPERTIES LABELS cli FIXTURES_SETUP origin_${variant})
  set_tests_properties(cli.origin.${variant} PROPERTIES LABELS cli FIXTURES_REQUIRED origin_${variant})
endforeach()

# The README's option table and docs/cli.md agree with --help (cli/options.cpp).
add_test(NAME cli.docs
  COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/check-cli-docs.py $<TARGET_FILE:smpl-export>
  ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.docs PROPERTIES LABELS cli)

# Motion layouts of today's tools (tests/cli/layouts, docs/motions.md): the numpy references of
# the video-to-motion cases checked through today's exporter, each clip written in our own terms
# (AMASS-style npz, turned Y up) and played by three.js (node, web/node_modules) against the
# reference at 1e-6 m.
add_test(NAME cli.layouts.video_equivalent
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/layouts/run_cases.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --web-src ${PROJECT_SOURCE_DIR}/tests/web --cases video --equivalent
          --work ${CMAKE_CURRENT_BINARY_DIR}/layouts_video_equivalent)
set_tests_properties(cli.layouts.video_equivalent PROPERTIES LABELS web)
# The video cases through the layout decoders (WHAM, VIBE, PHALP, GVHMR, TRAM, ROMP/BEV, EasyMocap,
# SMPLer-X): exports, notes, refusals, the sidecar's clip source, three.js vs numpy at 1e-6 m.
add_test(NAME cli.layouts.video
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/layouts/run_cases.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --web-src ${PROJECT_SOURCE_DIR}/tests/web --cases video
          --work ${CMAKE_CURRENT_BINARY_DIR}/layouts_video)
set_tests_properties(cli.layouts.video PROPERTIES LABELS web)

# The motion-generation, hand and camera-frame layouts (docs/motions.md "Motion-generation
# tools, hand and camera-frame fits"): every case of tests/cli/layouts/generation_cases.py
# exported by the decoders and played by three.js against its numpy reference at 1e-6 m, and
# the same references through today's exporter (AMASS-style equivalents).
add_test(NAME cli.layouts.generation
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/layouts/run_cases.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --web-src ${PROJECT_SOURCE_DIR}/tests/web --cases generation
          --work ${CMAKE_CURRENT_BINARY_DIR}/layouts_generation)
add_test(NAME cli.layouts.generation_equivalent
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/layouts/run_cases.py --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --web-src ${PROJECT_SOURCE_DIR}/tests/web --cases generation
          --equivalent --work ${CMAKE_CURRENT_BINARY_DIR}/layouts_generation_equivalent)
set_tests_properties(cli.layouts.generation cli.layouts.generation_equivalent PROPERTIES LABELS web)

# The README's `cmake --build build --target ...` commands work in a build configured as its
# quick start configures one (tools are defined even with the tests off): configure only.
add_test(NAME cli.readme_build_commands
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/readme_build_commands.py ${PROJECT_SOURCE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR} ${CMAKE_COMMAND})
set_tests_properties(cli.readme_build_commands PROPERTIES LABELS cli)

# smpl-skin-report --help prints its usage (not read as a model path); an unknown option is
# a usage error.
add_test(NAME cli.skin_report_help COMMAND $<TARGET_FILE:smpl-skin-report> --help)
set_tests_properties(cli.skin_report_help PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "^Usage: smpl-skin-report \\[--poses N\\] \\[--motion FILE \\[--stride S\\]\\] \\[MODEL \\.\\.\\.\\]")
add_test(NAME cli.skin_report_unknown_option COMMAND $<TARGET_FILE:smpl-skin-report> --bogus)
set_tests_properties(cli.skin_report_unknown_option PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "^Error in arguments: unknown option '--bogus'")

# samples/run.py as the README says to run it by hand: no --fixtures, so it writes its own
# fixtures with the scripts it lists (a script missing from its list fails here, not in CTest's
# cli.readme_samples, which reuses the build's fixtures).
add_test(NAME cli.readme_samples_by_hand
  COMMAND ${SMPL_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/samples/run.py --exe $<TARGET_FILE:smpl-export>
          --work ${CMAKE_CURRENT_BINARY_DIR}/readme_samples_by_hand)
set_tests_properties(cli.readme_samples_by_hand PROPERTIES LABELS cli TIMEOUT 900)

# Summary on stdout, notes and warnings on stderr, -q keeps warnings; batch [k/N] lines, ETA
# on a terminal, repeated notes folded with their count (tests/cli/output_streams_test.sh).
add_test(NAME cli.output_streams
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/output_streams_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR})
set_tests_properties(cli.output_streams PROPERTIES LABELS cli)

# --scene (docs/file-contract.md "Scene files"): every track of a multi-person file as one GLB,
# played by tests/cli/scene_check.py's own numpy glTF player and compared with the layouts' numpy
# forward pass (video_cases.py) where each body is present, hidden where absent, with the
# sensitivity checks (another track's betas, a one-frame shift); web.scene: three.js plays the
# same file; web.scene.babylon: Babylon.js; blender.scene: Blender's importer; validator.scene: the
# Khronos validator.
foreach(layout wham vibe phalp prompthmr mcs)
  add_test(NAME cli.scene.${layout}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_${layout})
  set_tests_properties(cli.scene.${layout} PROPERTIES LABELS cli)
endforeach()
# --skeleton-names on a scene: every body's skin carries the rig's bone names, and it plays as above.
foreach(case wham:mixamo prompthmr:ue5)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 layout)
  list(GET parts 1 names)
  add_test(NAME cli.scene.${layout}_${names}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --skeleton-names ${names}
            --work ${CMAKE_CURRENT_BINARY_DIR}/scene_${layout}_${names})
  set_tests_properties(cli.scene.${layout}_${names} PROPERTIES LABELS cli)
endforeach()
# PromptHMR (results.pkl and its world4d.mcs): two SMPL-X people and the moving camera (position, view
# direction, up) in every client.
foreach(layout wham prompthmr mcs)
  add_test(NAME web.scene.${layout}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_web_${layout}
            --web-src ${PROJECT_SOURCE_DIR}/tests/web)
  set_tests_properties(web.scene.${layout} PROPERTIES LABELS web)
endforeach()
# Babylon.js (web/'s devDependencies): the same expected file played by its glTF loader and AnimationGroup.
foreach(layout wham prompthmr)
  add_test(NAME web.scene.babylon.${layout}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_babylon_${layout}
            --babylon-src ${PROJECT_SOURCE_DIR}/tests/web)
  set_tests_properties(web.scene.babylon.${layout} PROPERTIES LABELS web)
endforeach()
foreach(layout wham prompthmr)
  add_test(NAME blender.scene.${layout}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_blender_${layout}
            --blender ${SMPL_BLENDER})
  set_tests_properties(blender.scene.${layout} PROPERTIES LABELS blender TIMEOUT 600)
endforeach()
# The same scenes written as FBX (--format fbx), read by Blender's FBX importer only: every body's
# evaluated mesh vs numpy where present, hidden where absent (PHALP: a gap), the camera's world
# matrix and vertical field of view, and the sensitivity checks (one frame later; the camera without
# the FBX +X/-Z axis correction).
foreach(layout prompthmr mcs phalp)
  add_test(NAME blender.scene.fbx.${layout}
    COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
            --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_blender_fbx_${layout}
            --format fbx --blender ${SMPL_BLENDER})
  set_tests_properties(blender.scene.fbx.${layout} PROPERTIES LABELS blender TIMEOUT 600)
endforeach()
# Godot 3.2 (Debian's godot3-server: the editor, headless): its glTF importer and AnimationPlayer
# (tests/cli/godot_scene.py); registered when a Godot binary is found.
if(SMPL_GODOT)
  foreach(layout prompthmr mcs)
    add_test(NAME godot.scene.${layout}
      COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_check.py --exe $<TARGET_FILE:smpl-export>
              --fixtures ${SMPL_FIXTURE_DIR} --layout ${layout} --work ${CMAKE_CURRENT_BINARY_DIR}/scene_godot_${layout}
              --godot ${SMPL_GODOT})
    set_tests_properties(godot.scene.${layout} PROPERTIES LABELS godot TIMEOUT 600)
  endforeach()
endif()
foreach(layout wham prompthmr)
  add_test(NAME validator.scene.${layout}
    COMMAND ${SMPL_NODE} ${PROJECT_SOURCE_DIR}/tests/validator/validate.js
            ${CMAKE_CURRENT_BINARY_DIR}/scene_${layout}/${layout}_scene.glb)
  set_tests_properties(validator.scene.${layout} PROPERTIES DEPENDS cli.scene.${layout} LABELS validator)
endforeach()
# The same bytes for any --threads count (GLB, FBX, BVH; with a motion; --preset web).
add_test(NAME cli.threads_determinism
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/threads_determinism_test.sh $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/threads_determinism ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.threads_determinism PROPERTIES LABELS cli)

# docs/batch.md's Slurm job array on a one-node Slurm (munge, slurmctld, slurmd on
# localhost in a temporary folder): the shards, one task cancelled midway and
# resubmitted, must write the one-process batch's bytes and manifest lines.
# Needs root (CI runs as root); not root, or no Slurm, is a failure, not a skip.
add_test(NAME batch.slurm
  COMMAND ${PROJECT_SOURCE_DIR}/scripts/slurm-test.sh --exe $<TARGET_FILE:smpl-export>
          --fixtures ${SMPL_FIXTURE_DIR} --docs ${PROJECT_SOURCE_DIR}/docs/batch.md)
set_tests_properties(batch.slurm PROPERTIES LABELS integration TIMEOUT 300)
