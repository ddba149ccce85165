// stb_image's implementation, compiled into the fuzz targets with their sanitizers and
// coverage instrumentation instead of being taken from Debian's (uninstrumented) libstb.so.
// The header is the one libstb.so is built from, so the fuzzers test the decoder clrender
// runs. Only the fuzz build compiles this file (see fuzz/CMakeLists.txt).
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
