// The files one run reads and writes, each with its role ("scene file", "--stats report"),
// so that no output replaces an input or another output of the same run: -o or --stats
// naming the scene, a texture, or each other, directly or through a hard or symbolic link.
// Files are compared by identity (output_target.h), not by name.
#pragma once

#include <map>
#include <string>

#include "output/output_target.h"

namespace clr {

class OutputRoles {
public:
    // Registers a file the run reads. Throws OutputError if it is one of the outputs.
    void add_input(const std::string& role, const std::string& path);
    // Registers a file the run writes. Throws OutputError, naming both roles, if it is an
    // input or another output.
    void add_output(const std::string& role, const std::string& path);

private:
    struct Named {
        std::string role;
        std::string path;
        bool is_output = false;
    };
    std::map<FileIdentity, Named> files_;
};

}  // namespace clr
