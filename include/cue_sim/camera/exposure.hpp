// The balls of the live table through a camera's exposure, from their exact trajectories: a copy
// of its balls is advanced across it by its clock (events, spins and turning included), so a ball
// at 5 m/s smears as far as it travels while the shutter is open.
#pragma once

#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/session/live_balls.hpp"
#include "cue_sim/session/table_clock.hpp"

namespace cue_sim
{
namespace camera
{
/// Farthest a ball's surface moves between two instants of an exposure [m]: 1 mm, under half a
/// pixel of the default camera (about 2.3 mm a pixel on the cloth), so that a smear is smooth.
constexpr double kBlurStep = 0.001;
/// Most instants an exposure is sampled at: a bound on the cost of a frame (a ball at 10 m/s
/// in a 4 ms exposure needs 40).
constexpr int kMaxInstants = 48;

/// The balls as they were at their last look (LiveBalls::look).
std::vector<BallPose> posesOf(const session::LiveBalls& balls);
/// The balls brought up to the physics time `clock` gives `stamp`, and looked at.
void advanceTo(session::LiveBalls& balls, const session::TableClock& clock, session::Stamp stamp);
/// How many instants an exposure of `physics_duration` [s] needs on `balls` as they are: enough
/// that no ball's surface (its centre's speed plus its spin's, R |w|) moves more than kBlurStep
/// between two, within [1, kMaxInstants].
int instantsFor(const session::LiveBalls& balls, double physics_duration);
/// The balls through an exposure of `duration` [s] of stamp time from `start` (at or after the
/// clock's last stamp): `balls` is a copy of the live table's and is advanced.
Exposure exposureOf(session::LiveBalls balls, const session::TableClock& clock, session::Stamp start, double duration);

}  // namespace camera
}  // namespace cue_sim
