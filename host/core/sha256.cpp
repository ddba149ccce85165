#include "core/sha256.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace clr {

struct Sha256::Context {
    EVP_MD_CTX* evp = nullptr;
    ~Context() { EVP_MD_CTX_free(evp); }
};

namespace {

void require(int ok) {
    if (ok != 1) throw std::runtime_error("SHA-256 (libcrypto) failed");
}

}  // namespace

Sha256::Sha256() : context_(std::make_unique<Context>()) {
    context_->evp = EVP_MD_CTX_new();
    if (!context_->evp) throw std::runtime_error("SHA-256 (libcrypto): out of memory");
    require(EVP_DigestInit_ex(context_->evp, EVP_sha256(), nullptr));
}

Sha256::~Sha256() = default;

Sha256& Sha256::add(const void* data, std::size_t size) {
    if (size > 0) require(EVP_DigestUpdate(context_->evp, data, size));
    return *this;
}

Sha256& Sha256::add_number(std::uint64_t number) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(number >> (8 * i));
    return add_field(bytes, sizeof bytes);
}

Sha256& Sha256::add_field(const void* data, std::size_t size) {
    unsigned char length[8];
    for (int i = 0; i < 8; ++i) length[i] = static_cast<unsigned char>(std::uint64_t(size) >> (8 * i));
    add(length, sizeof length);
    return add(data, size);
}

Sha256Digest Sha256::finish() {
    Sha256Digest digest{};
    unsigned int size = 0;
    require(EVP_DigestFinal_ex(context_->evp, digest.data(), &size));
    if (size != digest.size()) throw std::runtime_error("SHA-256 (libcrypto): unexpected digest size");
    return digest;
}

Sha256Digest sha256(const void* data, std::size_t size) { return Sha256().add(data, size).finish(); }

std::string to_hex(const Sha256Digest& digest) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string hex;
    hex.reserve(2 * digest.size());
    for (unsigned char byte : digest) {
        hex += kDigits[byte >> 4];
        hex += kDigits[byte & 15];
    }
    return hex;
}

}  // namespace clr
