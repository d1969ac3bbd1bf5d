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
expect_usage_error("--aa: unknown mode 'supersample'" render "${scene}" -o "${out}" --aa supersample)
expect_usage_error("--filter: unknown filter 'lanczos'" render "${scene}" -o "${out}" --filter lanczos)
expect_usage_error("4 or 9" render "${scene}" -o "${out}" --aa grid --spp 5)
expect_usage_error("spp must be 1" render "${scene}" -o "${out}" --aa quincunx --spp 4)
# Ranges are the library's, named after the flag; the scene need not be read for them.
expect_usage_error("--max-depth: max_depth must be in 0..31, got 32" render "${WORK_DIR}/none.json" -o "${out}" --max-depth 32)
expect_usage_error("--width: width must be in 1..32768, got 0" render "${WORK_DIR}/none.json" -o "${out}" --width 0)
# Past int, but within the flag's uint32: the value given, not one clamped on the way.
expect_usage_error("--width: width must be in 1..32768, got 4294967295" render "${WORK_DIR}/none.json" -o "${out}"
                   --width 4294967295)
expect_usage_error("--spp: spp must be in 1..65536, got 2147483648" render "${WORK_DIR}/none.json" -o "${out}"
                   --spp 2147483648)
# A float's overflow is refused (its underflow is the number meant: exit_codes.cmake).
expect_usage_error("--camera-pos: expected three numbers" render "${scene}" -o "${out}" --camera-pos 1e39,0,0)
expect_usage_error("--min-weight" render "${scene}" -o "${out}" --min-weight 1e39)
# One that rounds to 0 where 0 is not allowed is refused quoting what was typed.
expect_usage_error("--focus-distance: expected a positive distance, got '1e-50'" render "${scene}" -o "${out}"
                   --focus-distance 1e-50)
expect_usage_error("--min-weight" render "${scene}" -o "${out}" --min-weight 2)
expect_usage_error("--spp, --aa: aa grid needs a square spp" render "${scene}" -o "${out}" --aa grid --spp 5)
expect_usage_error("--aa-max-level" render "${scene}" -o "${out}" --aa-max-level 9)
expect_usage_error("--aa-threshold" render "${scene}" -o "${out}" --aa-threshold -0.5)
expect_usage_error("--first-hit: unknown mode 'raster'" render "${scene}" -o "${out}" --first-hit raster)
# The camera flags are checked with the rest of the scene's camera, once the scene is read,
# by the library's camera check; a refusal names the flags given.
expect_usage_error("--camera-pos: camera: position must have coordinates of at most 1e15"
                   render "${scene}" -o "${out}" --camera-pos 3e38,0,0)
expect_usage_error("--camera-up: camera.up: expected a direction" render "${scene}" -o "${out}" --camera-up 0,0,0)
expect_usage_error("--aperture: camera: aperture" render "${scene}" -o "${out}" --aperture 1e20)
expect_usage_error("--camera-pos, --camera-look: camera.look_at: expected a point different"
                   render "${scene}" -o "${out}" --camera-pos 0,0,0 --camera-look 0,0,0)

file(GLOB left "${WORK_DIR}/*")
if(left)
  message(FATAL_ERROR "usage errors must write nothing, found: ${left}")
endif()
