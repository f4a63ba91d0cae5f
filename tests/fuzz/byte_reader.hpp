// Turns a fuzzer's byte string into typed values, front to back. The same
// bytes mean the same values in every build (libFuzzer or the plain replay
// test), so a saved input reproduces everywhere. When the bytes run out every
// read returns the low end of its range (zero bits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace i2d::fuzz {

class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::size_t remaining() const { return size_ - pos_; }

    bool flag() { return (bits(1) & 1u) != 0; }

    /// An integer in [lo, hi].
    template <class T>
    T integer(T lo, T hi) {
        static_assert(std::is_integral_v<T>);
        const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
        int bytes = 1;
        while (bytes < 8 && (span >> (8 * bytes)) != 0) ++bytes;
        std::uint64_t v = bits(bytes);
        if (span != std::numeric_limits<std::uint64_t>::max()) v %= span + 1;
        return static_cast<T>(static_cast<std::uint64_t>(lo) + v);
    }

    /// A real number in [lo, hi] (hi − lo must be finite).
    template <class T>
    T real(T lo, T hi) {
        static_assert(std::is_floating_point_v<T>);
        const T t = static_cast<T>(static_cast<double>(bits(4)) / 4294967295.0);
        const T v = lo + (hi - lo) * t;
        return v > hi ? hi : v;
    }

    /// Any float: one byte chooses NaN, ±infinity, a huge, tiny or negative
    /// zero value, or the raw bits of the next four bytes.
    float anyFloat() {
        switch (bits(1) % 8) {
            case 0: return std::numeric_limits<float>::quiet_NaN();
            case 1: return std::numeric_limits<float>::infinity();
            case 2: return -std::numeric_limits<float>::infinity();
            case 3: return flag() ? 1.0e30f : -1.0e30f;
            case 4: return std::numeric_limits<float>::denorm_min();
            case 5: return -0.0f;
            default: {
                const std::uint32_t u = static_cast<std::uint32_t>(bits(4));
                float f;
                std::memcpy(&f, &u, sizeof f);
                return f;
            }
        }
    }

    /// Any double, chosen like anyFloat.
    double anyDouble() {
        switch (bits(1) % 8) {
            case 0: return std::numeric_limits<double>::quiet_NaN();
            case 1: return std::numeric_limits<double>::infinity();
            case 2: return -std::numeric_limits<double>::infinity();
            case 3: return flag() ? 1.0e300 : -1.0e300;
            case 4: return std::numeric_limits<double>::denorm_min();
            case 5: return -0.0;
            default: {
                const std::uint64_t u = bits(8);
                double d;
                std::memcpy(&d, &u, sizeof d);
                return d;
            }
        }
    }

private:
    // The next `count` bytes (1–8) as a little-endian integer.
    std::uint64_t bits(int count) {
        std::uint64_t v = 0;
        for (int i = 0; i < count && pos_ < size_; ++i) v |= static_cast<std::uint64_t>(data_[pos_++]) << (8 * i);
        return v;
    }

    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

}  // namespace i2d::fuzz
