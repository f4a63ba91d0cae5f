// The wide contact and hinge sweeps and the integrations eight lanes at a
// time: two contact blocks of one colour, one hinge block (eight lanes of its
// own) or eight bodies in an AVX register (wide_contact_kernel.hpp says why
// that is bit-identical to four lanes and to the scalar rows). Compiled with -mavx2
// when the engine is built for x86-64 (engine/CMakeLists.txt) and called only
// when the CPU has AVX2 (wideLanes in wide_contact.cpp); everything
// here that is compiled for AVX2 is private to this file.
#include <cstddef>

#include "wide_contact_kernel.hpp"
#include "wide_revolute_kernel.hpp"

#if defined(I2D_AVX2_KERNEL) && defined(__AVX2__)
#include <immintrin.h>

namespace i2d::detail {

namespace {

#define I2D_AVX inline __attribute__((always_inline))

struct Float8 {
    __m256 v;
};
struct Mask8 {
    __m256 m;
};
I2D_AVX Float8 operator+(Float8 a, Float8 b) { return {_mm256_add_ps(a.v, b.v)}; }
I2D_AVX Float8 operator-(Float8 a, Float8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
I2D_AVX Float8 operator*(Float8 a, Float8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
I2D_AVX Float8 operator/(Float8 a, Float8 b) { return {_mm256_div_ps(a.v, b.v)}; }
I2D_AVX Float8 operator-(Float8 a) { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }
I2D_AVX Mask8 operator<(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
I2D_AVX Mask8 operator>(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
/// a ≠ 0, NaN included, as SSE2's cmpneq and the scalar !=.
I2D_AVX Mask8 nonZero(Float8 a) { return {_mm256_cmp_ps(a.v, _mm256_setzero_ps(), _CMP_NEQ_UQ)}; }
/// b where a ≠ 0, else 0 (a division guarded against a singular lane).
I2D_AVX Float8 whereNonZero(Float8 a, Float8 b) {
    return {_mm256_and_ps(_mm256_cmp_ps(a.v, _mm256_setzero_ps(), _CMP_NEQ_UQ), b.v)};
}
I2D_AVX Mask8 operator&(Mask8 a, Mask8 b) { return {_mm256_and_ps(a.m, b.m)}; }
I2D_AVX Mask8 operator|(Mask8 a, Mask8 b) { return {_mm256_or_ps(a.m, b.m)}; }
/// a and not b.
I2D_AVX Mask8 andNot(Mask8 a, Mask8 b) { return {_mm256_andnot_ps(b.m, a.m)}; }
/// The bits of yes where the mask holds, else of no. A mask lane is all ones
/// or all zeros, so the blend (which reads each lane's sign bit) picks what
/// and/andnot/or would, in one instruction instead of three.
I2D_AVX Float8 select(Mask8 m, Float8 yes, Float8 no) { return {_mm256_blendv_ps(no.v, yes.v, m.m)}; }
/// Block k0's four lanes, then block k1's.
I2D_AVX Float8 load8(const float* lo, const float* hi) {
    return {_mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(lo)), _mm_loadu_ps(hi), 1)};
}
I2D_AVX void store8(float* lo, float* hi, Float8 a) {
    _mm_storeu_ps(lo, _mm256_castps256_ps128(a.v));
    _mm_storeu_ps(hi, _mm256_extractf128_ps(a.v, 1));
}

/// The eight bodies' states at i0[0…3] and i1[0…3] (two rows of four floats
/// each, body.hpp), transposed so that each field is one register of eight
/// lanes.
I2D_AVX WideBodyT<Float8> gatherStates8(const BodyState* states, const int* i0, const int* i1) {
    __m256 r[8];
    for (int i = 0; i < 4; ++i) {
        r[i] = _mm256_loadu_ps(reinterpret_cast<const float*>(states + i0[i]));
        r[4 + i] = _mm256_loadu_ps(reinterpret_cast<const float*>(states + i1[i]));
    }
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
    const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
    const __m256 u0 = _mm256_shuffle_ps(t0, t2, 0x44), u1 = _mm256_shuffle_ps(t0, t2, 0xEE);
    const __m256 u2 = _mm256_shuffle_ps(t1, t3, 0x44), u3 = _mm256_shuffle_ps(t1, t3, 0xEE);
    const __m256 u4 = _mm256_shuffle_ps(t4, t6, 0x44), u5 = _mm256_shuffle_ps(t4, t6, 0xEE);
    const __m256 u6 = _mm256_shuffle_ps(t5, t7, 0x44), u7 = _mm256_shuffle_ps(t5, t7, 0xEE);
    WideBodyT<Float8> b;
    b.vx = {_mm256_permute2f128_ps(u0, u4, 0x20)};
    b.vy = {_mm256_permute2f128_ps(u1, u5, 0x20)};
    b.w = {_mm256_permute2f128_ps(u2, u6, 0x20)};
    b.reserved = {_mm256_permute2f128_ps(u3, u7, 0x20)};
    b.dpx = {_mm256_permute2f128_ps(u0, u4, 0x31)};
    b.dpy = {_mm256_permute2f128_ps(u1, u5, 0x31)};
    b.qc = {_mm256_permute2f128_ps(u2, u6, 0x31)};
    b.qs = {_mm256_permute2f128_ps(u3, u7, 0x31)};
    return b;
}

/// Four lanes' velocity rows back to states + index[0…3], where flags[i] has
/// `moves`; a side that cannot move is never written (wide_body.hpp says why).
I2D_AVX void scatterHalf(BodyState* states, const int* index, const std::uint32_t* flags, std::uint32_t moves,
                         __m128 r0, __m128 r1, __m128 r2, __m128 r3) {
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    const __m128 rows[4] = {r0, r1, r2, r3};
    for (int i = 0; i < 4; ++i)
        if (flags[i] & moves) _mm_storeu_ps(reinterpret_cast<float*>(states + index[i]), rows[i]);
}

/// The velocity rows of the eight lanes (the low half's at i0, the high
/// half's at i1) of the bodies that can move.
I2D_AVX void scatterStates8(BodyState* states, const int* i0, const std::uint32_t* f0, const int* i1,
                            const std::uint32_t* f1, std::uint32_t moves, const WideBodyT<Float8>& b) {
    scatterHalf(states, i0, f0, moves, _mm256_castps256_ps128(b.vx.v), _mm256_castps256_ps128(b.vy.v),
                _mm256_castps256_ps128(b.w.v), _mm256_castps256_ps128(b.reserved.v));
    scatterHalf(states, i1, f1, moves, _mm256_extractf128_ps(b.vx.v, 1), _mm256_extractf128_ps(b.vy.v, 1),
                _mm256_extractf128_ps(b.w.v, 1), _mm256_extractf128_ps(b.reserved.v, 1));
}

/// Two blocks of one colour in the eight lanes of Float8.
template <class Block>
struct Lanes8 {
    using V = Float8;
    using M = Mask8;
    Block* k0;
    Block* k1;
    WideContactCold* c0 = nullptr;  ///< the contact blocks' cold parts (their sweeps only)
    WideContactCold* c1 = nullptr;
    I2D_AVX static V splat(float x) { return {_mm256_set1_ps(x)}; }
    I2D_AVX V load(float (Block::*f)[4]) const { return load8(k0->*f, k1->*f); }
    I2D_AVX void store(float (Block::*f)[4], V x) const { store8(k0->*f, k1->*f, x); }
    /// A contact block's point j.
    I2D_AVX V load(int j, PointField f) const { return load8(k0->points[j].*f, k1->points[j].*f); }
    I2D_AVX void store(int j, PointField f, V x) const { store8(k0->points[j].*f, k1->points[j].*f, x); }
    /// A contact block's largest normal impulse of point j (WideContactCold).
    I2D_AVX V loadMax(int j) const { return load8(c0->maxNormalImpulse[j], c1->maxNormalImpulse[j]); }
    I2D_AVX void storeMax(int j, V x) const { store8(c0->maxNormalImpulse[j], c1->maxNormalImpulse[j], x); }
    /// The lanes whose flags (a contact block's) have every bit of `bits`.
    I2D_AVX M flags(std::uint32_t bits) const {
        const __m256i f = _mm256_insertf128_si256(
            _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(k0->flags))),
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(k1->flags)), 1);
        const __m256i b = _mm256_set1_epi32(static_cast<int>(bits));
        return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(f, b), b))};
    }

    I2D_AVX WideBodyT<V> gather(const BodyState* states, bool sideA) const {
        return gatherStates8(states, sideA ? k0->a : k0->b, sideA ? k1->a : k1->b);
    }
    I2D_AVX void scatter(BodyState* states, bool sideA, const WideBodyT<V>& b) const {
        // A contact lane's flags say whether each side moves (made once when it was prepared).
        scatterStates8(states, sideA ? k0->a : k0->b, k0->flags, sideA ? k1->a : k1->b, k1->flags,
                       sideA ? kWideMovesA : kWideMovesB, b);
    }
};

