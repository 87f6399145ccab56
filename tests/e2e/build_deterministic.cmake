# `probeproxy build` writes the same bytes on every run and for every thread count.
foreach(threads 1 2 0)
  set(out ${OUT}/threads${threads})
  file(REMOVE_RECURSE ${out})
  execute_process(COMMAND ${PROBEPROXY} build ${SCENE} --out ${out} --regenerate --threads ${threads}
                          --face-size 64 --samples 512
    RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "build --threads ${threads} exited ${code}: ${stderr}")
  endif()
  foreach(f proxies.json proxies.glb)
    if(NOT EXISTS ${out}/${f})
      message(FATAL_ERROR "build --threads ${threads} wrote no ${f}")
    endif()
    file(SHA256 ${out}/${f} hash_${threads}_${f})
  endforeach()
endforeach()
foreach(f proxies.json proxies.glb)
  if(NOT hash_1_${f} STREQUAL hash_2_${f} OR NOT hash_1_${f} STREQUAL hash_0_${f})
    message(FATAL_ERROR "${f} differs between thread counts")
  endif()
endforeach()
# A second run over the first run's output replaces our own files and gives the same bytes.
execute_process(COMMAND ${PROBEPROXY} build ${SCENE} --out ${OUT}/threads1 --regenerate --threads 1
                        --face-size 64 --samples 512 RESULT_VARIABLE code ERROR_VARIABLE stderr OUTPUT_QUIET)
file(SHA256 ${OUT}/threads1/proxies.json again)
if(NOT code EQUAL 0 OR NOT again STREQUAL hash_1_proxies.json)
  message(FATAL_ERROR "a second build gave other bytes (exit ${code}: ${stderr})")
endif()
