# A film over the size limit is refused, with the limit in the user's terms,
# before the command line allocates the image (16 GiB for 32768 x 32768).
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P limits.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
# Under an 8 GiB address-space limit (a normal render fits in it), so an
# allocation of the image before the check would fail instead of passing slowly.
execute_process(COMMAND sh -c "ulimit -v 8388608 && exec \"$0\" \"$@\"" "${PRISM}"
                        render "${SOURCE_DIR}/scenes/whitted.json" -o "${WORK_DIR}/big.png"
                        --width 32768 --height 32768 --quiet
  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 60)
# A size the command line asked for is its mistake: exit 2, naming the flags.
if(NOT rc EQUAL 2 OR NOT err MATCHES "--width, --height: width x height must be at most 2\\^28 pixels")
  message(FATAL_ERROR "32768x32768: exited ${rc}, expected 2 naming the flags and the limit:\n${err}")
endif()
if(EXISTS "${WORK_DIR}/big.png")
  message(FATAL_ERROR "a refused render wrote an image")
endif()
