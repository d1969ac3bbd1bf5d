# Renders the Whitted example small: the colour image to PNG and the depth AOV to EXR
# succeed and write real files; the depth AOV to PNG is refused before rendering.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P render_png.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${SOURCE_DIR}/scenes/whitted.json")
set(size --width 64 --height 36)

function(run_prism)
  execute_process(COMMAND ${PRISM} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# expect_magic(<file> <hex of its first bytes>)
function(expect_magic file magic)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
  string(LENGTH "${magic}" hex_length)
  math(EXPR byte_count "${hex_length} / 2")
  file(READ "${file}" head LIMIT ${byte_count} HEX)
  if(NOT head STREQUAL magic)
    message(FATAL_ERROR "${file} starts with ${head}, expected ${magic}")
  endif()
endfunction()

run_prism(render "${scene}" -o "${WORK_DIR}/out.png" ${size} --quiet)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render to PNG exited ${rc}:\n${out}${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "--quiet must print nothing on stdout, got:\n${out}")
endif()
expect_magic("${WORK_DIR}/out.png" "89504e470d0a1a0a")

# Without --quiet, one summary line on stdout.
run_prism(render "${scene}" -o "${WORK_DIR}/depth.exr" ${size} --aov depth)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render of the depth AOV to EXR exited ${rc}:\n${out}${err}")
endif()
if(NOT out MATCHES "prism: rendered 64x36 at [0-9]+ spp on '.+' with (bvh|octree|bsp|none) \\(built in .* s\\) in .* primary, .* shadow rays, .* Mrays/s -> .*depth\\.exr")
  message(FATAL_ERROR "unexpected summary line:\n${out}")
endif()
expect_magic("${WORK_DIR}/depth.exr" "762f3101")

# Quincunx: (64+1)(36+1) + 64*36 = 4709 primary rays, 2.044 per pixel, through the
# first-hit pass (--first-hit zbuffer; auto traces this scene, whose plane the
# Z-buffer would test at every sample) or traced (--first-hit trace); the summary says so.
run_prism(render "${scene}" -o "${WORK_DIR}/quincunx.png" ${size} --aa quincunx --first-hit zbuffer)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "quincunx render exited ${rc}:\n${out}${err}")
endif()
if(NOT out MATCHES "aa quincunx \\(tent\\), 2\\.044 rays/pixel, first hit by zbuffer, shadows by accel, set-up [0-9.]+ s, tracing [0-9.]+ s; 4709 primary, ")
  message(FATAL_ERROR "unexpected quincunx summary line:\n${out}")
endif()
expect_magic("${WORK_DIR}/quincunx.png" "89504e470d0a1a0a")
run_prism(render "${scene}" -o "${WORK_DIR}/jitter.png" ${size} --spp 4 --filter mitchell --first-hit trace)
if(NOT rc EQUAL 0 OR NOT out MATCHES "aa jitter, mitchell filter, 4\\.000 rays/pixel, first hit by trace, shadows by accel, set-up [0-9.]+ s, tracing [0-9.]+ s; 9216 primary, ")
  message(FATAL_ERROR "jitter render exited ${rc} with an unexpected summary line:\n${out}${err}")
endif()

# --stats: the stages, then one row per kernel that ran (shade always does) and the rest.
run_prism(render "${scene}" -o "${WORK_DIR}/stats.png" ${size} --stats)
if(NOT rc EQUAL 0 OR NOT out MATCHES "prism: stages: set-up [0-9.]+ s \\(kernels built or loaded [0-9.]+ s, (bvh|octree|bsp|none) built [0-9.]+ s\\), tracing [0-9.]+ s"
   OR NOT out MATCHES "\n  shade +[0-9]+ +[0-9.]+ +[0-9.]+%" OR NOT out MATCHES "\n  other +[0-9.]+ +[0-9.]+%")
  message(FATAL_ERROR "--stats exited ${rc} or printed no stage table:\n${out}${err}")
endif()

# --check-nan on a plain scene: nothing found, said so, exit 0.
run_prism(render "${scene}" -o "${WORK_DIR}/checked.png" ${size} --check-nan --quiet)
if(NOT rc EQUAL 0 OR NOT err MATCHES "check-nan: every contribution and pixel is finite")
  message(FATAL_ERROR "--check-nan on a plain scene exited ${rc}:\n${out}${err}")
endif()

run_prism(render "${scene}" -o "${WORK_DIR}/depth.png" ${size} --aov depth --quiet)
if(rc EQUAL 0)
  message(FATAL_ERROR "the depth AOV to PNG must be refused, but prism exited 0")
endif()
string(FIND "${err}" "depth" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the refusal should explain why (depth needs a float format), got:\n${err}")
endif()
if(EXISTS "${WORK_DIR}/depth.png")
  message(FATAL_ERROR "a refused render wrote ${WORK_DIR}/depth.png")
endif()
