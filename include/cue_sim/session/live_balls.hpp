// The balls of the live table as they move: their simulation (a physics::Simulation, its event
// search kept between calls), each ball as of the last advance and how it is turned, and new
// physics that waits for the balls to rest. It knows physics time only; the live table maps its
// caller's stamps to it (TableClock). A plain value: the camera advances a copy of it through an
// exposure, and what it shows is the live table's exact motion.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/session/ball_orientations.hpp"

namespace cue_sim
{
namespace session
{
class LiveBalls
{
public:
  /// An empty table on `engine`. With `orientations`, each ball's orientation is carried along
  /// its motion; without, they stay identity and an advance is one call of the simulation.
  LiveBalls(std::shared_ptr<const physics::Engine<double>> engine, bool orientations);

  const physics::Engine<double>& engine() const { return *engine_; }
  const std::shared_ptr<const physics::Engine<double>>& engineShared() const { return engine_; }
  const physics::TableState<double>& state() const { return simulation_.state(); }
  double time() const { return simulation_.time(); }
  bool atRest() const { return simulation_.atRest(); }

  /// Processes every event up to physics time `time` (appending them to `happened`), turning the
  /// balls on the way. If a shot reaches the engine's event limit (strikes run to rest first, so
  /// only balls set moving by hand can), the table goes on from its last event.
  void advance(double time, std::vector<physics::Event<double>>* happened = nullptr);
  /// Takes what balls() and orientations() show from the balls now (after an advance or a change).
  void look();
  /// Every ball as of the last look.
  const std::vector<physics::Ball<double>>& balls() const { return balls_; }
  /// How each ball of balls() is turned (its own frame to the table frame), carried along its
  /// exact motion from when it was placed (physics::rotationAlong).
  const std::vector<Eigen::Quaterniond>& orientations() const { return orientations_now_; }

  // Changes, each at time() and checked by the caller (the simulation throws on what it refuses).
  /// Replaces every ball (a rack, a reset, a whole table, a game's next position).
  void startFrom(physics::TableState<double> state);
  /// A table at rest restarts at physics time 0: a strike from rest, like a prediction, starts there.
  void restartAtRest();
  void strike(int ball_id, const physics::CueStrike<double>& strike);
  /// Empty if the ball may be placed now (on the cloth, overlapping none but the ball it moves).
  std::string whyNotPlaceable(const physics::Ball<double>& ball) const { return simulation_.whyNotPlaceable(ball); }
  /// Adds the ball, or moves the ball with its id.
  void place(const physics::Ball<double>& ball);
  void remove(int ball_id);

  /// Empty if the balls as they are fit `engine` (a larger ball must still fit where they are).
  std::string whyNotFit(const physics::Engine<double>& engine) const;
  /// New coefficients and models for when the balls rest: a shot in flight ends with the physics
  /// it started with, as its prediction said. applyPendingPhysics applies them.
  void setPendingPhysics(std::shared_ptr<const physics::Engine<double>> engine) { pending_engine_ = std::move(engine); }
  bool physicsPending() const { return pending_engine_ != nullptr; }
  /// Applies the waiting physics if the balls rest and still fit it: true if it did.
  bool applyPendingPhysics();

  /// Changes when the balls are placed anew (rack, reset, edits, new physics): what is drawn of
  /// the table may have to be drawn again.
  long layoutVersion() const { return layout_version_; }
  /// Counts the strikes: a shot drawn in advance (a preview) is stale once this or
  /// layoutVersion() changes.
  long strikeCount() const { return strike_count_; }

private:
  /// simulation_.advance(time, happened), check by check, so that each ball changes at most once a
  /// step and is turned along the motion it had until then: the same events and balls, bit for bit.
  void advanceTurning(double time, std::vector<physics::Event<double>>* happened);

  std::shared_ptr<const physics::Engine<double>> engine_;
  std::shared_ptr<const physics::Engine<double>> pending_engine_;  ///< waiting for the balls to rest
  physics::Simulation<double> simulation_;
  bool turning_;
  BallOrientations orientations_;
  std::vector<physics::Ball<double>> balls_;
  std::vector<Eigen::Quaterniond> orientations_now_;  ///< of balls_
  bool looked_at_rest_ = false;                       ///< balls_ are at rest and nothing has moved since
  long layout_version_ = 0;
  long strike_count_ = 0;
};

/// The balls in play sitting on the cloth with radius R: where they are under another radius.
physics::TableState<double> onCloth(physics::TableState<double> state, double R);

}  // namespace session
}  // namespace cue_sim
