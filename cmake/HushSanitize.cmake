# Sanitizers for every target: -DHUSH_SANITIZE=address,undefined (scripts/sanitize.sh).
#
# Every executable of such a build also links tests/sanitize/runtime_defaults.c: the
# sanitizers' default options (leak checking on, the suppression files of
# tests/sanitize/) and a no-op dlclose that keeps the Vulkan driver and layers mapped
# until LeakSanitizer runs, so that their leaks can be told from hush's by library name.
set(HUSH_SANITIZE "" CACHE STRING "Comma-separated -fsanitize= list for every target (empty: none)")
if(HUSH_SANITIZE)
  # -g1: line tables only, so that reports name file:line at no measurable build cost.
  # The build type's optimisation stays: the tracer's tests are CPU-bound and ASan
  # already makes them several times slower.
  add_compile_options(-fsanitize=${HUSH_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=undefined -g1)
  add_link_options(-fsanitize=${HUSH_SANITIZE})
endif()

# Called once at the end of the top-level CMakeLists.txt, when every target exists.
function(hush_add_sanitizer_defaults_to_executables)
  if(NOT HUSH_SANITIZE)
    return()
  endif()
  set(sanitize_dir "${PROJECT_SOURCE_DIR}/tests/sanitize")
  add_library(hush_sanitizer_defaults OBJECT "${sanitize_dir}/runtime_defaults.c")
  target_compile_definitions(hush_sanitizer_defaults PRIVATE
    "HUSH_LSAN_SUPPRESSIONS=\"${sanitize_dir}/lsan.supp\""
    "HUSH_UBSAN_SUPPRESSIONS=\"${sanitize_dir}/ubsan.supp\"")
  hush_collect_executables(executables "${PROJECT_SOURCE_DIR}")
  foreach(executable IN LISTS executables)
    target_sources(${executable} PRIVATE $<TARGET_OBJECTS:hush_sanitizer_defaults>)
    # An executable exports only what a library linked at build time needs; lavapipe
    # and the loader are opened at run time, so dlclose must be exported by name.
    target_link_options(${executable} PRIVATE "LINKER:--export-dynamic-symbol=dlclose")
  endforeach()
endfunction()

function(hush_collect_executables out_var directory)
  set(found "")
  get_property(targets DIRECTORY "${directory}" PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
      list(APPEND found ${target})
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY "${directory}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    hush_collect_executables(nested "${subdirectory}")
    list(APPEND found ${nested})
  endforeach()
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()
