#include "output/output_roles.h"

#include "core/errors.h"

namespace clr {
namespace {

OutputError clash(const std::string& output_role, const std::string& output_path, const std::string& other_role,
                  const std::string& other_path) {
    return OutputError(output_path + ": the " + output_role + " would replace the " + other_role + " '" + other_path +
                       "' (the same file); choose another output name");
}

}  // namespace

void OutputRoles::add_input(const std::string& role, const std::string& path) {
    auto [entry, is_new] = files_.try_emplace(identify_file(path), Named{role, path, false});
    if (!is_new && entry->second.is_output) throw clash(entry->second.role, entry->second.path, role, path);
    // An input named twice (two billboards showing one texture) is simply read twice.
}

void OutputRoles::add_output(const std::string& role, const std::string& path) {
    auto [entry, is_new] = files_.try_emplace(identify_file(path), Named{role, path, true});
    if (!is_new) throw clash(role, path, entry->second.role, entry->second.path);
}

}  // namespace clr
