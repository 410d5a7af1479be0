// The one translation unit that holds Catch2's main().
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cstdlib>

namespace {
// The tests draw with shaders the optimiser specialises in their own process: files an earlier
// run left in the disk cache (PHIGS_SHADER_CACHE) would make a test's path depend on what ran
// before. The cache's own tests give it folders of their own.
const int kNoShaderCache = (setenv("PHIGS_SHADER_CACHE", "off", 1), 0);
}  // namespace
