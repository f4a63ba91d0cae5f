// Memory per body and per touching contact, Impulse2D and Box2D 2.4.1 in the
// same run (the figures of docs/performance.md's memory table, without the
// rest of the sweep), plus what Impulse2D allocates on top of that within a
// step (its per-step arrays, freed when the step ends when large). The peak is tracked
// through operator new, which Impulse2D's containers use; Box2D 2.4.1
// allocates through malloc, so it has no peak column.
//
// Usage: memory_footprint [BODIES]   (default 10000)
#include <cstdio>
#include <cstdlib>
#include <new>

#include "footprint.hpp"

namespace {
std::size_t g_newBytes = 0;  // bytes currently allocated through operator new
std::size_t g_newPeak = 0;
}  // namespace

void* operator new(std::size_t n) {
    void* p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    g_newBytes += malloc_usable_size(p);
    if (g_newBytes > g_newPeak) g_newPeak = g_newBytes;
    return p;
}
void operator delete(void* p) noexcept {
    if (!p) return;
    g_newBytes -= malloc_usable_size(p);
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace {

struct Held {
    std::size_t held = 0;      ///< heap growth from before building to after the steps (mallinfo2)
    std::size_t stepPeak = 0;  ///< most operator-new bytes above the built world's during the steps
    int contacts = 0;
};

Held measure(const tb::SceneDesc& desc, tb::EngineKind kind) {
    Held h;
    const std::size_t before = bench::heapInUse();
    auto sim = tb::makeSimulation(desc, kind);
    const std::size_t built = g_newBytes;
    g_newPeak = g_newBytes;
    for (int i = 0; i < 2; ++i) sim->step(desc.dt);
    h.stepPeak = g_newPeak - built;
    const std::size_t after = bench::heapInUse();
    h.held = after > before ? after - before : 0;
    h.contacts = sim->touchingContactCount();
    return h;
}

}  // namespace

int main(int argc, char** argv) {
    const int bodies = argc > 1 ? std::atoi(argv[1]) : 10000;
    if (bodies < 10) {
        std::fprintf(stderr, "usage: memory_footprint [BODIES >= 10]\n");
        return 2;
    }
    std::printf("engine,bytes_per_body,bytes_per_touching_contact,bodies,touching_contacts,"
                "step_peak_bytes_per_body,step_peak_bytes_per_touching_contact\n");
    for (tb::EngineKind kind : {tb::EngineKind::impulse2d, tb::EngineKind::box2d}) {
        const tb::SceneDesc scatteredDesc = bench::columnsScene(bodies, false);
        const tb::SceneDesc columnsDesc = bench::columnsScene(bodies, true);
        const Held scattered = measure(scatteredDesc, kind);
        const Held columns = measure(columnsDesc, kind);
        const int contacts = columns.contacts;
        const auto perContact = [&](std::size_t a, std::size_t b) {
            return contacts > 0 ? (static_cast<double>(a) - static_cast<double>(b)) / contacts : 0.0;
        };
        std::printf("%s,%.0f,%.0f,%d,%d", tb::engineName(kind), static_cast<double>(scattered.held) / bodies,
                    perContact(columns.held, scattered.held), bodies, contacts);
        if (kind == tb::EngineKind::impulse2d)
            std::printf(",%.0f,%.0f\n", static_cast<double>(scattered.stepPeak) / bodies,
                        perContact(columns.stepPeak, scattered.stepPeak));
        else
            std::printf(",,\n");
    }
    return 0;
}
