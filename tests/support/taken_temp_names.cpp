#include "support/taken_temp_names.h"

#include <filesystem>
#include <regex>
#include <stdexcept>
#include <string>

#include "output/temp_files.h"

namespace clr::testing {

int take_the_next_usual_temp_names(const TempFolder& folder, int count) {
    // The name just handed out tells the counter's value; the next names follow it.
    const std::string last = std::filesystem::path(temp_path_in_folder_of("x")).filename().string();
    std::smatch parts;
    if (!std::regex_match(last, parts, std::regex(R"((\.clrender-[0-9a-f]{8}-[0-9]+-)([0-9]+)\.tmp)")))
        throw std::runtime_error("unexpected temporary name " + last);
    const unsigned long next = std::stoul(parts[2].str()) + 1;
    for (unsigned long n = next; n < next + static_cast<unsigned long>(count); ++n) {
        const std::string name = parts[1].str() + std::to_string(n) + ".tmp";
        folder.write(name, "");
        folder.write(name + ".log", "");
    }
    return 2 * count;
}

}  // namespace clr::testing