/// Two lane policies' blocks swept at once (TwinLanes: four contact blocks
/// of one colour, sixteen lanes in two AVX registers per value). Every
/// operation becomes two independent instructions, one per half, so the two
/// halves' chains of dependent arithmetic overlap. A sweep of one block pair
/// is a chain (gather, the normal row, the friction row on the velocities it
/// left, scatter) longer than the core can look ahead of, so consecutive
/// pairs hardly overlapped. Swept two pairs together, pyramid100's step took
/// 7 % less time; four pairs together were slower than one
/// (docs/performance.md, "Two block pairs at once"). Each lane still sees the
/// same operations in the same order, so the bits are the same.
template <class T>
struct Twin {
    T lo, hi;
};
template <class T>
I2D_AVX Twin<T> operator+(Twin<T> a, Twin<T> b) {
    return {a.lo + b.lo, a.hi + b.hi};
}
template <class T>
I2D_AVX Twin<T> operator-(Twin<T> a, Twin<T> b) {
    return {a.lo - b.lo, a.hi - b.hi};
}
template <class T>
I2D_AVX Twin<T> operator*(Twin<T> a, Twin<T> b) {
    return {a.lo * b.lo, a.hi * b.hi};
}
template <class T>
I2D_AVX Twin<T> operator/(Twin<T> a, Twin<T> b) {
    return {a.lo / b.lo, a.hi / b.hi};
}
template <class T>
I2D_AVX Twin<T> operator-(Twin<T> a) {
    return {-a.lo, -a.hi};
}
template <class T>
I2D_AVX auto operator<(Twin<T> a, Twin<T> b) {
    return Twin<decltype(a.lo < b.lo)>{a.lo < b.lo, a.hi < b.hi};
}
template <class T>
I2D_AVX auto operator>(Twin<T> a, Twin<T> b) {
    return Twin<decltype(a.lo > b.lo)>{a.lo > b.lo, a.hi > b.hi};
}
template <class T>
I2D_AVX Twin<T> operator&(Twin<T> a, Twin<T> b) {
    return {a.lo & b.lo, a.hi & b.hi};
}
template <class T>
I2D_AVX Twin<T> operator|(Twin<T> a, Twin<T> b) {
    return {a.lo | b.lo, a.hi | b.hi};
}
template <class T>
I2D_AVX Twin<T> andNot(Twin<T> a, Twin<T> b) {
    return {andNot(a.lo, b.lo), andNot(a.hi, b.hi)};
}
template <class M, class T>
I2D_AVX Twin<T> select(Twin<M> m, Twin<T> yes, Twin<T> no) {
    return {select(m.lo, yes.lo, no.lo), select(m.hi, yes.hi, no.hi)};
}

