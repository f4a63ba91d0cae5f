// Memory per body and per touching contact, Impulse2D and Box2D 2.4.1 in the
// same run (the figures of docs/performance.md's memory table, without the
// rest of the sweep). Also the largest per-step solver arrays Impulse2D holds
// between steps, for the record.
//
// Usage: memory_footprint [BODIES]   (default 10000)
#include <cstdio>
#include <cstdlib>

#include "footprint.hpp"

int main(int argc, char** argv) {
    const int bodies = argc > 1 ? std::atoi(argv[1]) : 10000;
    if (bodies < 10) {
        std::fprintf(stderr, "usage: memory_footprint [BODIES >= 10]\n");
        return 2;
    }
    std::printf("engine,bytes_per_body,bytes_per_touching_contact,bodies,touching_contacts\n");
    for (tb::EngineKind kind : {tb::EngineKind::impulse2d, tb::EngineKind::box2d}) {
        int contacts = 0;
        const std::size_t scattered = bench::heldBytes(bench::columnsScene(bodies, false), kind, 2, nullptr);
        const std::size_t columns = bench::heldBytes(bench::columnsScene(bodies, true), kind, 2, &contacts);
        const double perBody = static_cast<double>(scattered) / bodies;
        const double perContact =
            contacts > 0 ? (static_cast<double>(columns) - static_cast<double>(scattered)) / contacts : 0.0;
        std::printf("%s,%.0f,%.0f,%d,%d\n", tb::engineName(kind), perBody, perContact, bodies, contacts);
    }
    return 0;
}
