#include "app/exit_status.h"

#include <new>
#include <system_error>

#include "core/errors.h"
#include "core/printable_text.h"
#include "device/cl_errors.h"
#include "device/opencl.h"

namespace clr {
namespace {

ExitStatus status(int code, const std::string& problem) {
    // One line whatever the message quotes (a file name with a newline, an encoder's log).
    const std::string text = printable(problem);
    return {code, "clrender: error: " + text, text};
}

ExitStatus internal_error(const std::string& what) {
    return status(kExitInternal, "internal error: " + what + "; please report this as a bug in clrender");
}

// std::thread reports a thread the system cannot start (no memory for its stack, the limit
// on processes) as resource_unavailable_try_again.
bool is_thread_exhaustion(const std::system_error& error) {
    return error.code() == std::errc::resource_unavailable_try_again;
}

}  // namespace

ExitStatus exit_status_for(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const Error& error) {
        ExitStatus result = status(error.code(), error.headline());
        // Each line is escaped alone: the breaks between them are clrender's, not the text's.
        for (const std::string& line : error.lines()) {
            result.message += "\n  " + printable(line);
            result.problem += "\n  " + printable(line);
        }
        return result;
    } catch (const cl::Error& error) {
        return status(kExitDevice, describe_cl_error(error, "OpenCL"));
    } catch (const std::bad_alloc&) {
        return status(kExitOutOfMemory, "out of memory");
    } catch (const std::system_error& error) {
        if (is_thread_exhaustion(error)) return status(kExitOutOfMemory, std::string("out of memory: ") + error.what());
        return internal_error(error.what());
    } catch (const std::exception& error) {
        return internal_error(error.what());
    } catch (...) {
        return internal_error("an exception of unknown type");
    }
}

}  // namespace clr
