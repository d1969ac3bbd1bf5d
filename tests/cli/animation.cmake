# prism render of an animation (scenes/animation.json, 12 frames): one file per
# frame, named by the frame number ("_NNNN" before the extension, or a run of
# '#' in -o); --frames K and A-B render only those, each the same bytes as in the
# whole run (PFM, whose bytes are the pixels); frames differ as the objects move;
# a frame past the last is a usage error (exit 2) before any render; a still
# keeps -o as it is.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P animation.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${SOURCE_DIR}/scenes/animation.json")
set(small --width 48 --height 36 --spp 2 --device 0)

function(run)
  execute_process(COMMAND ${PRISM} render "${scene}" ${small} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(same a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/${a}" "${WORK_DIR}/${b}" RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "${b} differs from ${a}")
  endif()
endfunction()

run(-o "${WORK_DIR}/all.pfm")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the whole animation exited ${rc}:\n${out}${err}")
endif()
string(REGEX MATCHALL "prism: rendered" summaries "${out}")
list(LENGTH summaries n)
if(NOT n EQUAL 12)
  message(FATAL_ERROR "expected a summary line for each of the 12 frames, got ${n}:\n${out}")
endif()
foreach(f 0000 0001 0005 0011)
  if(NOT EXISTS "${WORK_DIR}/all_${f}.pfm")
    message(FATAL_ERROR "frame ${f} was not written as all_${f}.pfm:\n${out}")
  endif()
endforeach()
if(EXISTS "${WORK_DIR}/all.pfm" OR EXISTS "${WORK_DIR}/all_0012.pfm")
  message(FATAL_ERROR "an animation of 12 frames must write all_0000.pfm to all_0011.pfm and nothing else")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/all_0000.pfm" "${WORK_DIR}/all_0011.pfm"
  RESULT_VARIABLE differ)
if(differ EQUAL 0)
  message(FATAL_ERROR "the first and last frames are the same image, though the objects move")
endif()

# One frame, and a range, named by a run of '#'.
run(-o "${WORK_DIR}/one_###.pfm" --frames 5 --quiet)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK_DIR}/one_005.pfm")
  message(FATAL_ERROR "--frames 5 -o one_###.pfm must write one_005.pfm (exit ${rc}):\n${err}")
endif()
same(all_0005.pfm one_005.pfm)
run(-o "${WORK_DIR}/range.pfm" --frames 10-11 --quiet)
if(NOT rc EQUAL 0 OR EXISTS "${WORK_DIR}/range_0009.pfm")
  message(FATAL_ERROR "--frames 10-11 must write frames 10 and 11 alone (exit ${rc}):\n${err}")
endif()
same(all_0010.pfm range_0010.pfm)
same(all_0011.pfm range_0011.pfm)

# Frames the animation does not have, and a range that is not one.
run(-o "${WORK_DIR}/past.pfm" --frames 11-12)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--frames: the scene has 12 frames \\(0 to 11\\), so 12 is not one of them")
  message(FATAL_ERROR "--frames 11-12: exited ${rc}, expected 2 with the frames the scene has:\n${err}")
endif()
run(-o "${WORK_DIR}/backwards.pfm" --frames 4-2)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--frames: the range 4-2 ends before it starts")
  message(FATAL_ERROR "--frames 4-2: exited ${rc}, expected 2:\n${err}")
endif()
file(GLOB stray "${WORK_DIR}/past*" "${WORK_DIR}/backwards*")
if(stray)
  message(FATAL_ERROR "a refused command line wrote ${stray}")
endif()

# A still keeps -o as it is, '#' and all.
execute_process(COMMAND ${PRISM} render "${SOURCE_DIR}/scenes/whitted.json" -o "${WORK_DIR}/still_#.pfm" ${small} --quiet
  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK_DIR}/still_#.pfm")
  message(FATAL_ERROR "a still must be written to -o as given, still_#.pfm (exit ${rc}):\n${err}")
endif()
