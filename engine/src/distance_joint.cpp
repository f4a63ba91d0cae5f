// The distance joint's rows (the constraint and its effective mass are in
// distance_joint.hpp): preparation, warm start, the sweeps of each solver
// pass, split mode's push, and storing the impulses.
#include <algorithm>
#include <cmath>

#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// The anchors and the axis at the current point of the step.
struct JointFrame {
    Vec2 rA, rB, axis;
    float length;
};

JointFrame currentFrame(const DistanceJointConstraint& jc, const BodyState& sA, const BodyState& sB) {
    JointFrame f;
    f.rA = rotate(sA.dq, jc.rA);
    f.rB = rotate(sB.dq, jc.rB);
    Vec2 d = (sB.dp - sA.dp) + jc.deltaCenter + f.rB - f.rA;
    f.axis = normalize(d, f.length);
    return f;
}

void applyAxial(const DistanceJointConstraint& jc, const JointFrame& f, float impulse, BodyState& sA, BodyState& sB) {
    Vec2 P = impulse * f.axis;
    sA.v = mulSub(sA.v, jc.invMassA, P);
    sA.w -= jc.invIA * cross(f.rA, P);
    sB.v = mulAdd(sB.v, jc.invMassB, P);
    sB.w += jc.invIB * cross(f.rB, P);
}

// Adds `impulse` to `accumulated` within [lo, hi]; returns the part applied.
float boundedIncrement(float& accumulated, float impulse, float lo, float hi) {
    const float total = clamp(accumulated + impulse, lo, hi);
    impulse = total - accumulated;
    accumulated = total;
    return impulse;
}

}  // namespace

void prepareDistanceJoints(WorldState& w) {
    std::vector<DistanceJointConstraint>& rows = w.solver.distanceJoints;
    rows.clear();
    rows.reserve(static_cast<std::size_t>(w.joints.count));  // one allocation (the array may have been freed)
    const float warm = w.settings.enableWarmStarting;
    for (int j = 0; j < w.joints.capacity(); ++j) {
        const DistanceJoint& jt = w.joints[j];
        if (!jt.alive) continue;
        const Body& bA = w.bodies[jt.bodyA];
        const Body& bB = w.bodies[jt.bodyB];
        if (!bA.awake && !bB.awake) continue;
        DistanceJointConstraint& jc = rows.emplace_back();
        jc.joint = j;
        // Awake bodies have a solver state; a static or sleeping side does not move.
        jc.a = bA.awake ? bA.solverIndex : kNullIndex;
        jc.b = bB.awake ? bB.solverIndex : kNullIndex;
        jc.invMassA = jc.a >= 0 ? bA.invMass : 0.0f;
        jc.invIA = jc.a >= 0 ? bA.invInertia : 0.0f;
        jc.invMassB = jc.b >= 0 ? bB.invMass : 0.0f;
        jc.invIB = jc.b >= 0 ? bB.invInertia : 0.0f;
        jc.rA = rotate(bA.xf.q, jt.def.localAnchorA - bA.localCenter);
        jc.rB = rotate(bB.xf.q, jt.def.localAnchorB - bB.localCenter);
        jc.deltaCenter = bB.center - bA.center;
        Vec2 axis = normalize(jc.deltaCenter + jc.rB - jc.rA);
        float crA = cross(jc.rA, axis), crB = cross(jc.rB, axis);
        float k = jc.invMassA + jc.invMassB + jc.invIA * crA * crA + jc.invIB * crB * crB;
        jc.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
        jc.length = jt.def.length;
        jc.minLength = jt.def.minLength;
        jc.maxLength = jt.def.maxLength;
        jc.hertz = jt.def.hertz;
        jc.dampingRatio = jt.def.dampingRatio;
        jc.enableLimit = jt.def.enableLimit;
        jc.rigid = !(jt.def.enableSpring && (!jt.def.enableLimit || jt.def.minLength < jt.def.maxLength));
        jc.impulse = warm ? jt.impulse : 0.0f;
        jc.lowerImpulse = warm ? jt.lowerImpulse : 0.0f;
        jc.upperImpulse = warm ? jt.upperImpulse : 0.0f;
    }
}

