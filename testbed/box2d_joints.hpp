// Testbed — a scene's joints as Box2D 2.4.1 joints (used by box2d_simulation.cpp).
#pragma once

#include <box2d/box2d.h>

#include <functional>
#include <string>
#include <vector>

#include "scene.hpp"

namespace tb {

/// Creates `j` in `world` as Box2D's own joint of the same kind with the same
/// settings (springs given in hertz and damping ratio become Box2D's N/m or
/// N·m/rad through b2LinearStiffness / b2AngularStiffness). `bodies` are the
/// scene's bodies, `joints` the joints made so far (a gear's joints are among
/// them). What Box2D expresses differently goes to `note`, one sentence each.
b2Joint* createBox2DJoint(b2World& world, const std::vector<b2Body*>& bodies, const std::vector<b2Joint*>& joints,
                          const JointDesc& j, const std::function<void(const std::string&)>& note);

}  // namespace tb