template <class L>
struct TwinLanes {
    using V = Twin<typename L::V>;
    using M = Twin<typename L::M>;
    L p, q;
    template <class F>
    I2D_AVX V load(F f) const {
        return {p.load(f), q.load(f)};
    }
    template <class F>
    I2D_AVX void store(F f, V x) const {
        p.store(f, x.lo), q.store(f, x.hi);
    }
    I2D_AVX static V splat(float x) { return {L::splat(x), L::splat(x)}; }
    I2D_AVX V load(int j, PointField f) const { return {p.load(j, f), q.load(j, f)}; }
    I2D_AVX void store(int j, PointField f, V x) const { p.store(j, f, x.lo), q.store(j, f, x.hi); }
    I2D_AVX V loadMax(int j) const { return {p.loadMax(j), q.loadMax(j)}; }
    I2D_AVX void storeMax(int j, V x) const { p.storeMax(j, x.lo), q.storeMax(j, x.hi); }
    I2D_AVX M flags(std::uint32_t bits) const { return {p.flags(bits), q.flags(bits)}; }
    I2D_AVX WideBodyT<V> gather(const BodyState* states, bool sideA) const {
        const auto a = p.gather(states, sideA), b = q.gather(states, sideA);
        return {{a.vx, b.vx},   {a.vy, b.vy},   {a.w, b.w},   {a.reserved, b.reserved},
                {a.dpx, b.dpx}, {a.dpy, b.dpy}, {a.qc, b.qc}, {a.qs, b.qs}};
    }
    I2D_AVX void scatter(BodyState* states, bool sideA, const WideBodyT<V>& b) const {
        p.scatter(states, sideA, {b.vx.lo, b.vy.lo, b.w.lo, b.reserved.lo, b.dpx.lo, b.dpy.lo, b.qc.lo, b.qs.lo});
        q.scatter(states, sideA, {b.vx.hi, b.vy.hi, b.w.hi, b.reserved.hi, b.dpx.hi, b.dpy.hi, b.qc.hi, b.qs.hi});
    }
};
using Lanes16 = TwinLanes<Lanes8<WideContactBlock>>;
template <class T>
I2D_AVX Twin<T> whereNonZero(Twin<T> a, Twin<T> b) {  // (the hinges')
    return {whereNonZero(a.lo, b.lo), whereNonZero(a.hi, b.hi)};
}

