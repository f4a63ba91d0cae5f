// A growable array of objects addressed by slot index, with a free list and
// a generation per slot (the generation goes into handles, see id.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace i2d::detail {

inline constexpr int kNullIndex = -1;

/// The capacity a persistent per-object array (bodies, shapes, contacts,
/// broadphase nodes and boxes) grows to when it is full: an eighth more than
/// it holds. Such arrays are most of what a world keeps, and half again or
/// double, as vectors grow, left up to a third or a half of them unused (a
/// world of 7,000 bodies held slots for 10,374; docs/performance.md,
/// "Memory"). Each element is moved about eight times on its way to a large
/// world instead of two or three: paid once while the world is built.
inline std::size_t grownCapacity(std::size_t size) { return size + size / 8 + 16; }

/// T has `bool alive` and `std::uint32_t generation`. Freed slots are reused
/// last-freed first. The storage grows by an eighth when full (grownCapacity),
/// not by std::vector's doubling.
template <class T>
struct SlotArray {
    std::vector<T> items;
    std::vector<int> freeSlots;
    int count = 0;

    int allocate() {
        int i;
        if (!freeSlots.empty()) {
            i = freeSlots.back();
            freeSlots.pop_back();
            std::uint32_t gen = items[static_cast<std::size_t>(i)].generation;
            items[static_cast<std::size_t>(i)] = T{};
            items[static_cast<std::size_t>(i)].generation = gen;
        } else {
            if (items.size() == items.capacity()) items.reserve(grownCapacity(items.size()));
            items.emplace_back();
            i = static_cast<int>(items.size()) - 1;
        }
        items[static_cast<std::size_t>(i)].alive = true;
        ++count;
        return i;
    }
    void release(int i) {
        T& t = items[static_cast<std::size_t>(i)];
        t.alive = false;
        ++t.generation;
        if (t.generation == 0) t.generation = 1;
        freeSlots.push_back(i);
        --count;
    }
    T& operator[](int i) { return items[static_cast<std::size_t>(i)]; }
    const T& operator[](int i) const { return items[static_cast<std::size_t>(i)]; }
    int capacity() const { return static_cast<int>(items.size()); }
};

/// Appends to `out`, in ascending order, every index whose byte in `marks` is set.
inline void appendMarked(const std::vector<std::uint8_t>& marks, std::vector<int>& out) {
    const int n = static_cast<int>(marks.size());
    for (int i = 0; i < n; ++i)
        if (marks[static_cast<std::size_t>(i)] != 0) out.push_back(i);
}

/// Appends every live slot of `a` to `out`, in ascending order, found from
/// the free list: the items are not read (in a large world each read was a
/// cache miss: scanning the contacts' flags on the stepping thread was half
/// of the narrowphase's own samples on pyramid100). `marks` is scratch.
template <class T>
void appendLiveSlots(const SlotArray<T>& a, std::vector<std::uint8_t>& marks, std::vector<int>& out) {
    const int n = a.capacity();
    if (a.freeSlots.empty()) {
        for (int i = 0; i < n; ++i) out.push_back(i);
        return;
    }
    marks.assign(static_cast<std::size_t>(n), 1);
    for (const int f : a.freeSlots) marks[static_cast<std::size_t>(f)] = 0;
    appendMarked(marks, out);
}

}  // namespace i2d::detail
