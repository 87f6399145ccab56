# `survey --proxies` looks probes up through a build export's kept proxies: on a level whose
# proxies are `auto`, that is what `survey` builds by itself, so the figures agree (to the
# export's rounding).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROBEPROXY} build ${SCENE} --out ${OUT}
  RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE stderr)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "build exited ${code}: ${stderr}")
endif()
foreach(run built exported)
  set(extra)
  if(run STREQUAL exported)
    set(extra --proxies ${OUT}/proxies.json)
  endif()
  execute_process(COMMAND ${PROBEPROXY} survey ${SCENE} --json ${extra}
    RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "survey (${run}) exited ${code}: ${stderr}")
  endif()
  string(JSON p95_${run} GET "${stdout}" p95_deg)
  string(JSON over_${run} GET "${stdout}" over_tolerance_share)
endforeach()
if(NOT over_built STREQUAL over_exported)
  message(FATAL_ERROR "over_tolerance_share: built ${over_built}, exported ${over_exported}")
endif()
# p95 compared to 1e-6 degrees: the export rounds file-unit values at 1e-9.
string(SUBSTRING "${p95_built}" 0 8 a)
string(SUBSTRING "${p95_exported}" 0 8 b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "p95_deg: built ${p95_built}, exported ${p95_exported}")
endif()
