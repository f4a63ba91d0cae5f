// Fuzz target: the closed-form impact law. Valid input gives finite
// velocities and never more kinetic energy than before (Stronge's energetic
// restitution); invalid input throws i2d::Error.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"

using namespace i2d;

namespace {

double energy(const ImpactBody& b, Vec2d v, double w) {
    double e = 0.0;
    if (b.invMass > 0.0) e += 0.5 * (v.x * v.x + v.y * v.y) / b.invMass;
    if (b.invInertia > 0.0) e += 0.5 * w * w / b.invInertia;
    return e;
}

ImpactBody body(fuzz::ByteReader& in, bool raw) {
    ImpactBody b;
    if (raw) {
        b.invMass = in.anyDouble();
        b.invInertia = in.anyDouble();
        b.r = {in.anyDouble(), in.anyDouble()};
        b.v = {in.anyDouble(), in.anyDouble()};
        b.w = in.anyDouble();
        return b;
    }
    // Either immovable, or masses from 1 g to 1000 t and lever arms up to 10 m.
    if (!in.flag()) {
        b.invMass = in.flag() ? 0.0 : std::pow(10.0, in.real(-3.0, 3.0));
        b.invInertia = in.flag() ? 0.0 : std::pow(10.0, in.real(-4.0, 4.0));
    }
    b.r = {in.real(-10.0, 10.0), in.real(-10.0, 10.0)};
    b.v = {in.real(-100.0, 100.0), in.real(-100.0, 100.0)};
    b.w = in.real(-100.0, 100.0);
    // Infinite mass does not move and infinite inertia does not turn here:
    // such a body moving anyway (a kinematic pusher) holds unbounded energy
    // and may rightly give some to the other, which the energy check forbids.
    if (b.invMass == 0.0) b.v = {};
    if (b.invInertia == 0.0) b.w = 0.0;
    return b;
}

// The input, printed before a property check fails.
void dump(const ImpactInput& in) {
    auto body = [](const char* name, const ImpactBody& b) {
        std::fprintf(stderr, "%s: invMass %.17g invInertia %.17g r (%.17g, %.17g) v (%.17g, %.17g) w %.17g\n", name,
                     b.invMass, b.invInertia, b.r.x, b.r.y, b.v.x, b.v.y, b.w);
    };
    std::fprintf(stderr, "e %.17g mu %.17g normal (%.17g, %.17g)\n", in.restitution, in.friction, in.normal.x,
                 in.normal.y);
    body("a", in.a);
    body("b", in.b);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::ByteReader in(data, size);
    const bool raw = in.flag();
    ImpactInput input;
    if (raw) {
        input.restitution = in.anyDouble();
        input.friction = in.anyDouble();
        input.normal = {in.anyDouble(), in.anyDouble()};
    } else {
        input.restitution = in.real(0.0, 1.0);
        input.friction = in.real(0.0, 2.0);
        const double angle = in.real(-4.0, 4.0);
        input.normal = {std::cos(angle), std::sin(angle)};
    }
    input.a = body(in, raw);
    input.b = body(in, raw);
    ImpactResult out;
    try {
        out = resolveImpact(input);
    } catch (const Error& e) {
        // Only input outside the documented domain may be refused: both
        // bodies immovable, or a singular collision matrix, which needs both
        // inverse masses to be zero.
        const bool allowed = raw || (input.a.invMass == 0.0 && input.b.invMass == 0.0);
        if (!allowed) {
            std::fprintf(stderr, "refused: %s\n", e.what());
            dump(input);
        }
        I2D_FUZZ_CHECK(allowed);
        return 0;
    }
    if (raw) return 0;
    I2D_FUZZ_CHECK(std::isfinite(out.vA.x) && std::isfinite(out.vA.y) && std::isfinite(out.wA));
    I2D_FUZZ_CHECK(std::isfinite(out.vB.x) && std::isfinite(out.vB.y) && std::isfinite(out.wB));
    const double before = energy(input.a, input.a.v, input.a.w) + energy(input.b, input.b.v, input.b.w);
    const double after = energy(input.a, out.vA, out.wA) + energy(input.b, out.vB, out.wB);
    // Relative 1e-9 of double round-off over a few dozen operations on
    // energies up to ~1e10 J; the law itself never adds energy.
    if (!(after <= before * (1.0 + 1.0e-9) + 1.0e-9)) {
        std::fprintf(stderr, "energy before %.17g after %.17g, case %s\n", before, after, toString(out.kind));
        dump(input);
    }
    I2D_FUZZ_CHECK(after <= before * (1.0 + 1.0e-9) + 1.0e-9);
    return 0;
}
