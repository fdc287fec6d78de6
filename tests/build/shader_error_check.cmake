# Builds a one-shader project through cmake/HushShaders.cmake with a deliberate
# error on line 5 and checks that the build fails and names file:line. Then fixes
# the shader and checks the same project builds, so the failure is the shader's.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/src/shaders")
file(WRITE "${WORK_DIR}/src/CMakeLists.txt" "
cmake_minimum_required(VERSION 3.25)
project(shader_error LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
list(APPEND CMAKE_MODULE_PATH \"${HUSH_SOURCE_DIR}/cmake\")
include(HushShaders)
add_library(hush_rhi INTERFACE)   # headers only: the generated table needs shader_library.hpp
target_include_directories(hush_rhi INTERFACE \"${HUSH_SOURCE_DIR}/rhi/include\")
hush_add_shader_library(broken_shaders NAMESPACE test::broken ROOT \"\${CMAKE_CURRENT_SOURCE_DIR}/shaders\"
                        SOURCES \"\${CMAKE_CURRENT_SOURCE_DIR}/shaders/broken.comp\")
")
set(good "#version 450\nlayout(local_size_x = 8) in;\nlayout(std430, binding = 0) buffer B { float v[]; };\nvoid main() {\n    v[gl_GlobalInvocationID.x] = 1.0;\n}\n")
string(REPLACE "= 1.0;" "= undeclared_name;" bad "${good}")
file(WRITE "${WORK_DIR}/src/shaders/broken.comp" "${bad}")

execute_process(COMMAND ${CMAKE_COMMAND} -S "${WORK_DIR}/src" -B "${WORK_DIR}/build" -G Ninja
                RESULT_VARIABLE configured OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "configuring the shader project failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/build"
                RESULT_VARIABLE built OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(built EQUAL 0)
  message(FATAL_ERROR "a shader with an undeclared identifier built without error:\n${out}")
endif()
if(NOT "${out}${err}" MATCHES "broken\\.comp:5")
  message(FATAL_ERROR "the build failed but did not name broken.comp:5:\n${out}\n${err}")
endif()
message(STATUS "shader error reported as expected")

file(WRITE "${WORK_DIR}/src/shaders/broken.comp" "${good}")
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/build"
                RESULT_VARIABLE rebuilt OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rebuilt EQUAL 0)
  message(FATAL_ERROR "the corrected shader did not build:\n${out}\n${err}")
endif()
message(STATUS "corrected shader builds")
