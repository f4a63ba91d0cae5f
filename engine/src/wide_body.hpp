// The solver states of four bodies as lanes of Float4 (float4.hpp): gathered
// from the BodyState array, velocities written back. Rows solved four at a
// time (wide_contact.cpp, wide_revolute.cpp) touch four different movable
// bodies per side, as the graph colouring guarantees, so the write-back never
// loses an update. A side that cannot move (the zero state of static and
// sleeping bodies, or a kinematic body, which the colouring lets many rows of
// a colour share) is read, never written: its velocity cannot change, and
// workers sharing a colour would otherwise write it at the same time.
#pragma once

#include "body.hpp"
#include "float4.hpp"

namespace i2d::detail {

struct WideBody {
    Float4 vx, vy, w, reserved;  ///< the first half of BodyState, lane by lane
    Float4 dpx, dpy, qc, qs;     ///< the second half: motion since the step began
};

#if defined(I2D_FLOAT4_SSE2)

/// BodyState is two rows of four floats (static_assert in body.hpp); four
/// states' rows transposed are the lanes. `reserved` is carried as raw bits.
inline WideBody gatherBodies(const BodyState* states, const int index[4]) {
    WideBody b;
    const float* s0 = reinterpret_cast<const float*>(states + index[0]);
    const float* s1 = reinterpret_cast<const float*>(states + index[1]);
    const float* s2 = reinterpret_cast<const float*>(states + index[2]);
    const float* s3 = reinterpret_cast<const float*>(states + index[3]);
    b.vx = {_mm_loadu_ps(s0)}, b.vy = {_mm_loadu_ps(s1)}, b.w = {_mm_loadu_ps(s2)}, b.reserved = {_mm_loadu_ps(s3)};
    transpose(b.vx, b.vy, b.w, b.reserved);
    b.dpx = {_mm_loadu_ps(s0 + 4)}, b.dpy = {_mm_loadu_ps(s1 + 4)}, b.qc = {_mm_loadu_ps(s2 + 4)},
    b.qs = {_mm_loadu_ps(s3 + 4)};
    transpose(b.dpx, b.dpy, b.qc, b.qs);
    return b;
}

inline void scatterVelocities(BodyState* states, const int index[4], const WideBody& b, const float invMass[4],
                              const float invInertia[4]) {
    Float4 r[4] = {b.vx, b.vy, b.w, b.reserved};
    transpose(r[0], r[1], r[2], r[3]);
    for (int i = 0; i < 4; ++i)
        if (invMass[i] != 0.0f || invInertia[i] != 0.0f)
            _mm_storeu_ps(reinterpret_cast<float*>(states + index[i]), r[i].v);
}

#else

inline WideBody gatherBodies(const BodyState* states, const int index[4]) {
    WideBody b;
    for (int i = 0; i < 4; ++i) {
        const BodyState& s = states[index[i]];
        b.vx.v[i] = s.v.x, b.vy.v[i] = s.v.y, b.w.v[i] = s.w, b.reserved.v[i] = 0.0f;
        b.dpx.v[i] = s.dp.x, b.dpy.v[i] = s.dp.y, b.qc.v[i] = s.dq.c, b.qs.v[i] = s.dq.s;
    }
    return b;
}

inline void scatterVelocities(BodyState* states, const int index[4], const WideBody& b, const float invMass[4],
                              const float invInertia[4]) {
    for (int i = 0; i < 4; ++i) {
        if (invMass[i] == 0.0f && invInertia[i] == 0.0f) continue;
        BodyState& s = states[index[i]];
        s.v = {b.vx.v[i], b.vy.v[i]};
        s.w = b.w.v[i];
    }
}

#endif

}  // namespace i2d::detail
