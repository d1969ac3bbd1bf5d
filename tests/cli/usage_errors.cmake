# Command-line mistakes exit with 2 and a message naming the option at fault. They are
# caught before the scene is read, so the scene path here need not exist.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P usage_errors.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${SOURCE_DIR}/scenes/whitted.json")
set(out "${WORK_DIR}/out.png")

# expect_usage_error(<substring of stderr> <prism arguments...>)
function(expect_usage_error what)
  execute_process(COMMAND ${PRISM} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr TIMEOUT 60)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "prism ${ARGN}: exited ${rc}, expected 2 (usage error):\n${stdout}${stderr}")
  endif()
  string(FIND "${stderr}" "prism: error: " at_prefix)
  string(FIND "${stderr}" "${what}" at)
  if(at_prefix EQUAL -1 OR at EQUAL -1)
    message(FATAL_ERROR "prism ${ARGN}: expected 'prism: error: ...${what}...' on stderr, got:\n${stderr}")
  endif()
endfunction()

expect_usage_error("-o" render "${scene}")
expect_usage_error("scene file" render -o "${out}")
expect_usage_error("--width" render "${scene}" -o "${out}" --width abc)
expect_usage_error("'abc'" render "${scene}" -o "${out}" --width abc)
expect_usage_error("--height" render "${scene}" -o "${out}" --height=12x)
expect_usage_error("--spp" render "${scene}" -o "${out}" --spp 0)
expect_usage_error("--spp" render "${scene}" -o "${out}" --spp -3)
expect_usage_error("--min-weight" render "${scene}" -o "${out}" --min-weight nan)
expect_usage_error("--seed" render "${scene}" -o "${out}" --seed 99999999999999999999999)
expect_usage_error("--max-depth needs a value" render "${scene}" -o "${out}" --max-depth)
expect_usage_error("--bogus" render "${scene}" -o "${out}" --bogus 3)
expect_usage_error("did you mean '--spp'" render "${scene}" -o "${out}" --sp 3)
expect_usage_error("--quiet takes no value" render "${scene}" -o "${out}" --quiet=yes)
expect_usage_error("--aov" render "${scene}" -o "${out}" --aov colour)
expect_usage_error("'.xyz'" render "${scene}" -o "${WORK_DIR}/out.xyz")
expect_usage_error("--frob" devices --frob)

file(GLOB left "${WORK_DIR}/*")
if(left)
  message(FATAL_ERROR "usage errors must write nothing, found: ${left}")
endif()
