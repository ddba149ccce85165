#include "device/exact_arithmetic.h"

namespace clr {

std::string with_exact_arithmetic(const cl::Device& device, const std::string& options) {
    cl_device_fp_config config = 0;
    try {
        config = device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>();
    } catch (const cl::Error&) {  // not said: the driver's defaults
        return options;
    }
    if ((config & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) == 0) return options;
    return options + (options.empty() ? "" : " ") + "-cl-fp32-correctly-rounded-divide-sqrt";
}

}  // namespace clr
