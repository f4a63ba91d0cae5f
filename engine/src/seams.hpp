// Seams between separate static shapes (seams.cpp): ghost contact points at
// internal edges and shared vertices are dropped from a manifold.
#pragma once

#include "impulse2d/collision.hpp"

namespace i2d::detail {

struct WorldState;
struct Contact;
struct Shape;

/// For a contact between a static shape and a moving one: drops the points of
/// `m` whose normal is not a normal of the static geometry as a whole (it
/// points into an adjacent static shape at a face or vertex the two share).
/// Only for a contact whose Contact::seamRule is set (hasSeamRule).
void dropSeamGhosts(const WorldState& w, const Contact& c, Manifold& m);

/// Whether dropSeamGhosts may drop points of a contact between shapes `a`
/// and `b` (ordered as in the contact) on bodies of these static-ness.
bool hasSeamRule(const Shape& a, const Shape& b, bool aStatic, bool bStatic);

}  // namespace i2d::detail
