// When a campaign shot must have ended, and which shots cannot end by physics.
#include "shot_ending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cue_sim/evaluation/soak.hpp"

namespace cue_sim
{
namespace evaluation
{
namespace
{
/// The stopping time is this many times the longest a ball with all the energy could move: balls
/// hand their motion on in collisions, so the last to stop may start late.
constexpr double kStopMargin = 2.0;
/// No shot runs longer than this [s] of simulated time (a ball at 6 m/s rolling against a resistance
/// of 1e-3 under a tenth of the Earth's gravity stops after 6e4 s).
constexpr double kLongestShot = 1e5;
/// An event storm: this many events within this span [s] of simulated time. A shot that cannot
/// end meets cushions and balls at most a few hundred times a second (a ball at the registry's
/// 12 m/s crosses its own radius of 1 mm in a tenth of a millisecond); a storm's events are
/// rounding apart.
constexpr std::size_t kStormEvents = 1000;
constexpr double kStormSpan = 1e-3;

/// Time [s] for a motion of size `amount` to be taken out at `rate` per second; none if the rate is
/// zero (that motion never stops: endlessByPhysics).
double spend(double amount, double rate)
{
  return rate > 0 ? amount / rate : 0.0;
}
}  // namespace

double stoppingTime(const physics::TableState<double>& struck, const physics::PhysicsParams<double>& p)
{
  const double m = p.ball_mass, R = p.ball_radius, g = p.gravity, I = 0.4 * m * R * R;
  double energy = 0;
  for (const physics::Ball<double>& b : struck.balls)
    if (b.inPlay())
      energy += 0.5 * m * b.v.squaredNorm() + 0.5 * I * b.w.squaredNorm() + m * g * std::max(b.r.z() - R, 0.0);
  const double v = std::sqrt(2 * energy / m), w = std::sqrt(2 * energy / I);
  // Sliding: the slip (at most v + R w) goes at 7/2 mu_slide g. Rolling: the speed at mu_roll g.
  // Spinning: w_z at 5 mu_spin g / (2 R). Bouncing: each flight 2 v_z / g, the next e_table of it.
  const double slide = spend(v + R * w, 3.5 * p.mu_slide * g);
  const double roll = spend(v, p.mu_roll * g);
  const double spin = spend(w, 2.5 * p.mu_spin * g / R);
  const double bounce = 2 * v / g / (1 - std::min(p.e_table, 0.999));
  const double longest = kStopMargin * (slide + roll + spin + bounce);
  return std::clamp(longest, SoakLimits::max_shot_time, kLongestShot);
}

std::string endlessByPhysics(const physics::TableState<double>& state, const physics::PhysicsParams<double>& p)
{
  using physics::Motion;
  for (const physics::Ball<double>& b : state.balls)
  {
    const std::string ball = "ball " + std::to_string(b.id);
    // With no rolling resistance a ball that moves on or over the cloth rolls for ever once its
    // slide (or its flight) ends, and may go on setting the others moving.
    if (b.translating() && p.mu_roll == 0)
      return ball + " moves, and rolls for ever once it rolls: mu_roll = 0";
    if (b.motion == Motion::Sliding && p.mu_slide == 0)
      return ball + " slides with mu_slide = 0";
    if (b.moving() && !b.airborne() && b.w.z() != 0 && p.mu_spin == 0)
      return ball + " spins with mu_spin = 0";
  }
  return "";
}

bool endsInAStorm(const std::vector<double>& times)
{
  if (times.size() < kStormEvents)
    return false;
  return times.back() - times[times.size() - kStormEvents] < kStormSpan;
}

}  // namespace evaluation
}  // namespace cue_sim
