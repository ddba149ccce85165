#include "output/encoder_timeout.h"

#include <cmath>
#include <cstdlib>
#include <locale>
#include <sstream>

#include "core/errors.h"

namespace clr {
namespace {

constexpr double kDefaultSeconds = 60;
constexpr double kLongestSeconds = 24 * 3600;  // beyond that, a typo rather than a wish

}  // namespace

Seconds encoder_stall_timeout() {
    const char* text = std::getenv("CLRENDER_ENCODER_TIMEOUT");
    if (!text || !*text) return Seconds(kDefaultSeconds);
    std::istringstream parser(text);
    parser.imbue(std::locale::classic());
    double seconds = 0;
    parser >> seconds;
    if (!parser || !parser.eof() || !std::isfinite(seconds) || seconds <= 0 || seconds > kLongestSeconds) {
        throw UsageError("CLRENDER_ENCODER_TIMEOUT must be a number of seconds above 0 and at most 86400 (got '" +
                         std::string(text) + "')");
    }
    return Seconds(seconds);
}

std::string seconds_text(Seconds seconds) {
    std::ostringstream text;
    text.imbue(std::locale::classic());
    text.precision(6);
    text << seconds.count();
    return text.str();
}

}  // namespace clr
