#include "support/process_table.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace clr::testing {

std::vector<ProcessEntry> process_table() {
    std::vector<ProcessEntry> table;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream stat_file(entry.path() / "stat");
        std::string stat;
        if (!std::getline(stat_file, stat)) continue;
        // "pid (command) state ppid pgrp ...": the command may contain spaces and ')'.
        std::istringstream fields(stat.substr(stat.rfind(')') + 1));
        ProcessEntry process;
        process.pid = std::stoi(name);
        fields >> process.state >> process.parent >> process.group;
        if (fields) table.push_back(process);
    }
    return table;
}

bool still_runs(const std::vector<ProcessEntry>& table, pid_t pid) {
    for (const ProcessEntry& process : table)
        if (process.pid == pid) return process.state != 'Z';
    return false;
}

}  // namespace clr::testing
