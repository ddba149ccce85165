#include "fuzz_support.h"

#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/printable_text.h"

namespace clr::fuzz {

namespace {

std::string make_work_folder() {
    const char* tmpdir = std::getenv("TMPDIR");
    std::string name = std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/clrender-fuzz-XXXXXX";
    if (!::mkdtemp(name.data())) report_bug("cannot make a work folder", name);
    return name;
}

void remove_work_folder() {
    std::error_code ignored;
    std::filesystem::remove_all(work_folder(), ignored);
}

}  // namespace

const std::string& work_folder() {
    // Never destroyed: the exit handler that removes the folder still needs its name, and
    // handlers and static destructors run in an order that is easy to get wrong.
    static const std::string* folder = [] {
        auto* made = new std::string(make_work_folder());
        std::atexit(remove_work_folder);
        return made;
    }();
    return *folder;
}

void write_file(const std::string& path, const void* data, std::size_t size) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) report_bug("cannot write a fuzz input file", path);
    const bool written = std::fwrite(data, 1, size, file) == size;
    if (std::fclose(file) != 0 || !written) report_bug("cannot write a fuzz input file", path);
}

bool is_one_printable_line(const std::string& message) { return clr::printable(message) == message; }

void report_bug(const std::string& what, const std::string& detail) {
    std::fprintf(stderr, "clrender fuzz: BUG: %s: %s\n", what.c_str(), detail.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace clr::fuzz
