# Run by CTest as `cmake -P` (registered in CMakeLists.txt beside this file).
# Installs the hush build at HUSH_BUILD_DIR into WORK_DIR/prefix, builds the
# consumer project at CONSUMER_SOURCE_DIR against it and runs it. Any failing
# step fails the test with that step's name.
foreach(required IN ITEMS HUSH_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "install_consumer.cmake: pass -D${required}=...")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
# Start clean: a stale prefix could hide a file the install no longer provides.
file(REMOVE_RECURSE "${WORK_DIR}")

function(run_step name)
  message(STATUS "install_consumer: ${name}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install_consumer: step '${name}' failed (${result}): ${ARGN}")
  endif()
endfunction()

run_step("install into ${prefix}" "${CMAKE_COMMAND}" --install "${HUSH_BUILD_DIR}" --prefix "${prefix}")

# The consumer is built like hush itself: same generator (Ninja unless told),
# compiler and build type.
if(NOT CONSUMER_GENERATOR)
  set(CONSUMER_GENERATOR Ninja)
endif()
set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${build}" -G "${CONSUMER_GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DHUSH_EXPECTED_PREFIX=${prefix}")
if(CONSUMER_BUILD_TYPE)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}")
endif()
if(CONSUMER_CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}")
endif()
if(CONSUMER_MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${CONSUMER_MAKE_PROGRAM}")
endif()
run_step("configure consumer" "${CMAKE_COMMAND}" ${configure_args})
run_step("build consumer" "${CMAKE_COMMAND}" --build "${build}")
run_step("run consumer" "${build}/hush_consumer")
run_step("run installed CLI" "${prefix}/bin/hush" --version)
message(STATUS "install_consumer: passed")
