// The test binary keeps its caches (program binaries, decoded images) in the build folder,
// never in the user's own cache, however it is started (ctest, or the binary directly).
// Tests that check the caches point CLRENDER_CACHE_DIR at folders of their own. The program
// store beside the binary is off too, so that runs build and cache programs as before; tests of
// the store name one.
#include <cstdlib>

namespace {

const bool kCacheFolderSet = [] {
    setenv("CLRENDER_CACHE_DIR", CLRENDER_TEST_CACHE_DIR, /*overwrite=*/0);
    setenv("CLRENDER_PROGRAM_STORE", "off", /*overwrite=*/0);
    return true;
}();

}  // namespace
