# One frame over several devices from the command line (issue 13), with three
# PoCL devices of one kind (POCL_DEVICES): 'prism devices' lists each, '--device
# all' and '--device 2,0' write the same image bit for bit as '--device 0' (PFM,
# whose bytes are the pixels), the summary names the devices and --stats shows
# each one's share; a device named twice is refused.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P devices.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${SOURCE_DIR}/scenes/whitted.json")
# 320x240 at 4 spp: 307,200 samples, five units of the sample sequence.
set(size --width 320 --height 240 --aa jitter --spp 4)

function(run_prism)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "POCL_DEVICES=pthread pthread pthread" ${PRISM} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

run_prism(devices)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\\[2\\] ")
  message(FATAL_ERROR "prism devices must list three devices (exit ${rc}):\n${out}${err}")
endif()

run_prism(render "${scene}" -o "${WORK_DIR}/one.pfm" ${size} --device 0 --quiet)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render on device 0 exited ${rc}:\n${out}${err}")
endif()

run_prism(render "${scene}" -o "${WORK_DIR}/all.pfm" ${size} --device all --stats)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render on all devices exited ${rc}:\n${out}${err}")
endif()
if(NOT out MATCHES "spp on 3 devices \\('[^']+', '[^']+', '[^']+'\\) with ")
  message(FATAL_ERROR "the summary must name the three devices:\n${out}")
endif()
if(NOT out MATCHES "units +samples +busy s" OR NOT out MATCHES "\\[2\\] ")
  message(FATAL_ERROR "--stats must show each device's share:\n${out}")
endif()

run_prism(render "${scene}" -o "${WORK_DIR}/list.pfm" ${size} --device 2,0 --quiet)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render on devices 2,0 exited ${rc}:\n${out}${err}")
endif()

foreach(other all list)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/one.pfm" "${WORK_DIR}/${other}.pfm"
    RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${other}.pfm differs from the image of one device")
  endif()
endforeach()

run_prism(render "${scene}" -o "${WORK_DIR}/twice.pfm" --width 8 --height 6 --device 0,0)
if(rc EQUAL 0 OR NOT err MATCHES "named twice")
  message(FATAL_ERROR "a device named twice must be refused (exit ${rc}):\n${out}${err}")
endif()

# A scene that names its devices (render.device) renders on them unless --device says otherwise.
file(WRITE "${WORK_DIR}/scene_devices.json" [=[{
  "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "fov": 40},
  "render": {"device": "all"},
  "lights": [{"position": [3, 6, 4]}],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
              {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]}]
}]=])
run_prism(render "${WORK_DIR}/scene_devices.json" -o "${WORK_DIR}/scene_all.pfm" --width 320 --height 240)
if(NOT rc EQUAL 0 OR NOT out MATCHES "spp on 3 devices ")
  message(FATAL_ERROR "render.device all must render on the three devices (exit ${rc}):\n${out}${err}")
endif()
run_prism(render "${WORK_DIR}/scene_devices.json" -o "${WORK_DIR}/scene_one.pfm" --width 320 --height 240 --device 1)
if(NOT rc EQUAL 0 OR out MATCHES "devices \\(")
  message(FATAL_ERROR "--device 1 must override render.device (exit ${rc}):\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/scene_all.pfm" "${WORK_DIR}/scene_one.pfm"
  RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the scene rendered on three devices differs from one device's image")
endif()
