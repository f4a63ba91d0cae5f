// Impulse2D — umbrella header.
#pragma once

#include "impulse2d/collision.hpp"
#include "impulse2d/debug_draw.hpp"
#include "impulse2d/error.hpp"
#include "impulse2d/geometry.hpp"
#include "impulse2d/id.hpp"
#include "impulse2d/impact.hpp"
#include "impulse2d/math.hpp"
#include "impulse2d/mover.hpp"
#include "impulse2d/tasks.hpp"
#include "impulse2d/types.hpp"
#include "impulse2d/world.hpp"
