# Installs prism into a fresh prefix and uses it as a stranger would:
#  - examples/ configured with find_package(prism) against the prefix alone,
#    built, and both programs run (each checks its own result);
#  - examples/c/query_mesh.c compiled again with pkg-config's flags;
#  - libprism exports exactly the functions prism.h declares, and
#    docs/c-api.md lists each;
#  - the installed prism command finds the installed library and plugins.
# Run by CTest: cmake -DBUILD=<build dir> -DSOURCE=<source dir> -DWORK=<scratch> -P install_test.cmake
cmake_minimum_required(VERSION 3.20)
foreach(v BUILD SOURCE WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "install_test: -D${v}=... is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "install_test: '${cmd}' failed (${rc}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})

# Everything in its place.
include(GNUInstallDirs)
foreach(f bin/prism include/prism.h include/prism_config.h include/prism_plugin.h
          lib/cmake/prism/prismConfig.cmake lib/cmake/prism/prismConfigVersion.cmake
          lib/cmake/prism/prismTargets.cmake lib/pkgconfig/prism.pc
          lib/prism/plugins/obj.so lib/prism/plugins/ply.so lib/prism/plugins/off.so)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install_test: ${prefix}/${f} was not installed")
  endif()
endforeach()

# Exactly the C API is exported: every function include/prism.h declares, and
# nothing else.
run(nm -D --defined-only ${prefix}/lib/libprism.so)
string(REGEX MATCHALL "[^\n]+" lines "${run_output}")
set(exported "")
foreach(line ${lines})
  string(REGEX REPLACE "^[0-9a-fA-F]* *[A-Za-z] " "" name "${line}")
  if(NOT name MATCHES "^prism")
    message(FATAL_ERROR "install_test: libprism exports '${name}', which is not part of the C API")
  endif()
  list(APPEND exported ${name})
endforeach()
file(READ ${SOURCE}/include/prism.h header)
file(READ ${SOURCE}/docs/c-api.md c_api_doc)
string(REGEX MATCHALL "PRISM_API[^;(]*[ *]prism[A-Za-z0-9]+\\(" declarations "${header}")
list(LENGTH declarations declared)
if(declared LESS 10)
  message(FATAL_ERROR "install_test: found only ${declared} declarations in prism.h; is the pattern stale?")
endif()
foreach(d ${declarations})
  string(REGEX MATCH "prism[A-Za-z0-9]+\\($" name "${d}")
  string(REGEX REPLACE "\\($" "" name "${name}")
  if(NOT name IN_LIST exported)
    message(FATAL_ERROR "install_test: prism.h declares ${name}, which libprism does not export")
  endif()
  # docs/c-api.md lists every function with its errors.
  string(FIND "${c_api_doc}" "`${name}`" listed)
  if(listed EQUAL -1)
    message(FATAL_ERROR "install_test: docs/c-api.md does not list ${name}")
  endif()
endforeach()

# The examples, through find_package(prism) and nothing else.
run(${CMAKE_COMMAND} -S ${SOURCE}/examples -B ${WORK}/examples -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK}/examples)
run(${WORK}/examples/query_mesh cpu)
message(STATUS "query_mesh: ${run_output}")
run(${WORK}/examples/render_scene ${WORK}/render_scene.png cpu)
message(STATUS "render_scene: ${run_output}")
if(NOT EXISTS ${WORK}/render_scene.png)
  message(FATAL_ERROR "install_test: render_scene did not write its image")
endif()

# The same program through pkg-config.
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
run(pkg-config --cflags --libs prism)
string(STRIP "${run_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
run(cc -std=c99 -Wall -Wextra -pedantic ${SOURCE}/examples/c/query_mesh.c ${flags} -lm
    -Wl,-rpath,${prefix}/lib -o ${WORK}/query_mesh_pkgconfig)
run(${WORK}/query_mesh_pkgconfig cpu)

# The installed command, with its plugins found beside the installed library.
run(${prefix}/bin/prism plugins)
foreach(format obj ply off)
  if(NOT run_output MATCHES "${prefix}/lib/prism/plugins/${format}.so")
    message(FATAL_ERROR "install_test: the installed prism does not list ${format}.so:\n${run_output}")
  endif()
endforeach()
run(${prefix}/bin/prism info ${SOURCE}/tests/data/meshes/cornell_box/CornellBox-Original.obj)
message(STATUS "install_test: installed into ${prefix}, examples built and run")
