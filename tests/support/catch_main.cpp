// The single translation unit that builds Catch2's runner for the non-GUI test programs.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
