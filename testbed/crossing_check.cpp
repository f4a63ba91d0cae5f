// Testbed — tunnelling and snag counts (see crossing_check.hpp).
#include "crossing_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tb {

namespace {

i2d::Transform poseOf(const BodySample& s) { return {{s.x, s.y}, i2d::makeRot(s.angle)}; }

std::optional<i2d::RayHit> castSolid(const ShapeDesc& shape, const i2d::RayCastInput& ray) {
    switch (shape.type) {
        case i2d::ShapeType::circle: return i2d::rayCast(ray, shape.circle);
        case i2d::ShapeType::capsule: return i2d::rayCast(ray, shape.capsule);
        case i2d::ShapeType::polygon: return i2d::rayCast(ray, shape.polygon);
        case i2d::ShapeType::segment: break;
    }
    return std::nullopt;
}

/// The segments of a segment shape or a chain.
std::vector<i2d::Segment> segmentsOf(const ShapeDesc& shape) {
    if (!shape.chain) return {shape.segment};
    std::vector<i2d::Segment> out;
    const std::size_t n = shape.chainPoints.size();
    const std::size_t count = shape.chainLoop ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k) out.push_back({shape.chainPoints[k], shape.chainPoints[(k + 1) % n]});
    return out;
}

/// Signed distance of p beyond the segment's line, seen from the side `from`
/// (positive: on the other side), and whether p projects onto the segment.
float beyond(const i2d::Segment& s, i2d::Vec2 from, i2d::Vec2 p, bool& within) {
    const i2d::Vec2 e = s.point2 - s.point1;
    const float len = i2d::length(e);
    const i2d::Vec2 n = i2d::leftPerp(e) * (1.0f / len);
    const float t = i2d::dot(p - s.point1, e) / (len * len);
    within = t >= 0.0f && t <= 1.0f;
    const float side = i2d::dot(from, n) >= 0.0f ? 1.0f : -1.0f;  // from's side of the line
    return -side * i2d::dot(p - s.point1, n);
}

bool collides(const BodyDesc& mover, const ShapeDesc& other) {
    if (other.def.isSensor) return false;
    for (const ShapeDesc& s : mover.shapes)
        if (!s.def.isSensor && i2d::shouldCollide(s.def.filter, other.def.filter)) return true;
    return false;
}

bool jointed(const SceneDesc& desc, int a, int b) {
    for (const JointDesc& j : desc.joints)
        if ((j.bodyA == a && j.bodyB == b) || (j.bodyA == b && j.bodyB == a)) return true;
    return false;
}

}  // namespace

CrossingCheck::CrossingCheck(const SceneDesc& desc) : desc_(desc) {
    for (std::size_t i = 0; i < desc.bodies.size(); ++i) {
        const BodyDesc& b = desc.bodies[i];
        const int index = static_cast<int>(i);
        if (b.def.type == i2d::BodyType::static_body && !b.shapes.empty()) statics_.push_back(index);
        if (b.def.type == i2d::BodyType::dynamic_body && b.def.isBullet) bullets_.push_back(index);
        if (b.driveSpeed) driven_.push_back(index);
    }
    tunnelledBody_.assign(desc.bodies.size(), 0);
    snaggedBody_.assign(desc.bodies.size(), 0);
}

void CrossingCheck::start(const Simulation& sim) {
    previous_.clear();
    for (int i = 0; i < sim.bodyCount(); ++i) previous_.push_back(sim.sample(i));
}

