# Fetches the corpus (cached) and writes its scenes; fails the fixture if either step fails.
execute_process(COMMAND ${FETCH} ${BUILD_DIR} OUTPUT_VARIABLE data RESULT_VARIABLE rc
  OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fetch_nexuiz.sh failed (${rc})")
endif()
foreach(set tuning validation)
  set(folder ${BUILD_DIR}/corpus/scenes)
  if(set STREQUAL validation)
    set(folder ${BUILD_DIR}/corpus/validation)
  endif()
  execute_process(COMMAND /usr/bin/python3 ${WRITE} ${PROBEPROXY} ${data}/data.pk3 ${folder}
    --set ${set} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "write_scenes.py --set ${set} failed (${rc})")
  endif()
endforeach()