/// One block of hinges (kHingeLanes = 8) in the lanes of Float8: each field
/// one load.
struct HingeLanes8 {
    using V = Float8;
    using M = Mask8;
    WideRevoluteBlock* k;
    I2D_AVX static V splat(float x) { return {_mm256_set1_ps(x)}; }
    I2D_AVX V load(HingeField f) const { return {_mm256_loadu_ps(k->*f)}; }
    I2D_AVX void store(HingeField f, V x) const { _mm256_storeu_ps(k->*f, x.v); }
    I2D_AVX WideBodyT<V> gather(const BodyState* states, bool sideA) const {
        const int* index = sideA ? k->a : k->b;
        return gatherStates8(states, index, index + 4);
    }
    I2D_AVX void scatter(BodyState* states, bool sideA, const WideBodyT<V>& b) const {
        const int* index = sideA ? k->a : k->b;
        scatterStates8(states, index, k->moves, index + 4, k->moves + 4, sideA ? kWideMovesA : kWideMovesB, b);
    }
};

}  // namespace

// The kernels' max and clamp (wide_lanes.hpp), in fewer instructions with the
// same bits: maxps(x, y) is x > y ? x : y, so maxps(b, a) is a < b ? b : a
// (a when unordered or equal, as the select); minps(hi, a) is a > hi ? hi : a.
template <>
I2D_AVX Float8 maxv<Float8, Mask8>(Float8 a, Float8 b) {
    return {_mm256_max_ps(b.v, a.v)};
}
template <>
I2D_AVX Float8 clampv<Float8, Mask8>(Float8 a, Float8 lo, Float8 hi) {
    return select(a < lo, lo, Float8{_mm256_min_ps(hi.v, a.v)});
}
// The same, half by half, for a Twin.
template <class V, class M>
requires requires(V v) { v.lo; }
I2D_AVX V maxv(V a, V b) {
    return {maxv<decltype(a.lo), decltype(M{}.lo)>(a.lo, b.lo), maxv<decltype(a.lo), decltype(M{}.lo)>(a.hi, b.hi)};
}
template <class V, class M>
requires requires(V v) { v.lo; }
I2D_AVX V clampv(V a, V lo, V hi) {
    return {clampv<decltype(a.lo), decltype(M{}.lo)>(a.lo, lo.lo, hi.lo),
            clampv<decltype(a.lo), decltype(M{}.lo)>(a.hi, lo.hi, hi.hi)};
}

