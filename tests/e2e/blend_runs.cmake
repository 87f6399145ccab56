# `probeproxy blend` on the corridor between probes a and b: exit 0, the weights on stdout
# (JSON), every mip level of the mixed cube and the weight picture written, the same bytes
# twice.
foreach(run 1 2)
  file(REMOVE_RECURSE ${OUT}${run})
  execute_process(COMMAND ${PROBEPROXY} blend ${SCENE} --at -3.5,0.3,1.6
    --out ${OUT}${run}/mix_{face}.exr --weights-png ${OUT}${run}/weights.png --json
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "blend exited ${code}: ${err}")
  endif()
endforeach()
# x = -3.5 is the edge of corridor_a's inner range: it takes 100%.
string(JSON probe GET "${out}" weights 0 probe)
string(JSON weight GET "${out}" weights 0 weight)
string(JSON count LENGTH "${out}" weights)
if(NOT probe STREQUAL "corridor_a" OR NOT weight EQUAL 1 OR NOT count EQUAL 1)
  message(FATAL_ERROR "unexpected weights:\n${out}")
endif()
string(JSON levels GET "${out}" levels)
math(EXPR last "${levels} - 1")
foreach(f mix_px.exr mix_nz.exr mix_mip1_px.exr mix_mip${last}_nz.exr weights.png)
  if(NOT EXISTS ${OUT}1/${f})
    message(FATAL_ERROR "blend did not write ${f}")
  endif()
  file(SHA256 ${OUT}1/${f} a)
  file(SHA256 ${OUT}2/${f} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "blend output ${f} differs between two runs")
  endif()
endforeach()
