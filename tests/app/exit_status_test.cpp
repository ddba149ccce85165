// The exit code and line for each kind of failure that ends a run (README, Exit codes): an
// unexpected exception is an internal error, never passed off as a device problem.
#include "app/exit_status.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <system_error>

#include "core/errors.h"
#include "device/opencl.h"

namespace clr {
namespace {

template <typename Exception>
ExitStatus status_for(const Exception& failure) {
    return exit_status_for(std::make_exception_ptr(failure));
}

TEST(ExitStatus, TypedErrorsKeepTheirCodeAndMessage) {
    EXPECT_EQ(status_for(UsageError("bad option")).code, 1);
    EXPECT_EQ(status_for(SceneError("a.json", "/width", "must be positive")).code, 2);
    EXPECT_EQ(status_for(DeviceError("no device")).code, 3);
    EXPECT_EQ(status_for(OutputError("disk full")).code, 4);
    EXPECT_EQ(status_for(SceneError("a.json", "/width", "must be positive")).message,
              "clrender: error: a.json: /width: must be positive");
}

// A listing under an error keeps its line breaks; each line is still escaped alone, so a
// device name cannot break or forge a line.
TEST(ExitStatus, LinesUnderAnErrorAreLinesEachEscaped) {
    const ExitStatus status =
        status_for(DeviceError("unknown OpenCL device 'x\n'; available devices:", {"[0] 0:0  cpu", "[1] 0:1  evil\nclrender: ok\x1b"}));
    EXPECT_EQ(status.code, 3);
    EXPECT_EQ(status.message,
              "clrender: error: unknown OpenCL device 'x\\x0A'; available devices:\n  [0] 0:0  cpu\n  [1] 0:1  "
              "evil\\x0Aclrender: ok\\x1B");
}

TEST(ExitStatus, UnexpectedExceptionIsAnInternalErrorNotADeviceError) {
    const ExitStatus status = status_for(std::logic_error("vector::_M_range_check"));
    EXPECT_EQ(status.code, 5);
    EXPECT_EQ(status.message,
              "clrender: error: internal error: vector::_M_range_check; please report this as a bug in clrender");
}

TEST(ExitStatus, ExceptionOfNoStandardTypeIsAnInternalError) {
    const ExitStatus status = status_for(42);
    EXPECT_EQ(status.code, 5);
    EXPECT_NE(status.message.find("internal error"), std::string::npos) << status.message;
}

TEST(ExitStatus, OtherSystemErrorsAreInternal) {
    EXPECT_EQ(status_for(std::system_error(std::make_error_code(std::errc::invalid_argument), "mutex")).code, 5);
}

TEST(ExitStatus, OutOfMemoryHasItsOwnCodeAndSaysSo) {
    const ExitStatus status = status_for(std::bad_alloc());
    EXPECT_EQ(status.code, 6);
    EXPECT_EQ(status.message, "clrender: error: out of memory");
}

TEST(ExitStatus, ThreadThatCannotStartIsOutOfMemory) {
    const ExitStatus status =
        status_for(std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again), "thread"));
    EXPECT_EQ(status.code, 6);
    EXPECT_EQ(status.message.rfind("clrender: error: out of memory: thread", 0), 0u) << status.message;
}

TEST(ExitStatus, UntypedOpenClErrorIsADeviceError) {
    const ExitStatus status = status_for(cl::Error(-5, "clEnqueueNDRangeKernel"));
    EXPECT_EQ(status.code, 3);
    EXPECT_EQ(status.message, "clrender: error: OpenCL: clEnqueueNDRangeKernel failed with CL_OUT_OF_RESOURCES");
}

TEST(ExitStatus, MessageIsOneEscapedLine) {
    const ExitStatus status = status_for(OutputError("out\nput\x1b[2J"));
    EXPECT_EQ(status.message.find('\n'), std::string::npos);
    EXPECT_EQ(status.message.find('\x1b'), std::string::npos);
    EXPECT_EQ(status.code, 4);
}

TEST(ExitStatus, InterruptionKeepsTheSignalCode) {
    EXPECT_EQ(status_for(Error("interrupted", static_cast<ExitCode>(130))).code, 130);
}

}  // namespace
}  // namespace clr
