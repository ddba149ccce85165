// Holds back what a library writes straight to file descriptor 2 while it runs. PoCL's
// compiler prints its diagnostics ("2 errors generated.") to stderr while clBuildProgram
// runs, before clrender can print its own error line, which must come first. The captured
// text is handed back, to be printed after that line or added to the error.
#pragma once

#include <cstdio>
#include <string>

namespace clr {

class StderrCapture {
public:
    // Starts capturing; if that is impossible (no temporary file), stderr stays as it was.
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // Restores stderr and returns what was written meanwhile (its first MiB at most).
    std::string finish();

private:
    int saved_stderr_ = -1;
    std::FILE* capture_ = nullptr;
};

}  // namespace clr
