#include "core/payload_checksum.h"

#include <xxhash.h>

#include <cstring>
#include <new>

namespace clr {

struct PayloadChecksummer::State {
    XXH3_state_t* xxh = nullptr;
    ~State() { XXH3_freeState(xxh); }
};

PayloadChecksummer::PayloadChecksummer() : state_(std::make_unique<State>()) {
    state_->xxh = XXH3_createState();
    if (!state_->xxh) throw std::bad_alloc();
    XXH3_128bits_reset(state_->xxh);
}

PayloadChecksummer::~PayloadChecksummer() = default;

void PayloadChecksummer::add(const void* data, std::size_t size) {
    if (size > 0) XXH3_128bits_update(state_->xxh, data, size);
}

PayloadChecksum PayloadChecksummer::finish() const {
    XXH128_canonical_t canonical;
    XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->xxh));
    PayloadChecksum checksum;
    static_assert(sizeof canonical.digest == sizeof checksum, "XXH3-128 is 16 bytes");
    std::memcpy(checksum.data(), canonical.digest, checksum.size());
    return checksum;
}

PayloadChecksum payload_checksum(const void* data, std::size_t size) {
    PayloadChecksummer checksummer;
    checksummer.add(data, size);
    return checksummer.finish();
}

}  // namespace clr