void CrossingCheck::observe(const Simulation& sim) {
    ++steps_;
    const int n = std::min(sim.bodyCount(), static_cast<int>(desc_.bodies.size()));
    std::vector<BodySample> now;
    now.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) now.push_back(sim.sample(i));

    auto crossed = [&](int mover, int other, const i2d::Transform& before, const i2d::Transform& after) {
        const BodySample& p = previous_[static_cast<std::size_t>(mover)];
        const BodySample& c = now[static_cast<std::size_t>(mover)];
        const i2d::Vec2 a = i2d::invTransformPoint(before, {p.cx, p.cy});
        const i2d::Vec2 b = i2d::invTransformPoint(after, {c.cx, c.cy});
        const std::vector<ShapeDesc>& shapes = desc_.bodies[static_cast<std::size_t>(other)].shapes;
        for (std::size_t k = 0; k < shapes.size(); ++k)
            if (collides(desc_.bodies[static_cast<std::size_t>(mover)], shapes[k]) &&
                passes(mover, other, static_cast<int>(k), a, b))
                return true;
        return false;
    };

    for (int i = 0; i < n; ++i) {
        const BodySample& c = now[static_cast<std::size_t>(i)];
        if (!c.dynamic || tunnelledBody_[static_cast<std::size_t>(i)]) continue;
        bool hit = false;
        for (int s : statics_) {
            if (s >= n || jointed(desc_, i, s)) continue;
            const i2d::Transform xf = poseOf(now[static_cast<std::size_t>(s)]);
            if ((hit = crossed(i, s, xf, xf))) break;
        }
        if (!hit && std::find(bullets_.begin(), bullets_.end(), i) != bullets_.end()) {
            for (int j = 0; j < n && !hit; ++j) {
                const BodyDesc& o = desc_.bodies[static_cast<std::size_t>(j)];
                if (j == i || o.def.type != i2d::BodyType::dynamic_body || o.def.isBullet || jointed(desc_, i, j))
                    continue;
                hit = crossed(i, j, poseOf(previous_[static_cast<std::size_t>(j)]),
                              poseOf(now[static_cast<std::size_t>(j)]));
            }
        }
        if (hit) {
            tunnelledBody_[static_cast<std::size_t>(i)] = 1;
            ++tunnelledCount_;
        }
    }
    if (steps_ > 5) {
        for (int i : driven_) {
            if (i >= n) continue;
            const BodySample& c = now[static_cast<std::size_t>(i)];
            const float drive = *desc_.bodies[static_cast<std::size_t>(i)].driveSpeed;
            drivenMaxVy_ = std::max(drivenMaxVy_, std::abs(c.vy));
            if (!snaggedBody_[static_cast<std::size_t>(i)] && std::abs(c.vx) < 0.5f * std::abs(drive)) {
                snaggedBody_[static_cast<std::size_t>(i)] = 1;
                ++snaggedCount_;
            }
        }
    }
    previous_ = std::move(now);
}

bool CrossingCheck::passes(int mover, int body, int k, i2d::Vec2 a, i2d::Vec2 b) {
    const ShapeDesc& shape = desc_.bodies[static_cast<std::size_t>(body)].shapes[static_cast<std::size_t>(k)];
    auto state = std::find_if(insides_.begin(), insides_.end(),
                              [&](const Inside& in) { return in.mover == mover && in.body == body && in.shape == k; });
    if (shape.type == i2d::ShapeType::segment) {
        const std::vector<i2d::Segment> segments = segmentsOf(shape);
        if (state != insides_.end()) {
            // Past a segment since an earlier step: through once kBeyond past it, forgotten once back.
            const i2d::Segment& s = segments[static_cast<std::size_t>(state->segment)];
            bool within = false;
            const float d = beyond(s, state->entryNormal, b, within);
            if (d <= 0.0f || !within) {
                insides_.erase(state);
                return false;
            }
            if (d > kBeyond) {
                insides_.erase(state);
                return true;
            }
            return false;
        }
        i2d::RayCastInput ray{a, b - a, 1.0f};
        for (std::size_t j = 0; j < segments.size(); ++j) {
            const i2d::Segment& s = segments[j];
            // A chain is crossed only from its colliding (right) side.
            if (shape.chain && i2d::cross(s.point2 - s.point1, a - s.point1) >= 0.0f) continue;
            if (!i2d::rayCast(ray, s)) continue;
            bool within = false;
            const i2d::Vec2 from = a - s.point1;  // kept as the side it came from
            if (beyond(s, from, b, within) > kBeyond) return true;
            insides_.push_back({mover, body, k, from, static_cast<int>(j)});
            return false;
        }
        return false;
    }
    if (state != insides_.end()) {
        // Inside since an earlier step: did it leave, and through which face?
        const std::optional<i2d::RayHit> exit = castSolid(shape, {b, a - b, 1.0f});
        if (!exit) return false;  // still inside
        const bool through = i2d::dot(exit->normal, state->entryNormal) < 0.0f;
        insides_.erase(state);
        return through;
    }
    const std::optional<i2d::RayHit> entry = castSolid(shape, {a, b - a, 1.0f});
    if (!entry) return false;
    const std::optional<i2d::RayHit> exit = castSolid(shape, {b, a - b, 1.0f});
    if (exit) return i2d::dot(exit->normal, entry->normal) < 0.0f;  // in and out within the step
    insides_.push_back({mover, body, k, entry->normal, -1});
    return false;
}

}  // namespace tb
