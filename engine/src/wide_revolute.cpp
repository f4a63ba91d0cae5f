// Eight revolute point blocks at a time (see wide_revolute.hpp): packing the
// slots into blocks, the four- or eight-lane sweeps (wide_revolute_kernel.hpp
// holds them), the store of the impulses.
#include "wide_revolute.hpp"

#include "joint_rows.hpp"
#include "wide_body.hpp"
#include "wide_contact.hpp"
#include "wide_lanes4.hpp"
#include "wide_revolute_kernel.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void packWideRevolutes(const WorldState& w, SolverArrays& s, int first, int last) {
    const int zero = static_cast<int>(s.states.size()) - 1;
    const bool warm = w.settings.enableWarmStarting;
    for (int start = first; start < last; start += kHingeLanes) {
        WideRevoluteBlock& block = s.wideRevolutes.emplace_back();
        WideRevoluteFrame& frame = s.wideFrames.emplace_back();
        for (int lane = 0; lane < kHingeLanes; ++lane) {
            const int place = start + lane;
            if (place >= last) {
                block.a[lane] = block.b[lane] = zero;
                block.joint[lane] = -1;
                block.rAx[lane] = block.rAy[lane] = block.rBx[lane] = block.rBy[lane] = 0.0f;
                block.dcx[lane] = block.dcy[lane] = 0.0f;
                block.mA[lane] = block.iA[lane] = block.mB[lane] = block.iB[lane] = 0.0f;
                block.px[lane] = block.py[lane] = 0.0f;
                block.moves[lane] = 0u;
                frame.bodyA[lane] = frame.bodyB[lane] = kNullIndex;
                frame.armAx[lane] = frame.armAy[lane] = frame.armBx[lane] = frame.armBy[lane] = 0.0f;
                continue;
            }
            const JointSlot& slot =
                s.jointSlots[static_cast<std::size_t>(s.jointOrder[static_cast<std::size_t>(place)])];
            const Joint& joint = w.joints[slot.joint];
            const RevoluteJointDef& def = std::get<RevoluteJointDef>(joint.def);
            const Vec2 p = warm ? joint.impulses.linear : Vec2{};
            block.a[lane] = slot.a >= 0 ? slot.a : zero;
            block.b[lane] = slot.b >= 0 ? slot.b : zero;
            block.joint[lane] = slot.joint;
            block.mA[lane] = slot.invMassA, block.iA[lane] = slot.invIA;
            block.mB[lane] = slot.invMassB, block.iB[lane] = slot.invIB;
            block.px[lane] = p.x, block.py[lane] = p.y;
            block.moves[lane] = moveFlags(slot.invMassA, slot.invIA, slot.invMassB, slot.invIB);
            // As setAnchors (joint_rows.hpp): from the centres of mass.
            const Vec2 armA = def.localAnchorA - w.bodies[joint.bodyA].localCenter;
            const Vec2 armB = def.localAnchorB - w.bodies[joint.bodyB].localCenter;
            frame.bodyA[lane] = joint.bodyA, frame.bodyB[lane] = joint.bodyB;
            frame.armAx[lane] = armA.x, frame.armAy[lane] = armA.y;
            frame.armBx[lane] = armB.x, frame.armBy[lane] = armB.y;
        }
    }
}

void refreshWideRevolutes(const WorldState& w, SolverArrays& s, int firstBlock, int lastBlock) {
    const bool warm = w.settings.enableWarmStarting;
    for (int k = firstBlock; k < lastBlock; ++k) {
        WideRevoluteBlock& block = s.wideRevolutes[static_cast<std::size_t>(k)];
        const WideRevoluteFrame& frame = s.wideFrames[static_cast<std::size_t>(k)];
        for (int lane = 0; lane < kHingeLanes; ++lane) {
            if (block.joint[lane] < 0) continue;
            const Body& bA = w.bodies[frame.bodyA[lane]];
            const Body& bB = w.bodies[frame.bodyB[lane]];
            // In world axes (setAnchors).
            const Vec2 rA = rotate(bA.xf.q, Vec2{frame.armAx[lane], frame.armAy[lane]});
            const Vec2 rB = rotate(bB.xf.q, Vec2{frame.armBx[lane], frame.armBy[lane]});
            const Vec2 dc = bB.center - bA.center;
            block.rAx[lane] = rA.x, block.rAy[lane] = rA.y, block.rBx[lane] = rB.x, block.rBy[lane] = rB.y;
            block.dcx[lane] = dc.x, block.dcy[lane] = dc.y;
            if (isDeepJoint(w, w.joints[block.joint[lane]], dc + rB - rA)) s.wideDeep[static_cast<std::size_t>(k)] = 1;
            if (!warm) block.px[lane] = block.py[lane] = 0.0f;
        }
    }
}

