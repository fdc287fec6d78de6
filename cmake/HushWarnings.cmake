# One place for warning flags, applied per target so that Debian's headers stay quiet.
function(hush_set_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wno-missing-field-initializers>)
  # GCC 12 at -O3 reports -Wrestrict on ordinary std::string concatenation
  # ("x" + std::to_string(n)) inside libstdc++'s own code: a known false positive
  # (GCC bug 105651, fixed in GCC 13). Debian 12 ships GCC 12 and CI builds Release
  # with warnings as errors, so the check is off for that compiler only.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-Wno-restrict>)
  endif()
  # GCC's -Wmaybe-uninitialized is unreliable under -fsanitize (the GCC manual says so
  # for the sanitizers' instrumentation): with ASan, GCC 12 reports it inside
  # libstdc++'s std::regex. Off in sanitized builds only; Release keeps it.
  if(HUSH_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-Wno-maybe-uninitialized>)
  endif()
  if(HUSH_WERROR)
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-Werror>)
  endif()
endfunction()
