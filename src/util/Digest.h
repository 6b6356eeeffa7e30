#pragma once
// A 64-bit FNV-1a digest of plain values: enough to tell "the same as last frame" from "changed"
// for caches keyed by what was drawn (shadows/common/DepthAndTintMaps). Not a cryptographic hash.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace penumbra::util {

class Digest {
public:
    template <typename... T>
    Digest& add(const T&... values) {
        (addBytes(values), ...);
        return *this;
    }
    // Never 0, so that 0 can stand for "nothing cached".
    std::uint64_t value() const { return state_ == 0 ? 1 : state_; }

private:
    template <typename T>
    void addBytes(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>, "digest plain values only");
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) state_ = (state_ ^ b) * 0x100000001b3ull;
    }
    std::uint64_t state_ = 0xcbf29ce484222325ull;
};

}  // namespace penumbra::util
