#include "device/stderr_capture.h"

#include <unistd.h>

#include <iostream>

namespace clr {

StderrCapture::StderrCapture() {
    std::cerr.flush();
    std::fflush(stderr);
    capture_ = std::tmpfile();  // already unlinked: nothing is left behind
    if (!capture_) return;
    saved_stderr_ = ::dup(STDERR_FILENO);
    if (saved_stderr_ < 0 || ::dup2(::fileno(capture_), STDERR_FILENO) < 0) {
        if (saved_stderr_ >= 0) ::close(saved_stderr_);
        saved_stderr_ = -1;
        std::fclose(capture_);
        capture_ = nullptr;
    }
}

StderrCapture::~StderrCapture() { finish(); }

std::string StderrCapture::finish() {
    if (!capture_) return "";
    std::fflush(stderr);
    ::dup2(saved_stderr_, STDERR_FILENO);
    ::close(saved_stderr_);
    saved_stderr_ = -1;
    constexpr std::size_t kMostBytes = 1 << 20;
    std::string text;
    std::rewind(capture_);
    char chunk[4096];
    while (text.size() < kMostBytes) {
        const std::size_t got = std::fread(chunk, 1, sizeof chunk, capture_);
        if (got == 0) break;
        text.append(chunk, got);
    }
    std::fclose(capture_);
    capture_ = nullptr;
    return text.substr(0, kMostBytes);
}

}  // namespace clr
