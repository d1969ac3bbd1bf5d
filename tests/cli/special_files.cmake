# Output and input paths that are not plain files: a full device is an error
# (and stays a device), a symbolic link is written through, and a FIFO given as
# the scene is refused at once instead of blocking.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P special_files.cmake

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(scene "${WORK_DIR}/sphere.json")
file(WRITE "${scene}" [=[{"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]}]=])
# One 32-byte ray, every byte 'A' (each float 12.08): a legal ray file.
set(rays "${WORK_DIR}/rays.bin")
file(WRITE "${rays}" "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA")

function(run_prism)
  execute_process(COMMAND ${PRISM} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  set(rc "${rc}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# A full disk: exit 1 with the system's reason, and /dev/full left a device.
if(EXISTS /dev/full)
  run_prism(trace "${scene}" --rays "${rays}" --hits /dev/full --quiet)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "cannot write hits to '/dev/full'")
    message(FATAL_ERROR "--hits /dev/full: exited ${rc}, expected 1 with a message:\n${err}")
  endif()
  execute_process(COMMAND test -c /dev/full RESULT_VARIABLE still_device)
  if(NOT still_device EQUAL 0)
    message(FATAL_ERROR "--hits /dev/full replaced the device with a file")
  endif()
endif()

# Through a symbolic link: the file it names gets the hits, the link stays.
file(CREATE_LINK "${WORK_DIR}/real_hits.bin" "${WORK_DIR}/link_hits.bin" SYMBOLIC)
run_prism(trace "${scene}" --rays "${rays}" --hits "${WORK_DIR}/link_hits.bin" --quiet)
file(SIZE "${WORK_DIR}/real_hits.bin" size)
if(NOT rc EQUAL 0 OR NOT size EQUAL 16 OR NOT IS_SYMLINK "${WORK_DIR}/link_hits.bin")
  message(FATAL_ERROR "--hits through a link: exited ${rc}, ${size} bytes in its target:\n${err}")
endif()

# A FIFO as the scene: refused, not waited on.
execute_process(COMMAND mkfifo "${WORK_DIR}/scene.json" RESULT_VARIABLE made)
if(made EQUAL 0)
  run_prism(render "${WORK_DIR}/scene.json" -o "${WORK_DIR}/out.png" --quiet)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "not a regular file")
    message(FATAL_ERROR "a FIFO as the scene: exited ${rc}, expected 1 naming it:\n${err}")
  endif()
endif()
