// The test binary keeps its caches (program binaries, decoded images) in the build folder,
// never in the user's own cache, however it is started (ctest, or the binary directly).
// Tests that check the caches point CLRENDER_CACHE_DIR at folders of their own.
#include <cstdlib>

namespace {

const bool kCacheFolderSet = [] {
    setenv("CLRENDER_CACHE_DIR", CLRENDER_TEST_CACHE_DIR, /*overwrite=*/0);
    return true;
}();

}  // namespace