// ---- Integration, eight bodies at a time ------------------------------------
// integrateFourVelocities and integrateFourPositions (integration.cpp) with
// bodies i and i + 4 in the low and high halves: each half is transposed
// as the four-lane path transposes its four bodies, and every lane sees the
// same operations in the same order (no fused multiply-add: the engine is
// built with -ffp-contract=off), so the results are the same bits.

namespace {

/// The four-float rows at lo[k·stride] (low half) and hi[k·stride] (high
/// half), k = 0…3, transposed in each half as _MM_TRANSPOSE4_PS.
I2D_AVX void loadTransposed(const float* lo, const float* hi, std::size_t stride, Float8& r0, Float8& r1, Float8& r2,
                            Float8& r3) {
    const __m256 a = load8(lo, hi).v, b = load8(lo + stride, hi + stride).v;
    const __m256 c = load8(lo + 2 * stride, hi + 2 * stride).v, d = load8(lo + 3 * stride, hi + 3 * stride).v;
    const __m256 t0 = _mm256_unpacklo_ps(a, b), t1 = _mm256_unpacklo_ps(c, d);
    const __m256 t2 = _mm256_unpackhi_ps(a, b), t3 = _mm256_unpackhi_ps(c, d);
    r0 = {_mm256_shuffle_ps(t0, t1, 0x44)};
    r1 = {_mm256_shuffle_ps(t0, t1, 0xEE)};
    r2 = {_mm256_shuffle_ps(t2, t3, 0x44)};
    r3 = {_mm256_shuffle_ps(t2, t3, 0xEE)};
}

/// The inverse of loadTransposed.
I2D_AVX void storeTransposed(float* lo, float* hi, std::size_t stride, Float8 r0, Float8 r1, Float8 r2, Float8 r3) {
    const __m256 t0 = _mm256_unpacklo_ps(r0.v, r1.v), t1 = _mm256_unpacklo_ps(r2.v, r3.v);
    const __m256 t2 = _mm256_unpackhi_ps(r0.v, r1.v), t3 = _mm256_unpackhi_ps(r2.v, r3.v);
    store8(lo, hi, {_mm256_shuffle_ps(t0, t1, 0x44)});
    store8(lo + stride, hi + stride, {_mm256_shuffle_ps(t0, t1, 0xEE)});
    store8(lo + 2 * stride, hi + 2 * stride, {_mm256_shuffle_ps(t2, t3, 0x44)});
    store8(lo + 3 * stride, hi + 3 * stride, {_mm256_shuffle_ps(t2, t3, 0xEE)});
}

I2D_AVX int laneBits8(Mask8 m) { return _mm256_movemask_ps(m.m); }

/// nonFiniteVelocities of integration.cpp: x·0 is NaN for a non-finite x.
I2D_AVX Mask8 nonFiniteVelocities8(Float8 vx, Float8 vy, Float8 w) {
    const Float8 zero = HingeLanes8::splat(0.0f);
    return nonZero(vx * zero + vy * zero + w * zero);
}

}  // namespace

