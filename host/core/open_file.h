// A file descriptor closed when it goes out of scope (the caches' and the program store's
// entries are read through one, opened with the checks each needs).
#pragma once

#include <unistd.h>

namespace clr {

class OpenFile {
public:
    explicit OpenFile(int descriptor) : descriptor_(descriptor) {}
    ~OpenFile() {
        if (descriptor_ >= 0) ::close(descriptor_);
    }
    OpenFile(const OpenFile&) = delete;
    OpenFile& operator=(const OpenFile&) = delete;
    int get() const { return descriptor_; }

private:
    int descriptor_;
};

}  // namespace clr
