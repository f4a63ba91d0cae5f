// Four floats operated on at once: SSE2 on x86-64 (always present there), a
// portable scalar path elsewhere or with I2D_SCALAR_FLOAT4 defined. Only
// IEEE-exact operations (+, −, ×, ÷, comparisons, selects) are offered and the
// engine is built without FMA contraction, so both paths give bit-identical
// results (tests/unit/test_wide_contact.cpp holds the wide rows to the scalar
// ones on either path; the asan-engine preset builds the portable one).
#pragma once

#include <cmath>
#include <cstdint>

#if defined(__SSE2__) && !defined(I2D_SCALAR_FLOAT4)
#include <emmintrin.h>
#define I2D_FLOAT4_SSE2 1
#endif

namespace i2d::detail {

#if defined(I2D_FLOAT4_SSE2)

struct Float4 {
    __m128 v;
};
inline Float4 splat(float x) { return {_mm_set1_ps(x)}; }
/// The lanes a, b, c, d (in that order), from registers.
inline Float4 make4(float a, float b, float c, float d) { return {_mm_setr_ps(a, b, c, d)}; }
inline Float4 load4(const float* p) { return {_mm_loadu_ps(p)}; }
inline void store4(float* p, Float4 a) { _mm_storeu_ps(p, a.v); }
inline Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
inline Float4 operator-(Float4 a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
/// √a, correctly rounded as std::sqrt is.
inline Float4 sqrt4(Float4 a) { return {_mm_sqrt_ps(a.v)}; }
/// b where a ≠ 0, else 0 (a division guarded against a singular lane).
inline Float4 whereNonZero(Float4 a, Float4 b) { return {_mm_and_ps(_mm_cmpneq_ps(a.v, _mm_setzero_ps()), b.v)}; }
/// Transposes four rows of four floats in place (rows become columns).
inline void transpose(Float4& r0, Float4& r1, Float4& r2, Float4& r3) { _MM_TRANSPOSE4_PS(r0.v, r1.v, r2.v, r3.v); }

/// Four lanes' truth values.
struct Mask4 {
    __m128 m;
};
inline Mask4 operator<(Float4 a, Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline Mask4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline Mask4 operator<=(Float4 a, Float4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
inline Mask4 nonZero(Float4 a) { return {_mm_cmpneq_ps(a.v, _mm_setzero_ps())}; }
/// The lanes of four flag words that have every bit of `bits`.
inline Mask4 hasBits(const std::uint32_t* p, std::uint32_t bits) {
    const __m128i b = _mm_set1_epi32(static_cast<int>(bits));
    const __m128i f = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), b);
    return {_mm_castsi128_ps(_mm_cmpeq_epi32(f, b))};
}
/// Bit k set where lane k holds.
inline int laneBits(Mask4 a) { return _mm_movemask_ps(a.m); }
inline Mask4 operator&(Mask4 a, Mask4 b) { return {_mm_and_ps(a.m, b.m)}; }
inline Mask4 operator|(Mask4 a, Mask4 b) { return {_mm_or_ps(a.m, b.m)}; }
/// a and not b.
inline Mask4 andNot(Mask4 a, Mask4 b) { return {_mm_andnot_ps(b.m, a.m)}; }
/// Lane by lane: yes where the mask holds, else no (the bits of one or the other).
inline Float4 select(Mask4 m, Float4 yes, Float4 no) {
    return {_mm_or_ps(_mm_and_ps(m.m, yes.v), _mm_andnot_ps(m.m, no.v))};
}

#else

struct Float4 {
    float v[4];
};
inline Float4 splat(float x) { return {{x, x, x, x}}; }
inline Float4 make4(float a, float b, float c, float d) { return {{a, b, c, d}}; }
inline Float4 load4(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline void store4(float* p, Float4 a) {
    for (int i = 0; i < 4; ++i) p[i] = a.v[i];
}
template <class Op>
inline Float4 lanewise(Float4 a, Float4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
inline Float4 operator+(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x + y; });
}
inline Float4 operator-(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x - y; });
}
inline Float4 operator*(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x * y; });
}
inline Float4 operator/(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x / y; });
}
inline Float4 operator-(Float4 a) {
    return lanewise(a, a, [](float x, float) { return -x; });
}
inline Float4 sqrt4(Float4 a) {
    return lanewise(a, a, [](float x, float) { return std::sqrt(x); });
}
inline Float4 whereNonZero(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x != 0.0f ? y : 0.0f; });
}
inline void transpose(Float4& r0, Float4& r1, Float4& r2, Float4& r3) {
    Float4* r[4] = {&r0, &r1, &r2, &r3};
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const float t = r[i]->v[j];
            r[i]->v[j] = r[j]->v[i];
            r[j]->v[i] = t;
        }
}

struct Mask4 {
    bool m[4];
};
template <class Op>
inline Mask4 lanewiseMask(Float4 a, Float4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
inline Mask4 operator<(Float4 a, Float4 b) {
    return lanewiseMask(a, b, [](float x, float y) { return x < y; });
}
inline Mask4 operator>(Float4 a, Float4 b) {
    return lanewiseMask(a, b, [](float x, float y) { return x > y; });
}
inline Mask4 operator<=(Float4 a, Float4 b) {
    return lanewiseMask(a, b, [](float x, float y) { return x <= y; });
}
inline Mask4 nonZero(Float4 a) {
    return lanewiseMask(a, a, [](float x, float) { return x != 0.0f; });
}
/// The lanes of four flag words that have every bit of `bits`.
inline Mask4 hasBits(const std::uint32_t* p, std::uint32_t bits) {
    return {{(p[0] & bits) == bits, (p[1] & bits) == bits, (p[2] & bits) == bits, (p[3] & bits) == bits}};
}
inline int laneBits(Mask4 a) { return int(a.m[0]) | int(a.m[1]) << 1 | int(a.m[2]) << 2 | int(a.m[3]) << 3; }
inline Mask4 operator&(Mask4 a, Mask4 b) {
    return {{a.m[0] && b.m[0], a.m[1] && b.m[1], a.m[2] && b.m[2], a.m[3] && b.m[3]}};
}
inline Mask4 operator|(Mask4 a, Mask4 b) {
    return {{a.m[0] || b.m[0], a.m[1] || b.m[1], a.m[2] || b.m[2], a.m[3] || b.m[3]}};
}
inline Mask4 andNot(Mask4 a, Mask4 b) {
    return {{a.m[0] && !b.m[0], a.m[1] && !b.m[1], a.m[2] && !b.m[2], a.m[3] && !b.m[3]}};
}
inline Float4 select(Mask4 m, Float4 yes, Float4 no) {
    return {{m.m[0] ? yes.v[0] : no.v[0], m.m[1] ? yes.v[1] : no.v[1], m.m[2] ? yes.v[2] : no.v[2],
             m.m[3] ? yes.v[3] : no.v[3]}};
}

#endif

// Both paths: the standard library's choices, lane by lane, so that a wide
// row takes what the scalar row takes, signed zeros included.
/// std::max(a, b): b where a < b, else a.
inline Float4 max4(Float4 a, Float4 b) { return select(a < b, b, a); }
/// std::min(a, b): b where b < a, else a.
inline Float4 min4(Float4 a, Float4 b) { return select(b < a, b, a); }
/// i2d::clamp(a, lo, hi): lo where a < lo, else hi where a > hi, else a.
inline Float4 clamp4(Float4 a, Float4 lo, Float4 hi) { return select(a < lo, lo, select(a > hi, hi, a)); }

}  // namespace i2d::detail
