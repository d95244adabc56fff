// Where a ball in sustained contact touches what holds it, at one instant: the gap, the normal and
// the curvature of the gap function, for each surface a ball can rest on or roll round (another
// ball, the slate, a cushion's face or the edge of its nose, a post's side or its rim). Internal to
// the physics core (src/physics/supports/); doc/physics.md, "Resting contact", derives the terms.
#pragma once

#include <cstdint>
#include <vector>

#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/types.hpp"
#include "physics/engine/table_geometry.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
using Mat3 = Eigen::Matrix<S, 3, 3>;

/// What a ball touches. A cushion is a face below its nose's height and the edge of the nose above
/// it; a jaw or a cushion's end is a post's side below it and its rim above it.
enum class Surface : std::uint8_t
{
  Ball,
  Slate,
  Face,
  Edge,
  PostSide,
  Rim,
};

const char* surfaceName(Surface surface);

/// One contact at an instant. The gap function phi (the distance between the surfaces) has the
/// gradient n (unit, from the support into the ball) and the Hessian H, so that for the velocity of
/// the ball relative to its support, v: phi' = n . v, n' = H v, and phi'' = n . a + v . H v.
template <typename S>
struct ContactGeometry
{
  Surface surface = Surface::Slate;
  S gap = S(0);  ///< [m]; negative: they overlap
  Vec3<S> n = Vec3<S>::UnitZ();
  Mat3<S> H = Mat3<S>::Zero();
  /// For a cushion: how far along the segment the centre is [m] (0 to its length beside it), and
  /// how far in front of its line (negative: behind it, over the cushion's top if above its nose).
  S along = S(0), across = S(0);
};

/// Two surfaces whose gap is within this [m] touch, for balls in sustained contact: a few contact
/// tolerances, since the piece each ball follows may stray one tolerance from its integrated path.
/// The groups gather what touches by it, and the event search leaves such a contact of a ball in a
/// group to the group's equations.
template <typename S>
S supportTouch(const PhysicsParams<S>& p)
{
  return S(4) * p.contact_tolerance;
}

/// A ball whose centre is at r touching a ball whose centre is at `other` (both of radius R).
template <typename S>
ContactGeometry<S> ballContact(const Vec3<S>& r, const Vec3<S>& other, S R);

/// The slate under a ball whose centre is at r.
template <typename S>
ContactGeometry<S> slateContact(const Vec3<S>& r, S R);

/// Cushion k: its face if the centre is at or below the nose's height, the nose's edge above it.
template <typename S>
ContactGeometry<S> cushionContact(const TableGeometry<S>& g, int k, const Vec3<S>& r, S R);

/// Post k (a jaw or a cushion's end): its side at or below the nose's height, its rim above it.
template <typename S>
ContactGeometry<S> postContact(const TableGeometry<S>& g, int k, const Vec3<S>& r, S R);

/// Whether a cushion contact is one the ball can be in: beside the segment, and in front of its line
/// (behind it, above the nose, the ball is over the cushion's top and has left the playing surface).
template <typename S>
bool onCushion(const ContactGeometry<S>& c, S length)
{
  return c.along >= S(0) && c.along <= length && c.across >= S(0);
}

/// A wall a ball touches: a cushion (its face or its nose's edge, by `segment`) or a post (its side or
/// its rim, by `circle`).
struct WallTouch
{
  Surface surface;
  int index;  ///< the segment's or the circle's
};

/// Every wall a ball whose centre is at r touches, its gap within `touch` [m] (a cushion only beside it
/// and in front of its line), in the order of the table's segments, then its circles.
template <typename S>
void wallsTouching(const TableGeometry<S>& g, const Vec3<S>& r, S R, S touch, std::vector<WallTouch>& out);

/// Whether a ball in the air has left the playing surface over a wall's top: its centre above the
/// noses, behind a cushion's line beside it (or over a post's flat top).
template <typename S>
bool overTheTop(const TableGeometry<S>& g, const Vec3<S>& r);

}  // namespace physics
}  // namespace cue_sim
