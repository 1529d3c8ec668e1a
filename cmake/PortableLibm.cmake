# smpl_libm: musl's libm with its symbols prefixed smpl_m_ (core/math/libm.h
# calls it), so that every build computes the same transcendental functions
# bit for bit (scripts/portable-libm.sh says why and how).
#   Linux: made at configure time from Debian's musl-dev (no download) into
#          <build>/libm.
#   Windows, WebAssembly: made by scripts/windows-deps.sh / wasm-deps.sh from Debian's musl source package
#          into SMPL_WIN_DEPS_PREFIX (found through the toolchain's root path).
if(WIN32 OR EMSCRIPTEN)
  find_library(SMPL_LIBM_LIBRARY smpl_m)
  find_path(SMPL_LIBM_INCLUDE_DIR smpl_m.h)
  if(NOT SMPL_LIBM_LIBRARY OR NOT SMPL_LIBM_INCLUDE_DIR)
    message(FATAL_ERROR "libsmpl_m.a not found: run scripts/windows-deps.sh (or wasm-deps.sh) "
                        "PREFIX and configure with its prefix (scripts/build-windows.sh, "
                        "build-wasm.sh do both)")
  endif()
else()
  set(_smpl_libm ${CMAKE_BINARY_DIR}/libm)
  execute_process(COMMAND ${PROJECT_SOURCE_DIR}/scripts/portable-libm.sh --target linux ${_smpl_libm}
                  RESULT_VARIABLE _smpl_libm_rc)
  if(NOT _smpl_libm_rc EQUAL 0)
    message(FATAL_ERROR "scripts/portable-libm.sh failed (Debian package musl-dev missing? "
                        "scripts/setup-deps.sh installs it)")
  endif()
  set(SMPL_LIBM_LIBRARY ${_smpl_libm}/lib/libsmpl_m.a)
  set(SMPL_LIBM_INCLUDE_DIR ${_smpl_libm}/include)
endif()
add_library(smpl_libm STATIC IMPORTED GLOBAL)
set_target_properties(smpl_libm PROPERTIES IMPORTED_LOCATION ${SMPL_LIBM_LIBRARY}
                      INTERFACE_INCLUDE_DIRECTORIES ${SMPL_LIBM_INCLUDE_DIR})
