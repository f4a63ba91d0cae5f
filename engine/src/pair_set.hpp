// The set of shape pairs that have a contact, keyed by the two shape slots.
//
// Open addressing with linear probing over a power-of-two table, at most half
// full, and deletion by backward shift (no tombstones, so lookups stay short
// however many pairs come and go). 8 bytes a slot: 16 to 32 bytes a pair,
// where a node-based std::unordered_map takes about 48.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace i2d::detail {

/// Key of an unordered pair of shape slots (the same whichever comes first).
inline std::uint64_t pairKey(int a, int b) {
    auto lo = static_cast<std::uint64_t>(std::min(a, b));
    auto hi = static_cast<std::uint64_t>(std::max(a, b));
    return (hi << 32) | lo;
}

class PairSet {
public:
    bool contains(std::uint64_t key) const {
        if (slots_.empty()) return false;
        for (std::size_t i = home(key);; i = next(i)) {
            if (slots_[i] == kEmpty) return false;
            if (slots_[i] == key) return true;
        }
    }

    /// Adds the key (no effect when present).
    void insert(std::uint64_t key) {
        if (2 * (count_ + 1) > slots_.size()) grow();
        std::size_t i = home(key);
        for (; slots_[i] != kEmpty; i = next(i))
            if (slots_[i] == key) return;
        slots_[i] = key;
        ++count_;
    }

    /// Removes the key (no effect when absent).
    void erase(std::uint64_t key) {
        if (slots_.empty()) return;
        std::size_t i = home(key);
        for (; slots_[i] != key; i = next(i))
            if (slots_[i] == kEmpty) return;
        // Backward shift: move later members of the probe run into the hole
        // when the hole lies on their way from their home slot.
        std::size_t hole = i;
        for (std::size_t j = next(hole); slots_[j] != kEmpty; j = next(j)) {
            const std::size_t h = home(slots_[j]);
            const bool between = hole <= j ? (h <= hole || h > j) : (h <= hole && h > j);
            if (between) {
                slots_[hole] = slots_[j];
                hole = j;
            }
        }
        slots_[hole] = kEmpty;
        --count_;
    }

    std::size_t size() const { return count_; }

private:
    // Shape slots are below 2^31, so no key has every bit set.
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    std::size_t home(std::uint64_t key) const {
        // Fibonacci hashing: the high bits of key·2^64/φ spread neighbouring keys.
        return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
    }
    std::size_t next(std::size_t i) const { return (i + 1) & (slots_.size() - 1); }

    void grow() {
        std::vector<std::uint64_t> old = std::move(slots_);
        const std::size_t size = old.empty() ? 64 : 2 * old.size();
        slots_.assign(size, kEmpty);
        shift_ = 64;
        for (std::size_t s = size; s > 1; s >>= 1) --shift_;
        count_ = 0;
        for (std::uint64_t key : old)
            if (key != kEmpty) insert(key);
    }

    std::vector<std::uint64_t> slots_;
    std::size_t count_ = 0;
    int shift_ = 64;
};

}  // namespace i2d::detail
