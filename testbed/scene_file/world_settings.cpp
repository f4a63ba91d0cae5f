// Testbed — a scene file's "world" object: the world settings (see parts.hpp).
#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

i2d::WorldSettings parseWorld(const json& j, const Loc& loc) {
    Obj o(j, loc,
          {"comment",
           "gravity",
           "position_correction",
           "impact_model",
           "velocity_iterations",
           "position_iterations",
           "substeps",
           "push_factor",
           "penetration_slop",
           "max_push_speed",
           "contact_hertz",
           "contact_damping_ratio",
           "joint_hertz",
           "joint_damping_ratio",
           "exact_joint_mass_ratio",
           "exact_column_tilt",
           "restitution_threshold",
           "impact_threshold",
           "hit_event_threshold",
           "speculative_distance",
           "manifold_reuse_distance",
           "aabb_margin",
           "max_linear_speed",
           "enable_warm_starting",
           "enable_continuous",
           "enable_sleep",
           "time_to_sleep",
           "linear_sleep_tolerance",
           "angular_sleep_tolerance"});
    o.checkUnknown();
    o.str("comment", "");
    i2d::WorldSettings s;
    s.gravity = o.vec("gravity", s.gravity, 1.0e4);
    s.positionCorrection = enumField(o, "position_correction", s.positionCorrection);
    s.impactModel = enumField(o, "impact_model", s.impactModel);
    s.velocityIterations = static_cast<int>(o.integer("velocity_iterations", s.velocityIterations, 1, kMaxIterations));
    s.positionIterations = static_cast<int>(o.integer("position_iterations", s.positionIterations, 0, kMaxIterations));
    s.substeps = static_cast<int>(o.integer("substeps", s.substeps, 1, kMaxIterations));
    s.pushFactor = o.f("push_factor", s.pushFactor, {0, 1});
    s.penetrationSlop = o.f("penetration_slop", s.penetrationSlop, {0, 1});
    s.maxPushSpeed = o.f("max_push_speed", s.maxPushSpeed, {0, kMaxSpeed});
    s.contactHertz = o.f("contact_hertz", s.contactHertz, {0, kMaxRate});
    s.contactDampingRatio = o.f("contact_damping_ratio", s.contactDampingRatio, {0, kMaxRate});
    s.jointHertz = o.f("joint_hertz", s.jointHertz, {0, kMaxRate});
    s.jointDampingRatio = o.f("joint_damping_ratio", s.jointDampingRatio, {0, kMaxRate});
    s.exactJointMassRatio = o.f("exact_joint_mass_ratio", s.exactJointMassRatio, {1, 1.0e30});
    s.exactColumnTilt = o.boolean("exact_column_tilt", s.exactColumnTilt);
    s.restitutionThreshold = o.f("restitution_threshold", s.restitutionThreshold, {0, kMaxSpeed});
    s.impactThreshold = o.f("impact_threshold", s.impactThreshold, {0, kMaxSpeed});
    s.hitEventThreshold = o.f("hit_event_threshold", s.hitEventThreshold, {0, kMaxSpeed});
    s.speculativeDistance = o.f("speculative_distance", s.speculativeDistance, {0, 10});
    s.manifoldReuseDistance = o.f("manifold_reuse_distance", s.manifoldReuseDistance, {0, 10});
    s.aabbMargin = o.f("aabb_margin", s.aabbMargin, {0, 100});
    s.maxLinearSpeed = o.f("max_linear_speed", s.maxLinearSpeed, {0, kMaxSpeed, true});
    s.enableWarmStarting = o.boolean("enable_warm_starting", s.enableWarmStarting);
    s.enableContinuous = o.boolean("enable_continuous", s.enableContinuous);
    s.enableSleep = o.boolean("enable_sleep", s.enableSleep);
    s.timeToSleep = o.f("time_to_sleep", s.timeToSleep, {0, kMaxRate});
    s.linearSleepTolerance = o.f("linear_sleep_tolerance", s.linearSleepTolerance, {0, kMaxSpeed});
    s.angularSleepTolerance = o.f("angular_sleep_tolerance", s.angularSleepTolerance, {0, kMaxSpeed});
    return s;
}

}  // namespace tb::scene_file
