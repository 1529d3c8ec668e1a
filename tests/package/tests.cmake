# Packaging (packaging/CMakeLists.txt, scripts/release.sh): the generated man
# page and completions, the cmake --install tree of this build (label cli),
# and the static binary and its packages (label package). The static tests
# need a SMPL_STATIC=ON build beside this one (scripts/test.sh builds
# build-static and passes it); without one they fail, saying so.
set(SMPL_STATIC_BUILD_DIR "" CACHE PATH "A SMPL_STATIC=ON build whose binary and packages the package tests check")
add_test(NAME package.completions
  COMMAND ${SMPL_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/completions_test.py $<TARGET_FILE:smpl-export>
          ${CMAKE_BINARY_DIR}/completions ${CMAKE_BINARY_DIR}/man/smpl-export.1)
add_test(NAME package.install
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/install_test.sh ${CMAKE_BINARY_DIR} ${PROJECT_VERSION}
          ${CMAKE_CURRENT_BINARY_DIR}/package_install)
set_tests_properties(package.completions package.install PROPERTIES LABELS cli)
add_test(NAME package.static_chroot
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/static_chroot_test.sh ${SMPL_STATIC_BUILD_DIR}/cli/smpl-export
          $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/package_static_chroot)
add_test(NAME package.cpack
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/cpack_test.sh ${SMPL_STATIC_BUILD_DIR} $<TARGET_FILE:smpl-export>
          ${PROJECT_VERSION} ${CMAKE_CURRENT_BINARY_DIR}/package_cpack)
set_tests_properties(package.static_chroot package.cpack PROPERTIES LABELS package)
# The Windows build (scripts/build-windows.sh) under wine against this build.
set(SMPL_WINDOWS_BUILD_DIR "" CACHE PATH "A Windows (mingw-w64) build whose smpl-export.exe the wine test runs")
add_test(NAME package.windows_wine
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/windows_wine_test.sh ${SMPL_WINDOWS_BUILD_DIR}/cli/smpl-export.exe
          $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/package_windows_wine
          ${CMAKE_BINARY_DIR}/wineprefix)
set_tests_properties(package.windows_wine PROPERTIES LABELS package)
# The WebAssembly build (scripts/build-wasm.sh) with node against this build.
find_program(SMPL_PACKAGE_NODE node)
if(NOT SMPL_PACKAGE_NODE)
  set(SMPL_PACKAGE_NODE node)  # the tests then fail with "not found": no silent skip
endif()
set(SMPL_WASM_BUILD_DIR "" CACHE PATH "A WebAssembly (emscripten) build whose smpl-export.js the node test runs")
add_test(NAME package.wasm_node
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/wasm_node_test.sh ${SMPL_WASM_BUILD_DIR}/npm/bin/smpl-export.js
          $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/package_wasm_node)
set_tests_properties(package.wasm_node PROPERTIES LABELS package)
# The JS API (exportAsset on in-memory files) of the same npm package, in node.
add_test(NAME package.wasm_api
  COMMAND ${SMPL_PACKAGE_NODE} ${CMAKE_CURRENT_LIST_DIR}/wasm_api_test.mjs ${SMPL_WASM_BUILD_DIR}/npm
          $<TARGET_FILE:smpl-export> ${SMPL_FIXTURE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/package_wasm_api)
set_tests_properties(package.wasm_api PROPERTIES LABELS package)
# The viewer's convert panel in headless Chromium with the same npm package.
find_program(SMPL_PACKAGE_CHROMIUM NAMES chromium chromium-browser)
if(NOT SMPL_PACKAGE_CHROMIUM)
  set(SMPL_PACKAGE_CHROMIUM /usr/bin/chromium)  # the test then fails: no silent skip
endif()
add_test(NAME package.wasm_browser
  COMMAND ${SMPL_PACKAGE_NODE} ${CMAKE_CURRENT_LIST_DIR}/wasm_browser_test.mjs --chromium ${SMPL_PACKAGE_CHROMIUM}
          --npm ${SMPL_WASM_BUILD_DIR}/npm --native $<TARGET_FILE:smpl-export> --fixtures ${SMPL_FIXTURE_DIR}
          --work ${CMAKE_CURRENT_BINARY_DIR}/package_wasm_browser)
set_tests_properties(package.wasm_browser PROPERTIES LABELS package TIMEOUT 300)
