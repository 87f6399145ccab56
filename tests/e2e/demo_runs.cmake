# The demo runs, says what it did, writes the level, its scene and every depth cube face, and
# two runs give the same bytes.
foreach(run 1 2)
  file(REMOVE_RECURSE ${OUT}${run})
  execute_process(COMMAND ${PROBEPROXY} demo --out ${OUT}${run} --face-size 32
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "demo exited ${code}: ${err}")
  endif()
endforeach()
if(NOT out MATCHES "probe corridor_c: depth cube 32 px/face")
  message(FATAL_ERROR "demo did not report the third probe:\n${out}")
endif()
foreach(f corridor.obj corridor.scene.json depth/corridor_a_depth_px.exr depth/corridor_c_depth_nz.exr
        export/proxies.json export/proxies.glb)
  if(NOT EXISTS ${OUT}1/${f})
    message(FATAL_ERROR "demo did not write ${f}")
  endif()
  file(SHA256 ${OUT}1/${f} a)
  file(SHA256 ${OUT}2/${f} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "demo output ${f} differs between two runs")
  endif()
endforeach()
