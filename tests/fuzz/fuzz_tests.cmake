# The CTest label `fuzz`, in the main build: builds the fuzz tree with clang
# (scripts/fuzz.sh build, into <build>/fuzz), runs every input kept in tests/fuzz/regressions/
# once, then each target for a short fixed number of runs from a fixed seed. Longer runs:
# scripts/fuzz.sh all --seconds S. Skipped, with a message, where clang or libFuzzer is missing.
find_program(PROBEPROXY_CLANGXX clang++-14)
file(GLOB PROBEPROXY_LIBFUZZER /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a)
if(NOT PROBEPROXY_CLANGXX OR NOT PROBEPROXY_LIBFUZZER)
  message(STATUS "fuzz tests off: clang++-14 and libclang-rt-14-dev are needed (scripts/setup.sh installs them)")
  return()
endif()

set(fuzz_script ${PROJECT_SOURCE_DIR}/scripts/fuzz.sh)
set(fuzz_env PROBEPROXY_FUZZ_DIR=${CMAKE_BINARY_DIR}/fuzz PROBEPROXY_FUZZ_SEED=1)
add_test(NAME fuzz_build COMMAND ${CMAKE_COMMAND} -E env ${fuzz_env} ${fuzz_script} build)
set_tests_properties(fuzz_build PROPERTIES LABELS fuzz FIXTURES_SETUP fuzz_tree TIMEOUT 1800)
add_test(NAME fuzz_regressions COMMAND ${CMAKE_COMMAND} -E env ${fuzz_env} ${fuzz_script} regressions)
set_tests_properties(fuzz_regressions PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_tree)
foreach(target scene_file runtime_export bsp pk3 level_gltf level_glb level_obj level_ply level_off
               cubemap_image cubemap_faces candidate_wire proxy_build_wire)
  add_test(NAME fuzz_${target} COMMAND ${CMAKE_COMMAND} -E env ${fuzz_env} ${fuzz_script} run ${target} --runs 500)
  set_tests_properties(fuzz_${target} PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_tree TIMEOUT 300)
endforeach()
