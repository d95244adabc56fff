// Where a ball in the air goes once it is past the cushions (internal to the physics core): the
// event search names the event by it, and the resolver moves the ball by it, so both agree.
// doc/physics.md, "Balls in the air", gives the rule and what it leaves out.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/event.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "physics/engine/table_geometry.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
struct Departure
{
  EventKind kind = EventKind::OffTable;  ///< Pocketed or OffTable
  int obstacle = kLandsOnRail;           ///< the pocket (Pocketed), or the OffTablePlace
  Vec3<S> where = Vec3<S>::Zero();       ///< OffTable: where it lands on the rail, or crosses the edge
};

/// Whether a ball entering a pocket's capture circle passes over the pocket's mouth rather than
/// into it: it is in the air with its lowest point above the cushions' nose, which a ball in the
/// mouth, between the jaws, cannot be.
template <typename S>
bool fliesOverPocket(const Ball<S>& ball, const TableGeometry<S>& geometry, S ball_radius)
{
  return ball.airborne() && ball.r.z() - ball_radius > geometry.nose_height;
}

/// Whether a ball in the air meets a jaw's (or cushion end's) post on its flat top, its centre
/// above it: it lands on the table's woodwork there, as on the rail.
template <typename S>
bool onPostTop(const Ball<S>& ball, const typename TableGeometry<S>::Circle& post, const TableGeometry<S>& geometry)
{
  return ball.airborne() && ball.r.z() > geometry.nose_height &&
         (ball.r.template head<2>() - post.centre).norm() <= post.radius;
}

/// The fate of a ball in the air that has just flown over a cushion's nose or a pocket's mouth: it
/// comes down to the rails' top (or is below it already, and lands at once). Landing inside a
/// pocket's capture circle and the table's edge, it drops into that pocket; inside the edge
/// elsewhere, it lands on the rail; beyond the edge, it falls to the floor, and `where` is the point
/// at which its centre crossed the edge.
template <typename S>
Departure<S> departureOf(const Ball<S>& ball, const TableGeometry<S>& geometry, const PhysicsParams<S>& p);

}  // namespace physics
}  // namespace cue_sim
