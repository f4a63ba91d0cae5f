// Testbed — a scene file's joint once every body is known: its body (or, for
// a gear, joint) references resolved, and the values the file left to the
// initial layout measured there (see parts.hpp).
#include <cmath>
#include <numbers>

#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

namespace {

i2d::Vec2 worldPoint(const BodyDesc& b, i2d::Vec2 local) {
    return i2d::transformPoint({b.def.position, i2d::makeRot(b.def.angle)}, local);
}

// angle(B) − angle(A) in the initial layout, in [−π, π].
float layoutAngle(const BodyDesc& a, const BodyDesc& b) {
    return static_cast<float>(std::remainder(double(b.def.angle) - double(a.def.angle), 2.0 * std::numbers::pi));
}

float layoutLength(const PendingJoint& pj, i2d::Vec2 p, i2d::Vec2 q, const char* what) {
    const float len = i2d::distance(p, q);
    if (!(len >= i2d::kLinearSlop))
        fail(pj.loc, std::string("the ") + what + " are " + fmt(len) +
                         " m apart at the start; give a length of at least 0.005 m or move the anchors");
    return len;
}

const char* jointTypeName(i2d::JointType t) { return enumName(t); }

}  // namespace

int Builder::resolveJoint(const json& ref, const Loc& loc, std::size_t self) const {
    int index = -1;
    if (ref.is_string()) {
        auto it = jointNames.find(ref.get<std::string>());
        if (it == jointNames.end()) fail(loc, "unknown joint name '" + ref.get<std::string>() + "'");
        index = it->second;
    } else {
        const std::int64_t n = static_cast<std::int64_t>(joints.size() - fileJointBase);
        index = static_cast<int>(fileJointBase) + static_cast<int>(checkInt(ref, loc, 0, n - 1));
    }
    if (static_cast<std::size_t>(index) >= self)
        fail(loc, "refers to " + joints[static_cast<std::size_t>(index)].loc.path +
                      ", which does not come before this gear (a gear follows the joints it couples)");
    return index;
}

JointDesc resolveJoint(const PendingJoint& pj, const Builder& bld, const std::vector<JointDesc>& done) {
    JointDesc jd;
    jd.name = pj.name;
    jd.def = pj.def;
    if (pj.type() == i2d::JointType::gear) {
        const std::size_t self = done.size();
        jd.joint1 = bld.resolveJoint(*pj.ref1, pj.ref1Loc, self);
        jd.joint2 = bld.resolveJoint(*pj.ref2, pj.ref2Loc, self);
        if (jd.joint1 == jd.joint2) fail(pj.ref2Loc, "a gear couples two different joints (both are the same)");
        for (auto [index, loc] : {std::pair{jd.joint1, &pj.ref1Loc}, std::pair{jd.joint2, &pj.ref2Loc}}) {
            const i2d::JointType t = done[static_cast<std::size_t>(index)].type();
            if (t != i2d::JointType::revolute && t != i2d::JointType::prismatic)
                fail(*loc, "refers to " + bld.joints[static_cast<std::size_t>(index)].loc.path + ", a " +
                               jointTypeName(t) + " joint; a gear couples revolute or prismatic joints");
        }
        jd.bodyA = done[static_cast<std::size_t>(jd.joint1)].bodyB;
        jd.bodyB = done[static_cast<std::size_t>(jd.joint2)].bodyB;
    } else {
        jd.bodyA = pj.refA ? bld.resolve(*pj.refA, pj.refALoc) : pj.indexA;
        jd.bodyB = pj.refB ? bld.resolve(*pj.refB, pj.refBLoc) : pj.indexB;
    }
    const int a = jd.bodyA, b = jd.bodyB;
    if (a == b) fail(pj.loc, "a joint needs two different bodies (both are body " + std::to_string(a) + ")");
    const BodyDesc& ba = bld.bodies[static_cast<std::size_t>(a)];
    const BodyDesc& bb = bld.bodies[static_cast<std::size_t>(b)];
    if (ba.def.type != i2d::BodyType::dynamic_body && bb.def.type != i2d::BodyType::dynamic_body)
        fail(pj.loc, "a joint needs at least one dynamic body");

    std::visit(
        [&](auto& d) {
            using D = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<D, i2d::DistanceJointDef>) {
                if (!pj.hasLength)
                    d.length = layoutLength(pj, worldPoint(ba, d.localAnchorA), worldPoint(bb, d.localAnchorB),
                                            "anchors");
            } else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef> ||
                                 std::is_same_v<D, i2d::PrismaticJointDef> || std::is_same_v<D, i2d::WeldJointDef>) {
                if (!pj.hasReferenceAngle) d.referenceAngle = layoutAngle(ba, bb);
            } else if constexpr (std::is_same_v<D, i2d::PulleyJointDef>) {
                if (!pj.hasLengthA)
                    d.lengthA = layoutLength(pj, d.groundAnchorA, worldPoint(ba, d.localAnchorA),
                                             "ground anchor A and anchor A");
                if (!pj.hasLengthB)
                    d.lengthB = layoutLength(pj, d.groundAnchorB, worldPoint(bb, d.localAnchorB),
                                             "ground anchor B and anchor B");
            }
        },
        jd.def);
    return jd;
}

}  // namespace tb::scene_file
