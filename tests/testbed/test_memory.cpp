// Memory a world holds between steps, per body and per touching contact, at
// or below Box2D 2.4.1's measured the same way in the same process (the
// bodies and columns of tests/benchmark/footprint.hpp, as memory_footprint
// and docs/performance.md's memory table measure them). Read from glibc's
// heap counters, not timed: the figures are the same on every run of a build.
#include <gtest/gtest.h>

#include <cstdio>

#include "../benchmark/footprint.hpp"

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitizedHeap = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
constexpr bool kSanitizedHeap = true;
#else
constexpr bool kSanitizedHeap = false;
#endif
#else
constexpr bool kSanitizedHeap = false;
#endif

struct PerObject {
    double perBody = 0.0, perContact = 0.0;
    int contacts = 0;
};

PerObject measure(tb::EngineKind engine, int bodies) {
    PerObject m;
    const std::size_t scattered = bench::heldBytes(bench::columnsScene(bodies, false), engine, 2, nullptr);
    const std::size_t columns = bench::heldBytes(bench::columnsScene(bodies, true), engine, 2, &m.contacts);
    m.perBody = static_cast<double>(scattered) / bodies;
    m.perContact = (static_cast<double>(columns) - static_cast<double>(scattered)) / m.contacts;
    return m;
}

TEST(Memory, PerBodyAndPerTouchingContactAtOrBelowBox2D) {
    if (kSanitizedHeap) GTEST_SKIP() << "the sanitizer's allocator keeps a heap of its own";
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    if (bench::heapInUse() == 0) GTEST_SKIP() << "no glibc heap counters (mallinfo2)";
    // From 500 bodies to 20,000: both engines' arrays grow in steps, so each
    // count lands at another point of their growth (Box2D 2.4.1's figures
    // range from 628 to 817 bytes a body over these counts).
    for (const int bodies : {500, 1000, 2000, 5000, 7000, 10000, 20000}) {
        const PerObject ours = measure(tb::EngineKind::impulse2d, bodies);
        const PerObject box2d = measure(tb::EngineKind::box2d, bodies);
        SCOPED_TRACE(bodies);
        ASSERT_EQ(ours.contacts, bodies);  // one touching contact below each box
        ASSERT_EQ(box2d.contacts, bodies);
        EXPECT_LE(ours.perBody, box2d.perBody);
        EXPECT_LE(ours.perContact, box2d.perContact);
        std::printf("%d bodies: Impulse2D %.0f B per body, %.0f per touching contact; Box2D 2.4.1 %.0f and %.0f\n",
                    bodies, ours.perBody, ours.perContact, box2d.perBody, box2d.perContact);
    }
}

}  // namespace
