// Error against run time: the scenes of the work-precision report, the long-double reference,
// and timed, error-measured runs of the event engine and the time-steppers (no ROS).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cue_sim/evaluation/time_stepping.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace evaluation
{
/// A shot ready to run: the cue has struck at t = 0.
struct ShotScene
{
  std::string name;
  bool single_shot = true;  ///< false for breaks, whose outcome is chaotic
  std::shared_ptr<const physics::TableModel> table;
  physics::PhysicsParams<double> params;
  physics::ModelChoice models;
  physics::TableState<double> state;
};

/// single ball sliding to rest, stun cut shot, draw shot off a cushion, a jump shot with draw over a
/// ball (the sequential cue: it flies and bounces on the slate), 9-ball break, 8-ball break; all on
/// the 7-ft table with the default contact models.
std::vector<ShotScene> workPrecisionScenes();

/// The extreme cases of the stability report, for the time-steppers: stiff friction (mu_s =
/// 50), a ball thrown at 50 m/s into a rack, a ball frozen to a cushion struck into it, a ball
/// with follow into a dead cushion (e_cushion = 0), a ball into a corner at 45 degrees,
/// Newton's cradle, a ball at 1e-9 m/s.
std::vector<ShotScene> stabilityScenes();

/// Ball centres (x, y, z) at each sample time, in the order of the scene's balls. Pocketed balls
/// are at their pocket's centre on the cloth (z = R).
struct Samples
{
  std::vector<double> times;
  std::vector<std::vector<Eigen::Vector3d>> positions;
};

/// The same shot in the long-double event engine, sampled every `interval` seconds until every
/// ball rests (at most max_time).
Samples referenceRun(const ShotScene& scene, double interval = 0.01, double max_time = 20.0);

struct MethodResult
{
  std::string method;              ///< "event", "symplectic_euler", "rk4"
  double parameter = 0;            ///< step [s] for the steppers; 0 for the event engine
  double seconds = 0;              ///< median wall time of one run
  double max_error = 0;            ///< largest |position - reference| over all samples and balls [m]
  double final_error = 0;          ///< the same at the last sample (the reference's rest) [m]
  long work = 0;                   ///< events (engine) or steps (steppers)
  physics::StepperReport stepper;  ///< what the stepper saw (steppers only)
};

/// Largest distance between two sample sets, over all times and balls, and at the last time.
void compareSamples(const Samples& run, const Samples& reference, double& max_error, double& final_error);

MethodResult runEventEngine(const ShotScene& scene, const Samples& reference, int repeats);
/// `parameter`: the step [s] of a fixed stepper, the tolerance of Dormand-Prince.
MethodResult runStepper(const ShotScene& scene, const Samples& reference, physics::Integrator integrator,
                        double parameter, int repeats);

}  // namespace evaluation
}  // namespace cue_sim
