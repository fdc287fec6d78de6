/* Linked into every executable of a sanitized build (cmake/HushSanitize.cmake).
 *
 * Why a no-op dlclose: the Vulkan loader dlcloses lavapipe and the validation layer
 * in vkDestroyInstance, long before LeakSanitizer runs at exit. Leaks made inside
 * them are then reported from "<unknown module>", and no suppression by library
 * name can tell them from hush's own. Defined in the executable (and exported, see
 * the CMake module), this dlclose comes first in symbol lookup, ahead of libc's and
 * of the sanitizer runtime's interceptor, so every library stays mapped and named.
 * A test process is short-lived, so keeping libraries mapped costs nothing real.
 *
 * The option hooks below make a sanitized binary behave the same when run by hand
 * as under CTest: the environment's ASAN_OPTIONS / LSAN_OPTIONS / UBSAN_OPTIONS are
 * read after these defaults and override them. */

int dlclose(void* handle);
int dlclose(void* handle) {
  (void)handle;
  return 0;
}

const char* __asan_default_options(void);
const char* __asan_default_options(void) {
  return "detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1";
}

const char* __lsan_default_options(void);
const char* __lsan_default_options(void) {
  return "suppressions=" HUSH_LSAN_SUPPRESSIONS ":print_suppressions=0";
}

const char* __ubsan_default_options(void);
const char* __ubsan_default_options(void) {
  return "print_stacktrace=1:halt_on_error=1:suppressions=" HUSH_UBSAN_SUPPRESSIONS;
}
