// Catch2's runner for the tracer tests (CPU only: no validation log to check).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
