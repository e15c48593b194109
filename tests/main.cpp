// The single Catch2 test binary's entry point. Test files live beside it, one folder per
// library (tests/core, tests/models, tests/losses, tests/optim).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
