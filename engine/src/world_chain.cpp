// World: the public API facade for chains — the checks of a chain's points,
// then one segment shape per pair of consecutive points, each knowing its
// neighbours' far points (ghost vertices). Collision of chain segments:
// seams.cpp (smooth, one-sided) and continuous.cpp (one-sided).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "impulse2d/world.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;

namespace {

// Geometry of the checks in double precision: points may be 1e7 m from the
// origin, where a float cannot resolve the 5 mm slop.
struct P {
    double x, y;
};
P toP(Vec2 v) { return {v.x, v.y}; }
double crossP(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double pointSegmentDistance(P p, P a, P b) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double len2 = ex * ex + ey * ey;
    double t = len2 > 0.0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * ex), p.y - (a.y + t * ey));
}

/// Distance between segments ab and cd (0 when they cross).
double segmentsDistance(P a, P b, P c, P d) {
    const double d1 = crossP(a, b, c), d2 = crossP(a, b, d), d3 = crossP(c, d, a), d4 = crossP(c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
    return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                     pointSegmentDistance(d, a, b)});
}

void validateChain(const ChainDef& def) {
    const std::size_t n = def.points.size();
    if (n < 2) fail("a chain needs at least 2 points (got " + std::to_string(n) + ")");
    if (def.isLoop && n < 3) fail("a chain loop needs at least 3 points (got " + std::to_string(n) + ")");
    detail::requireInRange(def.friction, 0.0f, detail::kMaxFriction, "chain friction");
    detail::requireUnitInterval(def.restitution, "chain restitution");
    for (std::size_t i = 0; i < n; ++i) detail::requireBounded(def.points[i], "chain point");
    const std::size_t segments = def.isLoop ? n : n - 1;
    auto at = [&](std::size_t i) { return toP(def.points[i % n]); };
    for (std::size_t i = 0; i < segments; ++i) {
        if (std::hypot(at(i + 1).x - at(i).x, at(i + 1).y - at(i).y) <= kLinearSlop)
            fail("chain points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                 " are no more than the linear slop (0.005 m) apart");
    }
    // Folding back: a segment's far point on (or within the slop of) the
    // segment before it.
    const std::size_t joints = def.isLoop ? segments : segments - 1;
    for (std::size_t i = 0; i < joints; ++i) {
        if (pointSegmentDistance(at(i + 2), at(i), at(i + 1)) <= kLinearSlop ||
            pointSegmentDistance(at(i), at(i + 1), at(i + 2)) <= kLinearSlop)
            fail("chain folds back on itself at point " + std::to_string((i + 1) % n));
    }
    // Crossing or touching: every pair of segments that are not neighbours,
    // found by sweeping their boxes (grown by the slop) along x, so that a
    // terrain of 100,000 points is checked in a fraction of a second (testing
    // every pair took 58 s at 64,000). The pair reported is the first in
    // segment order, as a test of every pair would find it.
    struct Extent {
        double lowX, highX, lowY, highY;
        std::size_t segment;
    };
    std::vector<Extent> extents(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const P a = at(i), b = at(i + 1);
        extents[i] = {std::min(a.x, b.x) - kLinearSlop, std::max(a.x, b.x) + kLinearSlop,
                      std::min(a.y, b.y) - kLinearSlop, std::max(a.y, b.y) + kLinearSlop, i};
    }
    std::sort(extents.begin(), extents.end(), [](const Extent& l, const Extent& r) {
        return l.lowX < r.lowX || (l.lowX == r.lowX && l.segment < r.segment);
    });
    std::size_t firstI = segments, firstJ = segments;
    for (std::size_t k = 0; k < segments; ++k) {
        const Extent& e = extents[k];
        for (std::size_t m = k + 1; m < segments && extents[m].lowX <= e.highX; ++m) {
            const Extent& f = extents[m];
            if (f.lowY > e.highY || e.lowY > f.highY) continue;
            const std::size_t i = std::min(e.segment, f.segment), j = std::max(e.segment, f.segment);
            if (j == i + 1) continue;                                 // neighbours
            if (def.isLoop && i == 0 && j == segments - 1) continue;  // the loop's closing neighbours
            if (i > firstI || (i == firstI && j >= firstJ)) continue;
            if (segmentsDistance(at(i), at(i + 1), at(j), at(j + 1)) <= kLinearSlop) firstI = i, firstJ = j;
        }
    }
    if (firstI < segments)
        fail("chain crosses or touches itself: segments " + std::to_string(firstI) + " and " + std::to_string(firstJ) +
             " come within the linear slop (0.005 m)");
}

}  // namespace

std::vector<ShapeId> World::createChain(BodyId bodyId, const ChainDef& def) {
    auto& w = state();
    w.checkUnlocked();
    const int b = w.bodyIndex(bodyId);
    validateChain(def);
    const std::size_t n = def.points.size();
    const std::size_t segments = def.isLoop ? n : n - 1;
    ShapeDef sd;
    sd.density = 0.0f;
    sd.friction = def.friction;
    sd.restitution = def.restitution;
    sd.filter = def.filter;
    sd.enableContactEvents = def.enableContactEvents;
    sd.userData = def.userData;
    std::vector<ShapeId> ids;
    ids.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        detail::ShapeGeometry g;
        g.segment = {def.points[i], def.points[(i + 1) % n]};
        const int s = detail::createShape(w, b, sd, ShapeType::segment, g, false);
        detail::Shape& shape = w.shapes[s];
        shape.chainSegment = true;
        const bool first = i == 0, last = i + 1 == segments;
        shape.ghost1 = (first && !def.isLoop) ? g.segment.point1 : def.points[(i + n - 1) % n];
        shape.ghost2 = (last && !def.isLoop) ? g.segment.point2 : def.points[(i + 2) % n];
        ids.push_back(w.shapeHandle(s));
    }
    // Once for the whole chain: per segment, the body's mass pass over all
    // its shapes made a chain of 100,000 points take minutes to create.
    detail::updateMass(w, b);
    return ids;
}

bool World::isChainSegment(ShapeId id) const { return state().shapes[state().shapeIndex(id)].chainSegment; }

ChainSegment World::shapeChainSegment(ShapeId id) const {
    const detail::Shape& s = state().shapes[state().shapeIndex(id)];
    if (!s.chainSegment) fail("shape is not a chain segment");
    return {s.geometry.segment, s.ghost1, s.ghost2};
}

}  // namespace i2d
