# A scene file that does not exist: exit 1, a message naming the file, no output.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P missing_scene.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${WORK_DIR}/no-such-scene.json")

execute_process(COMMAND ${PRISM} render "${scene}" -o "${WORK_DIR}/out.png" --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "a missing scene exited ${rc}, expected 1:\n${out}${err}")
endif()
string(FIND "${err}" "prism: error: " at_prefix)
string(FIND "${err}" "no-such-scene.json" at_name)
if(at_prefix EQUAL -1 OR at_name EQUAL -1)
  message(FATAL_ERROR "expected 'prism: error: ...' naming no-such-scene.json, got:\n${err}")
endif()
file(GLOB left "${WORK_DIR}/*")
if(left)
  message(FATAL_ERROR "a failed render must write nothing, found: ${left}")
endif()
