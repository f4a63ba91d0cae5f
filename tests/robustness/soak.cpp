// Soak: runs shipped scenes for a long simulated time and checks that no
// state becomes non-finite and that memory stops growing once the scene is
// warmed up. Prints one line per checkpoint and a summary; exits non-zero on
// non-finite state or when the resident set grows by more than the allowed
// amount after warm-up.
//
// With --max-sway M it also fails when a body named "top" ever moves more
// than M metres sideways from where it started (a column that must stand).
//
// Usage: soak [--seconds S (3600)] [--sleep on|off] [--max-sway M] [--assets DIR] SCENE...
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

// Resident set size in KiB (Linux /proc; 0 elsewhere).
long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0;
    long resident = 0;
    if (!(statm >> pages >> resident)) return 0;
    return resident * 4;  // 4 KiB pages
}

bool finiteWorld(const i2d::World& world) {
    for (i2d::BodyId b : world.bodies()) {
        if (!i2d::isFinite(world.position(b)) || !i2d::isFinite(world.linearVelocity(b)) ||
            !std::isfinite(world.angularVelocity(b)) || !std::isfinite(world.angle(b)))
            return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 3600.0;
    bool sleepOff = false;
    double maxSwayAllowed = -1.0;
    std::string assets;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else if (a == "--sleep" && i + 1 < argc) {
            sleepOff = std::string(argv[++i]) == "off";
        } else if (a == "--max-sway" && i + 1 < argc) {
            maxSwayAllowed = std::atof(argv[++i]);
        } else if (a == "--assets" && i + 1 < argc) {
            assets = argv[++i];
        } else {
            scenes.push_back(a);
        }
    }
    if (scenes.empty() || !(seconds > 0.0)) {
        std::fprintf(stderr, "usage: soak [--seconds S] [--sleep on|off] [--max-sway M] [--assets DIR] SCENE...\n");
        return 2;
    }
    // Allowed growth of the resident set after warm-up (the first 10% of the
    // run): 1 MiB — page-granular noise of the allocator, far below one byte per step.
    const long allowedGrowthKiB = 1024;
    int failures = 0;
    for (const std::string& name : scenes) {
        tb::SceneDesc desc = tb::loadSceneDesc(name, assets);
        if (sleepOff) desc.settings.enableSleep = false;
        tb::Scene scene = tb::buildScene(desc);
        const long steps = std::lround(seconds / desc.dt);
        const long warmup = std::max(1L, steps / 10);
        long warmKiB = 0;
        long peakKiB = 0;
        long startKiB = residentKiB();
        bool finite = true;
        const auto topIt = scene.named.find("top");
        const bool hasTop = topIt != scene.named.end();
        const float x0 = hasTop ? scene.world->position(topIt->second).x : 0.0f;
        double maxSway = 0.0;
        for (long s = 1; s <= steps && finite; ++s) {
            scene.world->step(desc.dt);
            if (hasTop) maxSway = std::max(maxSway, double(std::abs(scene.world->position(topIt->second).x - x0)));
            if (s % 600 == 0 || s == steps || s == warmup) {
                finite = finiteWorld(*scene.world);
                long rss = residentKiB();
                if (s == warmup) warmKiB = rss;
                peakKiB = std::max(peakKiB, rss);
            }
            if (s % (steps / 10 > 0 ? steps / 10 : 1) == 0)
                std::printf("%s: %.0f s simulated, %d awake, RSS %ld KiB\n", name.c_str(), s * desc.dt,
                            scene.world->awakeBodyCount(), residentKiB());
        }
        const long endKiB = residentKiB();
        const bool grew = endKiB - warmKiB > allowedGrowthKiB;
        std::printf(
            "%s: %ld steps (%.0f s), sleep %s, finite %s, RSS start %ld KiB, after warm-up %ld KiB, end %ld KiB, peak %ld KiB%s\n",
            name.c_str(), steps, steps * desc.dt, desc.settings.enableSleep ? "on" : "off", finite ? "yes" : "NO",
            startKiB, warmKiB, endKiB, peakKiB, grew ? "  GREW" : "");
        const bool swayed = hasTop && maxSwayAllowed >= 0.0 && maxSway > maxSwayAllowed;
        if (hasTop)
            std::printf("%s: top box swayed at most %.4f m%s\n", name.c_str(), maxSway, swayed ? "  TOO FAR" : "");
        std::fflush(stdout);
        if (!finite || grew || swayed) ++failures;
    }
    return failures == 0 ? 0 : 1;
}