namespace {

/// Half of a block of hinges (lanes 4·half to 4·half + 3) in the lanes of
/// Float4, as Lanes4 holds a contact block.
struct HingeLanes4 {
    using V = Float4;
    using M = Mask4;
    WideRevoluteBlock* k;
    int half;
    static V splat(float x) { return detail::splat(x); }
    V load(HingeField f) const { return load4(k->*f + 4 * half); }
    void store(HingeField f, V x) const { store4(k->*f + 4 * half, x); }
    WideBodyT<V> gather(const BodyState* states, bool sideA) const {
        const WideBody b = gatherBodies(states, (sideA ? k->a : k->b) + 4 * half);
        return {b.vx, b.vy, b.w, b.reserved, b.dpx, b.dpy, b.qc, b.qs};
    }
    void scatter(BodyState* states, bool sideA, const WideBodyT<V>& b) const {
        const WideBody w{b.vx, b.vy, b.w, b.reserved, b.dpx, b.dpy, b.qc, b.qs};
        const int o = 4 * half;
        if (sideA)
            scatterVelocities(states, k->a + o, w, k->mA + o, k->iA + o);
        else
            scatterVelocities(states, k->b + o, w, k->mB + o, k->iB + o);
    }
};

#if defined(I2D_AVX2_KERNEL)
bool avx2Lanes() { return wideLanes() == 8; }
#endif

}  // namespace

#if defined(I2D_AVX2_KERNEL)
// wide_avx2.cpp: blocks [first, last), each in one register's lanes.
void warmStartWideRevolutesAvx2(WideRevoluteBlock* blocks, BodyState* states, int first, int last, bool kept);
void solveWideRevolutesAvx2(WideRevoluteBlock* blocks, BodyState* states, const HingeRates& rates, int first, int last,
                            bool kept);
#endif

void warmStartWideRevolutes(SolverArrays& s, int firstBlock, int lastBlock, bool kept) {
    BodyState* states = s.states.data();
#if defined(I2D_AVX2_KERNEL)
    if (avx2Lanes()) {
        if (lastBlock > firstBlock)
            warmStartWideRevolutesAvx2(&s.wideRevolutes[0], states, firstBlock, lastBlock, kept);
        return;
    }
#endif
    for (int i = firstBlock; i < lastBlock; ++i)
        for (int half = 0; half < 2; ++half)
            warmStartHingeBlock(HingeLanes4{&s.wideRevolutes[static_cast<std::size_t>(i)], half}, states, kept);
}

void solveWideRevolutes(SolverArrays& s, const JointContext& ctx, int firstBlock, int lastBlock, bool kept) {
    const RowBias rb = rigidBias(ctx, 1.0f);  // the rates, applied to each component of the separation
    const HingeRates rates{rb.bias, rb.massScale, rb.impulseScale};
    BodyState* states = s.states.data();
#if defined(I2D_AVX2_KERNEL)
    if (avx2Lanes()) {
        if (lastBlock > firstBlock)
            solveWideRevolutesAvx2(&s.wideRevolutes[0], states, rates, firstBlock, lastBlock, kept);
        return;
    }
#endif
    for (int i = firstBlock; i < lastBlock; ++i)
        for (int half = 0; half < 2; ++half)
            solveHingeBlock(HingeLanes4{&s.wideRevolutes[static_cast<std::size_t>(i)], half}, states, rates, kept);
}

void storeWideRevolutes(WorldState& w, float h) {
    const float invH = 1.0f / h;
    for (const WideRevoluteBlock& k : w.solver.wideRevolutes)
        for (int lane = 0; lane < kHingeLanes; ++lane) {
            if (k.joint[lane] < 0) continue;
            Joint& joint = w.joints[k.joint[lane]];
            joint.impulses = JointImpulses{};
            joint.impulses.linear = {k.px[lane], k.py[lane]};
            joint.reactionForce = invH * joint.impulses.linear;
            joint.reactionTorque = 0.0f;
            joint.motorEffort = 0.0f;
            joint.lastForce = length(joint.reactionForce);
        }
}

void dropWideImpulses(SolverArrays& s, const std::vector<char>& bad) {
    for (WideRevoluteBlock& k : s.wideRevolutes)
        for (int lane = 0; lane < kHingeLanes; ++lane)
            if (bad[static_cast<std::size_t>(k.a[lane])] || bad[static_cast<std::size_t>(k.b[lane])])
                k.px[lane] = k.py[lane] = 0.0f;
}

}  // namespace i2d::detail
