#include "render/program_store_builder.h"

#include <filesystem>
#include <set>

#include "device/exact_arithmetic.h"
#include "device/kernel_sources.h"
#include "device/program_cache.h"
#include "device/program_store.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

bool is_entry_name(const std::string& name) {
    if (name.size() != 64 + 6 || name.compare(64, 6, ".clbin") != 0) return false;
    for (int i = 0; i < 64; ++i)
        if (!((name[i] >= '0' && name[i] <= '9') || (name[i] >= 'a' && name[i] <= 'f'))) return false;
    return true;
}

// Removes the entries of ours in `folder` that `keep` does not name.
int remove_entries_except(const std::string& folder, const std::set<std::string>& keep) {
    int removed = 0;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (is_entry_name(name) && !keep.count(name) && it->is_regular_file() && fs::remove(it->path(), error)) ++removed;
    }
    return removed;
}

}  // namespace

ProgramStoreBuild build_program_store(const std::string& folder, const DeviceEntry& device,
                                      const std::vector<FeatureSet>& feature_sets, std::ostream& log) {
    ProgramStoreBuild result;
    std::error_code error;
    fs::create_directories(folder, error);
    const ProgramStore store(folder);
    const std::string source = assemble_program_source(kRenderTilesProgram.entry);
    const std::string magic = ProgramCache::driver_magic(device.device);
    const cl::Context context(device.device);
    std::set<std::string> wanted;
    for (const FeatureSet& features : feature_sets) {
        const std::string options = features.build_options();
        const ProgramCache::Key key = ProgramCache::key(device.device, source, options);
        wanted.insert(fs::path(store.path(key)).filename().string());
        if (store.load(key, magic)) {
            ++result.kept;
            continue;
        }
        try {
            // As DeviceContext::build_program builds it, and as DeviceContext::store_built_programs
            // takes its binary: asking for it compiles the kernel's generic work-group function,
            // which the first frame of a run from the binary then reuses.
            cl::Program program(context, source);
            program.build({device.device}, with_exact_arithmetic(device.device, options).c_str());
            const std::vector<std::vector<unsigned char>> binaries = program.getInfo<CL_PROGRAM_BINARIES>();
            if (binaries.size() != 1 || !store.write(key, binaries.front())) throw std::runtime_error("no binary written");
            ++result.built;
        } catch (const std::exception& failure) {
            ++result.failed;
            log << "clrender_build_program_store: " << options << ": " << failure.what() << "\n";
        }
    }
    result.removed = remove_entries_except(folder, wanted);
    return result;
}

int empty_program_store(const std::string& folder) { return remove_entries_except(folder, {}); }

}  // namespace clr
