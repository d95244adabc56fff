// A ball in the air against the table's walls in three dimensions (internal to the event search).
// Each cushion is a block whose face rises from the cloth to its nose at nose_height and whose
// top runs back from the nose to the rail; each jaw and cushion end is a post as high. A ball
// meets a wall's face while its centre is at or below the top, the nose's edge (or the post's
// rim) while above it, and flies over the wall when its centre passes the nose line above it.
// doc/physics.md, "Balls in the air", derives the gaps.
#pragma once

#include "physics/search/candidates.hpp"

namespace cue_sim
{
namespace physics
{
/// Lowers `first` to the ball's earliest meeting with a cushion, jaw or pocket, or flight over a
/// cushion, before it: `path` about `base`, for a ball in the air. The cushions and posts in
/// `touching` (those a ball in sustained contact touches, its group's to follow) are left out.
template <typename S>
void findAirborneWallEvents(const Trajectory<S>& path, S base, const TableGeometry<S>& geometry, S ball_radius,
                            Candidate<S>& first, const std::vector<WallTouch>* touching = nullptr);

}  // namespace physics
}  // namespace cue_sim
