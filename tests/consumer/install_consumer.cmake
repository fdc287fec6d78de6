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
# A sanitized hush (scripts/sanitize.sh) is static libraries that call the sanitizer runtime: the
# consumer must compile and link with the same -fsanitize list. The consumer is an
# outside project, without hush's no-op dlclose (tests/sanitize/runtime_defaults.c),
# so the Vulkan driver's leaks could not be told from its own: leak checking is off
# for the consumer's programs only (the installed CLI below keeps it).
set(sanitize_flags "")
set(consumer_env "")   # NAME=VALUE assignments for every consumer program's run
if(CONSUMER_SANITIZE)
  set(sanitize_flags "-fsanitize=${CONSUMER_SANITIZE}")
  list(APPEND configure_args "-DCMAKE_C_FLAGS=${sanitize_flags}" "-DCMAKE_CXX_FLAGS=${sanitize_flags}"
       "-DCMAKE_EXE_LINKER_FLAGS=${sanitize_flags}")
  list(APPEND consumer_env "ASAN_OPTIONS=detect_leaks=0")
endif()
run_step("configure consumer" "${CMAKE_COMMAND}" ${configure_args})
run_step("build consumer" "${CMAKE_COMMAND}" --build "${build}")
run_step("run consumer" "${CMAKE_COMMAND}" -E env ${consumer_env} "${build}/hush_consumer")
run_step("run C consumer (CMake package)" "${CMAKE_COMMAND}" -E env ${consumer_env} "${build}/hush_c_consumer")
# The C API as a plain Makefile project would use it: pkg-config alone.
find_program(PKG_CONFIG pkg-config REQUIRED)
find_program(C_COMPILER NAMES cc gcc clang REQUIRED)
file(GLOB pc_files "${prefix}/lib*/pkgconfig/hush.pc" "${prefix}/lib*/*/pkgconfig/hush.pc")
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir "${pc_file}" DIRECTORY)
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PKG_CONFIG_PATH=${pc_dir}" "${PKG_CONFIG}" --cflags --libs hush
                OUTPUT_VARIABLE pc_flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE pc_result)
if(NOT pc_result EQUAL 0)
  message(FATAL_ERROR "install_consumer: pkg-config --cflags --libs hush failed in ${pc_dir}")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
run_step("compile C consumer (pkg-config)" "${C_COMPILER}" -std=c11 -Wall -Wextra -Werror
         ${sanitize_flags} "${CONSUMER_SOURCE_DIR}/main.c" ${pc_flags} -lm -o "${build}/hush_c_pkgconfig")
run_step("run C consumer (pkg-config)" "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${pc_dir}/.." ${consumer_env}
         "${build}/hush_c_pkgconfig")
run_step("run installed CLI" "${prefix}/bin/hush" --version)
message(STATUS "install_consumer: passed")
