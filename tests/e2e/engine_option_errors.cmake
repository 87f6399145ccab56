# An engine name the tool does not know, and an engine model asked for with a proxy choice only
# the generic model has, are refused with one line naming the option and exit 2, before any
# work.
function(expect_refused expected)
  execute_process(COMMAND ${PROBEPROXY} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE stdout
    ERROR_VARIABLE stderr)
  if(NOT code EQUAL 2)
    message(FATAL_ERROR "'${ARGN}' exited ${code}, not 2: ${stderr}")
  endif()
  string(FIND "${stderr}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${ARGN}' said '${stderr}', not '${expected}'")
  endif()
endfunction()
set(names "expected one of generic, unity, unity-hdrp, unreal, godot3, godot4, bevy, eevee")
expect_refused("--engine: ${names}, got 'godot'" survey ${SCENE} --engine godot)
expect_refused("--engine: ${names}, got 'unreal5'" layout ${SCENE} --engine unity,unreal5
  --out ${OUT}/never)
expect_refused("option proxy: an engine model looks each probe up through the preset"
  survey ${SCENE} --engine unity --proxy aabb)
if(EXISTS ${OUT}/never)
  message(FATAL_ERROR "a refused layout wrote ${OUT}/never")
endif()
