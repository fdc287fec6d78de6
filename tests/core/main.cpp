// Catch2's runner for the core tests (CPU only).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
