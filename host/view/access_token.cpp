#include "view/access_token.h"

#include <openssl/crypto.h>
#include <sys/random.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace clr {

std::string make_access_token() {
    std::uint8_t bytes[16];
    std::size_t filled = 0;
    while (filled < sizeof bytes) {
        const ssize_t got = getrandom(bytes + filled, sizeof bytes - filled, 0);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) throw std::runtime_error(std::string("cannot get random bytes for the access token: ") + std::strerror(errno));
        filled += static_cast<std::size_t>(got);
    }
    static const char* const digits = "0123456789abcdef";
    std::string token;
    for (std::uint8_t byte : bytes) {
        token += digits[byte >> 4];
        token += digits[byte & 15];
    }
    return token;
}

bool token_matches(std::string_view given, std::string_view token) {
    // The length is no secret (always 32); the digits are compared in constant time.
    if (given.size() != token.size() || token.empty()) return false;
    return CRYPTO_memcmp(given.data(), token.data(), token.size()) == 0;
}

std::string cookie_value(std::string_view cookie_header, std::string_view name) {
    std::string found;
    int times = 0;
    std::size_t start = 0;
    while (start <= cookie_header.size()) {
        std::size_t end = cookie_header.find(';', start);
        if (end == std::string_view::npos) end = cookie_header.size();
        std::string_view pair = cookie_header.substr(start, end - start);
        while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
        while (!pair.empty() && pair.back() == ' ') pair.remove_suffix(1);
        const std::size_t equals = pair.find('=');
        if (equals != std::string_view::npos && pair.substr(0, equals) == name) {
            found = std::string(pair.substr(equals + 1));
            ++times;
        }
        start = end + 1;
    }
    return times == 1 ? found : "";
}

}  // namespace clr
