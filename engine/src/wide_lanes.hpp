// What the wide sweeps (wide_contact_kernel.hpp, wide_revolute_kernel.hpp)
// share whatever their lane count: a lane policy L gives the vector type
// L::V and mask type L::M, splat, loads and stores of a block's fields, and
// the gather and scatter of its bodies. Lanes4 (wide_lanes4.hpp) is one
// contact block in Float4, HingeLanes4 (wide_revolute.cpp) half a hinge
// block; Lanes8 (wide_avx2.cpp) two contact blocks of one colour in an AVX
// register, HingeLanes8 one hinge block. The kernels are templates, always
// inlined into the function that runs them, so that they are compiled for
// the instruction set of that function's file.
#pragma once

#include "body.hpp"

namespace i2d::detail {

#define I2D_KERNEL inline __attribute__((always_inline))

/// A BodyState's eight floats, lane by lane.
template <class V>
struct WideBodyT {
    V vx, vy, w, reserved;
    V dpx, dpy, qc, qs;
};

template <class V, class M>
I2D_KERNEL V maxv(V a, V b) {
    return select(a < b, b, a);
}
template <class V, class M>
I2D_KERNEL V clampv(V a, V lo, V hi) {
    return select(a < lo, lo, select(a > hi, hi, a));
}

}  // namespace i2d::detail
