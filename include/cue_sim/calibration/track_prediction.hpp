// Where a shot's balls are at the instants a camera or a tracker saw them: what a fit of the
// simulator to a real table compares with the observations (cue_sim.calibrate, doc/calibration.md).
// The engine is exact between events, so a prediction at any instant costs the events before it
// and a closed-form evaluation; an event between two frames is where it lies, not at a frame.
// No ROS and no Python.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/thread_pool.hpp"

namespace cue_sim
{
namespace calibration
{
/// A strike applied at the start of a track.
struct TrackStrike
{
  int ball_id = 0;
  physics::CueStrike<double> cue;
};

/// One shot to predict: the table when its track begins and the instants asked for.
struct TrackRequest
{
  /// The balls at start.time; any may be moving (a cue ball just struck, its velocity and spin
  /// given). Valid on the engine (Engine::whyInvalid).
  physics::TableState<double> start;
  std::optional<TrackStrike> strike;  ///< applied at start.time before anything moves, if given
  std::vector<double> times;          ///< [s] on start's clock: ascending, none before start.time
  /// [s] how long the camera's shutter is open around each instant, in [0, kMaxExposure]: a
  /// position is then the average over it, as a detector finds the centre of a smeared ball.
  /// Exposures of consecutive instants may not overlap.
  double exposure = 0;
};

/// The longest exposure a prediction averages over [s] (the node's bound on ~camera/exposure).
constexpr double kMaxExposure = 0.1;
/// Slices an exposure is averaged over when an event falls within it (elsewhere the middle is
/// the average to the second order: a sliding ball's deceleration of 5 m/s^2 over 4 ms moves its
/// mean 3 um from its middle). A contact's kink in the exposure leaves the 8-slice midpoint
/// average within v e / 512 of the true one: 0.02 mm at 3 m/s and 4 ms, where the middle alone is
/// up to v e / 8 = 1.5 mm off, always on the same side (the position is convex or concave in time
/// at the kink), which biases a restitution fitted to frames at 0.05 %.
constexpr int kExposureSlices = 8;

/// What the contacts of a predicted shot were, up to its last instant asked for: what tells a fit
/// which coefficients the shot can determine.
struct ContactCounts
{
  int ball_ball = 0;
  int cushion = 0;  ///< straight cushions and jaws
  int pocketed = 0;
};

struct TrackPrediction
{
  /// Empty if predicted; else why not (a strike refused, a request out of order, the event limit).
  std::string error;
  std::vector<double> positions;       ///< times x balls x 2 [m] (x, y in the table frame), start's ball order
  std::vector<std::uint8_t> on_table;  ///< times x balls: 0 once a ball is pocketed
  ContactCounts contacts;
};

/// Empty if `request` can be predicted on `engine`, else which field is wrong and why.
std::string whyBadRequest(const physics::Engine<double>& engine, const TrackRequest& request);

/// Every request predicted on the pool's threads, in the order of `requests`. A request that
/// cannot be predicted has its error set; the others are unaffected.
std::vector<TrackPrediction> predictTracks(const physics::Engine<double>& engine,
                                           const std::vector<TrackRequest>& requests, physics::ThreadPool& pool);

}  // namespace calibration
}  // namespace cue_sim
