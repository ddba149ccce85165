// Typed errors thrown at the program's boundaries and caught once in main, each mapped to
// the exit code the command line documents (docs/command-line.md, Exit codes).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace clr {

enum ExitCode : int {
    kExitOk = 0,
    kExitUsage = 1,
    kExitScene = 2,   // bad scene file or input image
    kExitDevice = 3,  // OpenCL platform, device, build or run-time error
    kExitOutput = 4,  // output file or encoder error
    kExitInternal = 5,     // a failure clrender does not expect: a bug to report
    kExitOutOfMemory = 6,  // the machine's memory (or threads) ran out: not the scene's fault, not the device's
    kExitImagesDiffer = 7,  // clrender compare: the render and the image differ beyond the tolerance
};

class Error : public std::runtime_error {
public:
    Error(const std::string& message, ExitCode code) : std::runtime_error(message), code_(code), headline_(message) {}
    // `message`, then `lines` to print under it, each on a line of its own (the choices there
    // are, such as the devices). what() holds them all, one per line.
    Error(const std::string& message, std::vector<std::string> lines, ExitCode code)
        : std::runtime_error(joined(message, lines)), code_(code), headline_(message), lines_(std::move(lines)) {}
    ExitCode code() const { return code_; }
    const std::string& headline() const { return headline_; }
    const std::vector<std::string>& lines() const { return lines_; }

private:
    static std::string joined(std::string message, const std::vector<std::string>& lines) {
        for (const std::string& line : lines) message += "\n" + line;
        return message;
    }

    ExitCode code_;
    std::string headline_;
    std::vector<std::string> lines_;
};

// A problem with the scene or an input image. `file` is the file at fault, `location` a
// JSON pointer such as "/spheres/3/radius" (empty when the whole file is meant, or for
// images), and `detail` says what is wrong.
class SceneError : public Error {
public:
    SceneError(const std::string& file, const std::string& location, const std::string& detail)
        : Error(format(file, location, detail), kExitScene), file_(file), location_(location), detail_(detail) {}

    const std::string& file() const { return file_; }
    const std::string& location() const { return location_; }
    const std::string& detail() const { return detail_; }

private:
    static std::string format(const std::string& file, const std::string& location, const std::string& detail) {
        return file + (location.empty() ? "" : ": " + location) + ": " + detail;
    }
    std::string file_, location_, detail_;
};

class DeviceError : public Error {
public:
    explicit DeviceError(const std::string& message) : Error(message, kExitDevice) {}
    DeviceError(const std::string& message, std::vector<std::string> lines) : Error(message, std::move(lines), kExitDevice) {}
};

class OutputError : public Error {
public:
    explicit OutputError(const std::string& message) : Error(message, kExitOutput) {}
};

class UsageError : public Error {
public:
    explicit UsageError(const std::string& message) : Error(message, kExitUsage) {}
};

}  // namespace clr
