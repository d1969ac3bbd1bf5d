# Every command's kinds of mistake against docs/cli.md's exit-code table: 2 for a
# wrong command line (the message names the flag or argument), 1 for work that
# failed (the message names the file or device), 0 for success.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P exit_codes.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${SOURCE_DIR}/scenes/whitted.json")
set(mesh "${SOURCE_DIR}/tests/data/meshes/cornell_box/CornellBox-Original.obj")
file(WRITE "${WORK_DIR}/odd.rays" "not a whole number of 32-byte records")
set(checked 0)

# expect(<exit code> <substring of stderr, or "" for none> <prism arguments...>)
function(expect code what)
  execute_process(COMMAND ${PRISM} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR "prism ${ARGN}: exited ${rc}, expected ${code}:\n${err}")
  endif()
  if(NOT what STREQUAL "")
    string(FIND "${err}" "${what}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "prism ${ARGN}: expected '${what}' in the message, got:\n${err}")
    endif()
  endif()
  if(code EQUAL 2)  # a usage error says how to get help
    string(FIND "${err}" "--help" help)
    if(help EQUAL -1)
      message(FATAL_ERROR "prism ${ARGN}: a usage error should point at --help:\n${err}")
    endif()
  endif()
  math(EXPR n "${checked} + 1")
  set(checked ${n} PARENT_SCOPE)
endfunction()

# Usage errors: 2.
expect(2 "no command given")
expect(2 "unknown command 'bogus'" bogus)
expect(2 "--x" plugins --x)
expect(2 "--frob" devices --frob)
expect(2 "expected one mesh file" info)
expect(2 "missing --rays" trace "${scene}")
expect(2 "expected one scene or mesh file" trace --rays x --hits y)
expect(2 "--accel: unknown structure 'kd'" trace "${scene}" --rays "${WORK_DIR}/odd.rays" --hits "${WORK_DIR}/h" --accel kd)
expect(2 "--max-depth: max_depth must be in 0..31" render "${scene}" -o "${WORK_DIR}/x.png" --max-depth 32)
expect(2 "--width: width must be in 1..32768, got 0" render "${scene}" -o "${WORK_DIR}/x.png" --width 0)
expect(2 "--aa-max-level" render "${scene}" -o "${WORK_DIR}/x.png" --aa-max-level 9)
# Work that failed: 1.
expect(1 "cannot open scene file" render "${WORK_DIR}/none.json" -o "${WORK_DIR}/x.png")
expect(1 "folder '${WORK_DIR}/no/dir' does not exist" render "${scene}" -o "${WORK_DIR}/no/dir/x.png")
expect(1 "device '99'" render "${scene}" -o "${WORK_DIR}/x.png" --device 99 --width 4 --height 3)
expect(1 "cannot read rays from" trace "${scene}" --rays "${WORK_DIR}/none.rays" --hits "${WORK_DIR}/h")
expect(1 "not a whole number of 32-byte rays" trace "${scene}" --rays "${WORK_DIR}/odd.rays" --hits "${WORK_DIR}/h")
expect(1 "cannot open" info "${WORK_DIR}/none.obj")
expect(1 "unknown mesh file extension '.json'" info "${scene}")
# Success: 0.
expect(0 "" info "${mesh}")
expect(0 "" plugins)
expect(0 "" render "${scene}" -o "${WORK_DIR}/x.png" --width 8 --height 6 --quiet)
# A number too small for float is the float it rounds to, not a mistake:
# --min-weight 1e-50 renders the very image of --min-weight 0.
expect(0 "" render "${scene}" -o "${WORK_DIR}/tiny.pfm" --width 8 --height 6 --quiet --min-weight 1e-50)
expect(0 "" render "${scene}" -o "${WORK_DIR}/zero.pfm" --width 8 --height 6 --quiet --min-weight 0)
file(SHA256 "${WORK_DIR}/tiny.pfm" tiny)
file(SHA256 "${WORK_DIR}/zero.pfm" zero)
if(NOT tiny STREQUAL zero)
  message(FATAL_ERROR "--min-weight 1e-50 and --min-weight 0 rendered different images")
endif()
message(STATUS "exit codes: ${checked} cases as docs/cli.md says")
