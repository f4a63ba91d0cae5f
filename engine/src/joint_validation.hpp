// Checks of the joint definitions' values (joint_validation.cpp), shared by
// the World's create…Joint and set…JointDef; each throws i2d::Error naming the
// value. Bodies and joints named by handle are checked by the callers.
#pragma once

#include "impulse2d/joints.hpp"

namespace i2d::detail {

void validateJointDef(const DistanceJointDef& def);
void validateJointDef(const RevoluteJointDef& def);
void validateJointDef(const PrismaticJointDef& def);
void validateJointDef(const WeldJointDef& def);
void validateJointDef(const WheelJointDef& def);
void validateJointDef(const MotorJointDef& def);
void validateJointDef(const MouseJointDef& def);
void validateJointDef(const PulleyJointDef& def);
void validateJointDef(const GearJointDef& def);

}  // namespace i2d::detail