bool integrateEightVelocitiesAvx2(BodyState* states, const BodyIntegration* in, float h, float maxSpeed2) {
    for (int i = 0; i < 8; ++i)
        if (!in[i].movedByForces) return false;
    constexpr std::size_t kRecord = sizeof(BodyIntegration) / sizeof(float);
    static_assert(sizeof(BodyIntegration) % sizeof(float) == 0);
    Float8 ax, ay, torque, invI, unused, linear, angular, flagWord;
    loadTransposed(&in[0].linearAcceleration.x, &in[4].linearAcceleration.x, kRecord, ax, ay, torque, invI);
    loadTransposed(&in[0].invInertia, &in[4].invInertia, kRecord, unused, linear, angular, flagWord);
    float* f = &states[0].v.x;
    Float8 vx, vy, w, up;
    loadTransposed(f, f + 32, 8, vx, vy, w, up);
    if (laneBits8(nonFiniteVelocities8(vx, vy, w)) != 0) return false;
    const Float8 step = HingeLanes8::splat(h);
    vx = (vx + step * ax) * linear;
    vy = (vy + step * ay) * linear;
    if (laneBits8(vx * vx + vy * vy > HingeLanes8::splat(maxSpeed2)) != 0) return false;
    w = (w + step * invI * torque) * angular;
    storeTransposed(f, f + 32, 8, vx, vy, w, up);
    return true;
}

bool integrateEightPositionsAvx2(BodyState* states, float h, float maxSpeed2, float maxAngular) {
    using L = HingeLanes8;
    float* f = &states[0].v.x;
    Float8 vx, vy, w, up;
    loadTransposed(f, f + 32, 8, vx, vy, w, up);
    const Float8 fast = vx * vx + vy * vy;
    const Float8 absW = select(w < L::splat(0.0f), -w, w);
    if (laneBits8((fast > L::splat(maxSpeed2)) | (absW > L::splat(maxAngular)) | nonFiniteVelocities8(vx, vy, w)) != 0)
        return false;
    Float8 dpx, dpy, c, sn;
    loadTransposed(f + 4, f + 36, 8, dpx, dpy, c, sn);
    const Float8 step = L::splat(h);
    dpx = dpx + step * vx;
    dpy = dpy + step * vy;
    const Float8 angle = step * w;
    const Float8 rc = c - angle * sn, rs = sn + angle * c;
    const Float8 mag = {_mm256_sqrt_ps((rc * rc + rs * rs).v)};
    const Float8 inv = select(mag > L::splat(0.0f), L::splat(1.0f) / mag, L::splat(0.0f));
    storeTransposed(f + 4, f + 36, 8, dpx, dpy, rc * inv, rs * inv);
    return true;
}

int warmStartWideContactsAvx2(WideContactBlock* blocks, BodyState* states, int first, int last, int points) {
    int i = first;
    withPointCount(points, [&](auto n) {
        for (; i + 1 < last; i += 2) warmStartBlock<n()>(Lanes8<WideContactBlock>{blocks + i, blocks + i + 1}, states);
    });
    return i;
}

int solveWideContactsAvx2(WideContactBlock* blocks, WideContactCold* cold, BodyState* states, const SweepParams& sp,
                          int first, int last, int points) {
    int i = first;
    withPointCount(points, [&](auto n) {
        using L8 = Lanes8<WideContactBlock>;
        auto l8 = [&](int k) { return L8{blocks + k, blocks + k + 1, cold + k, cold + k + 1}; };
        for (; i + 3 < last; i += 4) solveBlock<n()>(Lanes16{l8(i), l8(i + 2)}, states, sp);
        for (; i + 1 < last; i += 2) solveBlock<n()>(l8(i), states, sp);
    });
    return i;
}

void warmStartWideRevolutesAvx2(WideRevoluteBlock* blocks, BodyState* states, int first, int last, bool kept) {
    for (int i = first; i < last; ++i) warmStartHingeBlock(HingeLanes8{blocks + i}, states, kept);
}

void solveWideRevolutesAvx2(WideRevoluteBlock* blocks, BodyState* states, const HingeRates& rates, int first, int last,
                            bool kept) {
    // Two blocks at once where there are two (TwinLanes): joint_grid's step took 4 % less time.
    int i = first;
    for (; i + 1 < last; i += 2)
        solveHingeBlock(TwinLanes<HingeLanes8>{HingeLanes8{blocks + i}, HingeLanes8{blocks + i + 1}}, states, rates,
                        kept);
    for (; i < last; ++i) solveHingeBlock(HingeLanes8{blocks + i}, states, rates, kept);
}

}  // namespace i2d::detail

#endif
