# scripts/bench_charts.py on a small bench.json: every chart appears as PNG and SVG, and two
# runs give byte-identical SVGs.
foreach(run 1 2)
  file(REMOVE_RECURSE ${OUT}${run})
  execute_process(COMMAND ${PYTHON} ${SCRIPT} ${FIXTURE} ${OUT}${run} --table
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "bench_charts.py exited ${code}: ${err}")
  endif()
endforeach()
foreach(chart l_room_error_vs_cost l_room_error_vs_planes tiny_closet_error_vs_cost
        tiny_closet_error_vs_planes summary)
  if(NOT EXISTS ${OUT}1/${chart}.png)
    message(FATAL_ERROR "no ${chart}.png")
  endif()
  file(SHA256 ${OUT}1/${chart}.svg a)
  file(SHA256 ${OUT}2/${chart}.svg b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${chart}.svg differs between two runs")
  endif()
endforeach()
