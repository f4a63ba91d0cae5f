// The slot array's live slots, listed from its free list (appendLiveSlots),
// against the slots' own flags, while slots are freed and reused at random.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "slot_array.hpp"

namespace {

struct Item {
    bool alive = false;
    std::uint32_t generation = 0;
};

std::vector<int> liveByFlags(const i2d::detail::SlotArray<Item>& a) {
    std::vector<int> live;
    for (int i = 0; i < a.capacity(); ++i)
        if (a[i].alive) live.push_back(i);
    return live;
}

}  // namespace

TEST(SlotArray, LiveSlotsFromTheFreeListAreTheLiveFlagsInOrder) {
    i2d::detail::SlotArray<Item> a;
    std::vector<std::uint8_t> marks;
    std::vector<int> live;
    // Empty, then full (no free slot: the shortcut), then freed and reused.
    i2d::detail::appendLiveSlots(a, marks, live);
    EXPECT_TRUE(live.empty());
    for (int i = 0; i < 100; ++i) a.allocate();
    live.clear();
    i2d::detail::appendLiveSlots(a, marks, live);
    EXPECT_EQ(live, liveByFlags(a));
    std::mt19937 rng(7);
    for (int round = 0; round < 200; ++round) {
        const int index = std::uniform_int_distribution<int>(0, a.capacity() - 1)(rng);
        if (a[index].alive && round % 3 != 0)
            a.release(index);
        else
            a.allocate();
        // Appended after what the list already holds, as the narrowphase's rounds do.
        live.assign(1, -5);
        i2d::detail::appendLiveSlots(a, marks, live);
        std::vector<int> expected{-5};
        for (const int i : liveByFlags(a)) expected.push_back(i);
        ASSERT_EQ(live, expected) << "round " << round;
    }
    EXPECT_FALSE(a.freeSlots.empty());  // the rounds did free slots
}
