# prism --help, COMMAND --help and --version exit 0 and say what they should; an
# unknown command is a usage error (exit 2) that names the command.
# Run as: cmake -DPRISM=<exe> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P help.cmake

function(run_prism)
  execute_process(COMMAND ${PRISM} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(expect_contains text what label)
  string(FIND "${text}" "${what}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${label}: expected to find '${what}' in:\n${text}")
  endif()
endfunction()

run_prism(--help)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "prism --help exited ${rc}:\n${out}${err}")
endif()
foreach(word render devices --spp docs/cli.md docs/scene-format.md PRISM_KERNEL_DIR .cache/prism)
  expect_contains("${out}" "${word}" "prism --help")
endforeach()

run_prism(render --help)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "prism render --help exited ${rc}:\n${out}${err}")
endif()
foreach(word --output --width --height --spp --max-depth --min-weight --device --aov --seed --no-cache --quiet
             .png .exr .hdr .pfm .tif depth normal primid albedo
             --aa --filter --aa-threshold --aa-max-level --first-hit
             grid quincunx adaptive jitter poisson random box tent gaussian mitchell zbuffer trace docs/sampling.md)
  expect_contains("${out}" "${word}" "prism render --help")
endforeach()

run_prism(devices --help)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "prism devices --help exited ${rc}:\n${out}${err}")
endif()
expect_contains("${out}" "pocl-opencl-icd" "prism devices --help")

run_prism(--version)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^prism [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "prism --version exited ${rc} and printed:\n${out}${err}")
endif()

run_prism(frobnicate)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "an unknown command exited ${rc}, expected 2:\n${out}${err}")
endif()
expect_contains("${err}" "prism: error: unknown command 'frobnicate'" "prism frobnicate")

run_prism()
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "prism without a command exited ${rc}, expected 2:\n${out}${err}")
endif()
