// Impulse2D — small 2D vector, rotation and transform types.
//
// All engine arithmetic is single precision. Functions here are inline and
// free of branches where possible so the solver's inner loops stay cheap.
#pragma once

#include <cmath>
#include <cstdint>

namespace i2d {

/// A 2D vector (metres, metres per second, newtons, ... depending on use).
struct Vec2 {
    float x = 0.0f;
    float y = 0.0f;
};

/// Component-wise arithmetic and exact comparison.
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
constexpr Vec2 operator*(float s, Vec2 a) { return {s * a.x, s * a.y}; }
constexpr Vec2 operator*(Vec2 a, float s) { return {s * a.x, s * a.y}; }
constexpr Vec2& operator+=(Vec2& a, Vec2 b) {
    a.x += b.x;
    a.y += b.y;
    return a;
}
constexpr Vec2& operator-=(Vec2& a, Vec2 b) {
    a.x -= b.x;
    a.y -= b.y;
    return a;
}
constexpr Vec2& operator*=(Vec2& a, float s) {
    a.x *= s;
    a.y *= s;
    return a;
}
constexpr bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

/// Dot product a·b.
constexpr float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// 2D cross product a × b (the z component of the 3D cross product).
constexpr float cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// v × s for a scalar s along z: (s v.y, −s v.x).
constexpr Vec2 cross(Vec2 v, float s) { return {s * v.y, -s * v.x}; }
/// s × v for a scalar s along z: (−s v.y, s v.x). Used for ω × r.
constexpr Vec2 cross(float s, Vec2 v) { return {-s * v.y, s * v.x}; }
/// Counter-clockwise perpendicular (−y, x).
constexpr Vec2 leftPerp(Vec2 v) { return {-v.y, v.x}; }
/// Clockwise perpendicular (y, −x).
constexpr Vec2 rightPerp(Vec2 v) { return {v.y, -v.x}; }
/// |v|², |v| (Euclidean length), and the distance between two points.
constexpr float lengthSquared(Vec2 v) { return v.x * v.x + v.y * v.y; }
inline float length(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }
inline float distance(Vec2 a, Vec2 b) { return length(b - a); }
constexpr float distanceSquared(Vec2 a, Vec2 b) { return lengthSquared(b - a); }
/// a + t·(b − a): a at t = 0, b at t = 1.
constexpr Vec2 lerp(Vec2 a, Vec2 b, float t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }
/// a + s·b and a − s·b.
constexpr Vec2 mulAdd(Vec2 a, float s, Vec2 b) { return {a.x + s * b.x, a.y + s * b.y}; }
constexpr Vec2 mulSub(Vec2 a, float s, Vec2 b) { return {a.x - s * b.x, a.y - s * b.y}; }
/// Component-wise absolute value, minimum and maximum.
constexpr Vec2 abs(Vec2 a) { return {a.x < 0 ? -a.x : a.x, a.y < 0 ? -a.y : a.y}; }
constexpr Vec2 min(Vec2 a, Vec2 b) { return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y}; }
constexpr Vec2 max(Vec2 a, Vec2 b) { return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y}; }

/// Unit vector along v, or the zero vector when v is (nearly) zero.
inline Vec2 normalize(Vec2 v) {
    float len = length(v);
    if (len < 1.0e-12f) return {0.0f, 0.0f};
    float inv = 1.0f / len;
    return {inv * v.x, inv * v.y};
}

/// Unit vector along v and its former length.
inline Vec2 normalize(Vec2 v, float& len) {
    len = length(v);
    if (len < 1.0e-12f) return {0.0f, 0.0f};
    float inv = 1.0f / len;
    return {inv * v.x, inv * v.y};
}

/// True when no component is NaN or ±∞.
inline bool isFinite(float a) { return std::isfinite(a); }
inline bool isFinite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

/// A rotation stored as cosine and sine of its angle (counter-clockwise positive).
struct Rot {
    float c = 1.0f;
    float s = 0.0f;
};

/// Rotation by `angle` radians; angleOf gives it back in [−π, π].
inline Rot makeRot(float angle) { return {std::cos(angle), std::sin(angle)}; }
inline float angleOf(Rot q) { return std::atan2(q.s, q.c); }
/// R(q)·v and R(q)ᵀ·v (the inverse rotation).
constexpr Vec2 rotate(Rot q, Vec2 v) { return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
constexpr Vec2 invRotate(Rot q, Vec2 v) { return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y}; }
/// q·r: rotate by r, then by q.
constexpr Rot mulRot(Rot q, Rot r) { return {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s}; }
/// qᵀ·r: the rotation from q to r.
constexpr Rot invMulRot(Rot q, Rot r) { return {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c}; }

/// Advance a rotation by the small angle dθ and renormalise. This is the 2D
/// form of eq. 3.2.4 of Tamis and Maggiore (2015), "Constraint based physics
/// solver" (o += ½ ω o Δt, then normalise): with the
/// rotation as a unit complex number q, q' = normalise(q + i dθ q).
inline Rot integrateRotation(Rot q, float deltaAngle) {
    float c = q.c - deltaAngle * q.s;
    float s = q.s + deltaAngle * q.c;
    float mag = std::sqrt(c * c + s * s);
    float inv = mag > 0.0f ? 1.0f / mag : 0.0f;
    return {c * inv, s * inv};
}

/// A rigid transform: p + R(q)·v.
struct Transform {
    Vec2 p{};
    Rot q{};
};

/// A point from the transform's frame to the outer frame (p + R·v), and back.
constexpr Vec2 transformPoint(const Transform& t, Vec2 v) { return rotate(t.q, v) + t.p; }
constexpr Vec2 invTransformPoint(const Transform& t, Vec2 v) { return invRotate(t.q, v - t.p); }
/// A⁻¹·B: B expressed in A's frame.
constexpr Transform invMulTransforms(const Transform& a, const Transform& b) {
    return {invRotate(a.q, b.p - a.p), invMulRot(a.q, b.q)};
}
/// A·B: B's frame expressed in A's outer frame.
constexpr Transform mulTransforms(const Transform& a, const Transform& b) {
    return {rotate(a.q, b.p) + a.p, mulRot(a.q, b.q)};
}

/// An axis-aligned bounding box: lower and upper corners.
struct AABB {
    Vec2 lower{};
    Vec2 upper{};
};

/// True when the boxes overlap or touch.
constexpr bool overlaps(const AABB& a, const AABB& b) {
    return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x || a.lower.y > b.upper.y);
}
/// The smallest box containing both.
constexpr AABB unionOf(const AABB& a, const AABB& b) { return {min(a.lower, b.lower), max(a.upper, b.upper)}; }
/// True when `inner` lies inside `outer` (boundary included).
constexpr bool contains(const AABB& outer, const AABB& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}
/// Perimeter of the box (the cost measure of the broadphase tree).
constexpr float perimeter(const AABB& a) { return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y)); }

/// a limited to [lo, hi].
constexpr float clamp(float a, float lo, float hi) { return a < lo ? lo : (a > hi ? hi : a); }

}  // namespace i2d