void warmStartDistanceJoints(WorldState& w) {
    BodyState dA, dB;
    for (DistanceJointConstraint& jc : w.solver.distanceJoints) {
        BodyState& sA = jc.a >= 0 ? w.solver.states[static_cast<std::size_t>(jc.a)] : (dA = BodyState{});
        BodyState& sB = jc.b >= 0 ? w.solver.states[static_cast<std::size_t>(jc.b)] : (dB = BodyState{});
        JointFrame f = currentFrame(jc, sA, sB);
        applyAxial(jc, f, jc.impulse + jc.lowerImpulse - jc.upperImpulse, sA, sB);
    }
}

void solveDistanceJoints(WorldState& w, float h, SolvePass pass) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    // Joint stiffness capped at 1/4 of the substep rate, so jointHertz 60 holds
    // at 4 substeps as in Box2D v3 (twice its contact hertz). This needs the two
    // joint sweeps of the solve stage (solver.cpp, kJointSolvePasses): with one,
    // a 100:1 chain (heavy_chain) diverged at this stiffness, and at the former
    // cap of 1/8 it stretched by 3.1 m.
    const Softness jointSoft = makeSoft(std::min(set.jointHertz, 0.25f * invH), set.jointDampingRatio, h);
    BodyState dA, dB;
    for (DistanceJointConstraint& jc : w.solver.distanceJoints) {
        BodyState& sA = jc.a >= 0 ? w.solver.states[static_cast<std::size_t>(jc.a)] : (dA = BodyState{});
        BodyState& sB = jc.b >= 0 ? w.solver.states[static_cast<std::size_t>(jc.b)] : (dB = BodyState{});
        JointFrame f = currentFrame(jc, sA, sB);
        // A joint's impulse per (sub)step never needs to exceed what changes
        // the relative speed along it by twice the speed limit; bounding it
        // keeps a diverging row (a fuzzed, stretched 600:1 joint reached
        // 1e36 N·s, then NaN) finite.
        const float maxImpulse = 2.0f * set.maxLinearSpeed * jc.axialMass;
        auto cdot = [&]() {
            Vec2 dv = (sB.v + cross(sB.w, f.rB)) - (sA.v + cross(sA.w, f.rA));
            return dot(dv, f.axis);
        };
        if (jc.rigid) {
            float C = f.length - jc.length;
            float bias = 0.0f, ms = 1.0f, is = 0.0f;
            if (pass == SolvePass::soft_bias) {
                bias = jointSoft.biasRate * C;
                ms = jointSoft.massScale;
                is = jointSoft.impulseScale;
            } else if (pass == SolvePass::baumgarte) {
                bias = set.pushFactor * invH * C;  // Tamis and Maggiore (2015) eq. 5.2.3
            }
            float impulse = -ms * jc.axialMass * (cdot() + bias) - is * jc.impulse;
            impulse = boundedIncrement(jc.impulse, impulse, -maxImpulse, maxImpulse);
            applyAxial(jc, f, impulse, sA, sB);
        } else if (jc.hertz > 0.0f) {
            // A spring: its softness is physical, so it applies in every pass.
            Softness spring = makeSoft(jc.hertz, jc.dampingRatio, h);
            float C = f.length - jc.length;
            float impulse = -spring.massScale * jc.axialMass * (cdot() + spring.biasRate * C) -
                            spring.impulseScale * jc.impulse;
            impulse = boundedIncrement(jc.impulse, impulse, -maxImpulse, maxImpulse);
            applyAxial(jc, f, impulse, sA, sB);
        }
        if (jc.enableLimit && jc.minLength < jc.maxLength) {
            // One-sided limit row along `sign`·axis: C ≥ 0 is allowed (speculative
            // when positive), the accumulated impulse stays ≥ 0.
            auto limitRow = [&](float C, float sign, float& accumulated) {
                float bias = 0.0f, ms = 1.0f, is = 0.0f;
                if (C > 0.0f) {
                    bias = C * invH;
                } else if (pass == SolvePass::soft_bias) {
                    bias = jointSoft.biasRate * C;
                    ms = jointSoft.massScale;
                    is = jointSoft.impulseScale;
                } else if (pass == SolvePass::baumgarte) {
                    bias = set.pushFactor * invH * C;
                }
                float impulse = -ms * jc.axialMass * (sign * cdot() + bias) - is * accumulated;
                impulse = boundedIncrement(accumulated, impulse, 0.0f, maxImpulse);
                applyAxial(jc, f, sign * impulse, sA, sB);
            };
            // Lower limit: length ≥ minLength (pushes apart).
            limitRow(f.length - jc.minLength, 1.0f, jc.lowerImpulse);
            // Upper limit: length ≤ maxLength, a rope (pulls together).
            limitRow(jc.maxLength - f.length, -1.0f, jc.upperImpulse);
        }
    }
}

