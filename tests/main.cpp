// The test runner of the core and GDAL tests: Catch2's own, under Catch2 2 and 3 alike.
#define CATCH_CONFIG_RUNNER
#include "catch_compat.h"

int main(int argc, char* argv[]) {
  return Catch::Session().run(argc, argv);
}
