#include "device/device_context.h"

#include <iostream>
#include <sstream>

#include "core/errors.h"
#include "core/message_lines.h"
#include "core/printable_text.h"
#include "device/cl_errors.h"
#include "device/driver_limits.h"
#include "device/exact_arithmetic.h"
#include "device/program_cache.h"
#include "device/stderr_capture.h"

namespace clr {
namespace {

// What the compiler printed during a build that succeeded (warnings): as it printed it, or with
// --progress json one JSON warning a line, so that every line on standard error stays JSON.
void print_compiler_output(const std::string& text) {
    if (!json_messages()) {
        std::cerr << text;
        return;
    }
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) std::cerr << message_line("warning", "OpenCL compiler: " + printable(line));
}

}  // namespace

DeviceContext::DeviceContext(const DeviceEntry& device, ProgramStore store) : entry_(device), store_(std::move(store)) {
    try {
        context_ = cl::Context(entry_.device);
        queue_ = cl::CommandQueue(context_, entry_.device, CL_QUEUE_PROFILING_ENABLE);
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "opening OpenCL device '" + entry_.device_name + "'"));
    }
}

std::optional<cl::Program> DeviceContext::build_from_cache(const ProgramCache& cache, const ProgramCache::Key& key,
                                                          const std::string& options) const {
    std::optional<std::vector<unsigned char>> binary;
    std::string aside;
    try {
        binary = cache.borrow(key, ProgramCache::driver_magic(entry_.device), aside);
    } catch (const std::exception&) {  // e.g. no memory for the entry: a miss
    }
    if (!binary) return std::nullopt;
    try {
        cl::Program cached(context_, {entry_.device}, cl::Program::Binaries{*binary});
        cached.build({entry_.device}, with_exact_arithmetic(entry_.device, options).c_str());
        // Back under its name when this context ends, not now: the driver may still crash on it
        // when the kernels are made or run, and then it must not be found again.
        borrowed_.push_back({cache.cache_folder(), key, aside});
        ++cache_hits_;
        return cached;
    } catch (const cl::Error&) {
        cache.discard(aside);  // refused by the driver: replaced by the build from source
        return std::nullopt;
    }
}

std::optional<ProgramCache::Key> DeviceContext::key_of(const ProgramCache& cache, const std::string& source,
                                                       const std::string& options) const {
    if (!cache.enabled() && !store_.enabled()) return std::nullopt;
    try {
        return ProgramCache::key(entry_.device, source, options);
    } catch (const std::exception&) {  // no key, no caching
        return std::nullopt;
    }
}

std::optional<cl::Program> DeviceContext::prebuilt_program(const ProgramCache& cache,
                                                           const std::optional<ProgramCache::Key>& key,
                                                           const std::string& options) const {
    if (!key) return std::nullopt;
    // A binary from an earlier run first (device/program_cache.h). The cache hands out only
    // entries that pass every check; one the driver still refuses is removed and rebuilt.
    if (std::optional<cl::Program> cached = build_from_cache(cache, *key, options)) return cached;
    // Then the read-only store built ahead of need: nothing to store after a hit.
    std::optional<cl::Program> stored = build_from_store(store_, context_, entry_.device, *key, options);
    if (stored) ++store_hits_;
    return stored;
}

std::optional<cl::Program> DeviceContext::prebuilt_program(const std::string& source, const std::string& options) const {
    const ProgramCache cache = ProgramCache::from_environment();
    return prebuilt_program(cache, key_of(cache, source, options), options);
}

cl::Program DeviceContext::build_program(const std::string& source, const std::string& options) const {
    const ProgramCache cache = ProgramCache::from_environment();
    const std::optional<ProgramCache::Key> key = key_of(cache, source, options);
    if (std::optional<cl::Program> prebuilt = prebuilt_program(cache, key, options)) return *prebuilt;
    // Short of address space, PoCL's compiler hangs or crashes instead of failing.
    check_room_for_a_build();
    cl::Program program(context_, source);
    const std::string all_options = with_exact_arithmetic(entry_.device, options);
    // The compiler's own output waits until clrender's error line, if any, is out.
    StderrCapture compiler_output;
    try {
        program.build({entry_.device}, all_options.c_str());
        print_compiler_output(compiler_output.finish());
    } catch (const cl::Error& error) {
        const std::string printed = compiler_output.finish();
        const std::string building = "building the OpenCL program for '" + entry_.device_name + "'";
        if (error.err() == CL_OUT_OF_HOST_MEMORY) throw Error("out of memory: " + building, kExitOutOfMemory);
        // A build that failed for the process's surroundings (a cache folder PoCL cannot write,
        // too few descriptors), not for the source: that is what the user can act on.
        if (std::optional<Error> trouble = driver_trouble(building + " failed")) throw *trouble;
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(entry_.device);
        } catch (const cl::Error&) {
            log = "(no build log available)";
        }
        throw DeviceError(describe_cl_error(error, building) +
                          "\nbuild options: " + all_options + "\nbuild log:\n" + log +
                          (printed.empty() ? "" : "\ncompiler output:\n" + printed));
    }
    // Asking PoCL for the binary compiles every kernel of the program, which takes longer than
    // a frame (docs/benchmarks.md, Figures behind design choices): that is left to
    // store_built_programs(), after the frames are written.
    if (key && cache.enabled()) to_store_.push_back({cache.cache_folder(), *key, program});
    return program;
}

DeviceContext::~DeviceContext() { give_back_borrowed(); }

void DeviceContext::give_back_borrowed() const {
    for (const Borrowed& entry : borrowed_) ProgramCache(entry.cache_folder).give_back(entry.key, entry.aside);
    borrowed_.clear();
}

void DeviceContext::store_built_programs() {
    give_back_borrowed();
    for (const PendingEntry& entry : to_store_) {
        try {
            std::vector<std::vector<unsigned char>> binaries = entry.program.getInfo<CL_PROGRAM_BINARIES>();
            if (binaries.size() == 1) ProgramCache(entry.cache_folder).store(entry.key, binaries.front());
        } catch (const std::exception&) {  // best effort: the next run builds from source again
        }
    }
    to_store_.clear();
}

}  // namespace clr