void solveDistanceJointPush(WorldState& w, float h) {
    const float invH = 1.0f / h;
    SolverArrays& s = w.solver;
    for (DistanceJointConstraint& jc : s.distanceJoints) {
        BodyState sA = jc.a >= 0 ? s.states[static_cast<std::size_t>(jc.a)] : BodyState{};
        BodyState sB = jc.b >= 0 ? s.states[static_cast<std::size_t>(jc.b)] : BodyState{};
        JointFrame f = currentFrame(jc, sA, sB);
        float C;
        if (jc.rigid) {
            C = f.length - jc.length;
        } else if (jc.enableLimit && f.length < jc.minLength) {
            C = f.length - jc.minLength;
        } else if (jc.enableLimit && f.length > jc.maxLength) {
            C = f.length - jc.maxLength;
        } else {
            continue;
        }
        // Pseudo-velocities of the two bodies, in and out of the bias arrays.
        BodyState pA{}, pB{};
        if (jc.a >= 0) {
            pA.v = s.biasV[static_cast<std::size_t>(jc.a)];
            pA.w = s.biasW[static_cast<std::size_t>(jc.a)];
        }
        if (jc.b >= 0) {
            pB.v = s.biasV[static_cast<std::size_t>(jc.b)];
            pB.w = s.biasW[static_cast<std::size_t>(jc.b)];
        }
        Vec2 dv = (pB.v + cross(pB.w, f.rB)) - (pA.v + cross(pA.w, f.rA));
        float target = -w.settings.pushFactor * invH * C;
        float impulse = -jc.axialMass * (dot(dv, f.axis) - target);
        applyAxial(jc, f, impulse, pA, pB);
        if (jc.a >= 0) {
            s.biasV[static_cast<std::size_t>(jc.a)] = pA.v;
            s.biasW[static_cast<std::size_t>(jc.a)] = pA.w;
        }
        if (jc.b >= 0) {
            s.biasV[static_cast<std::size_t>(jc.b)] = pB.v;
            s.biasW[static_cast<std::size_t>(jc.b)] = pB.w;
        }
    }
}

void storeDistanceJointImpulses(WorldState& w, float dt) {
    for (const DistanceJointConstraint& jc : w.solver.distanceJoints) {
        DistanceJoint& jt = w.joints[jc.joint];
        jt.impulse = jc.impulse;
        jt.lowerImpulse = jc.lowerImpulse;
        jt.upperImpulse = jc.upperImpulse;
        jt.lastForce = std::abs(jc.impulse + jc.lowerImpulse - jc.upperImpulse) / dt;
    }
}

}  // namespace i2d::detail
