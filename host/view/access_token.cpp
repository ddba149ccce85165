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

}  // namespace clr
