// The accuracy criteria of the work-precision report, checked quickly in CI (no timings).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "cue_sim/evaluation/work_precision.hpp"
#include "cue_sim/physics/motion.hpp"

using namespace cue_sim::evaluation;
using cue_sim::physics::Integrator;

namespace
{
double startingEnergy(const ShotScene& scene)
{
  double energy = 0;
  for (const auto& b : scene.state.balls)
    energy += cue_sim::physics::mechanicalEnergy(b, scene.params);
  return energy;
}
}  // namespace

TEST(Accuracy, EventEngineIsWithinOneNanometreOfTheLongDoubleReferenceOnSingleShots)
{
  for (const ShotScene& scene : workPrecisionScenes())
  {
    if (!scene.single_shot)
      continue;
    const Samples reference = referenceRun(scene);
    const MethodResult event = runEventEngine(scene, reference, 1);
    EXPECT_LT(event.max_error, 1e-9) << scene.name;
    EXPECT_LT(event.final_error, 1e-9) << scene.name;
    EXPECT_GT(reference.times.size(), 50u) << scene.name << ": the shot lasts a while";
  }
}

TEST(Accuracy, TimeSteppersConvergeAtFirstOrderOrBetter)
{
  const ShotScene scene = workPrecisionScenes().front();  // single ball sliding to rest
  const Samples reference = referenceRun(scene);
  for (const Integrator integrator : {Integrator::SymplecticEuler, Integrator::RungeKutta4})
  {
    const MethodResult coarse = runStepper(scene, reference, integrator, 1e-2, 1);
    const MethodResult fine = runStepper(scene, reference, integrator, 1e-4, 1);
    EXPECT_LT(fine.max_error, coarse.max_error / 10) << integratorName(integrator);
    EXPECT_TRUE(fine.stepper.finished) << integratorName(integrator);
    // Not asserted: the steppers' energy. Their snap to rolling keeps v and sets the spin to
    // match, which can add rotational energy; the report shows how much (StepperReport).
  }
}

TEST(Accuracy, DormandPrinceWithLocatedEventsConvergesWithItsTolerance)
{
  // Located events remove the first-order error of the friction switch and the contacts.
  for (const ShotScene& scene : workPrecisionScenes())
  {
    if (!scene.single_shot)
      continue;
    const Samples reference = referenceRun(scene);
    const MethodResult loose = runStepper(scene, reference, Integrator::DormandPrince54, 1e-3, 1);
    const MethodResult tight = runStepper(scene, reference, Integrator::DormandPrince54, 1e-9, 1);
    EXPECT_LT(tight.max_error, 1e-6) << scene.name;
    EXPECT_LT(tight.max_error, loose.max_error / 100) << scene.name;
    EXPECT_LT(tight.stepper.max_overlap, 1e-12) << scene.name;
    // Friction only takes energy: on the cloth none is gained at all. Flight keeps it exactly, so
    // there the kinetic and potential energy's sum may round up by a few ulps of it.
    if (std::none_of(scene.state.balls.begin(), scene.state.balls.end(), [](const auto& b) { return b.airborne(); }))
      EXPECT_LE(tight.stepper.energy_gain, 0.0) << scene.name;
    else
      EXPECT_LE(tight.stepper.energy_gain, 16 * std::numeric_limits<double>::epsilon() * startingEnergy(scene))
          << scene.name;
  }
}

TEST(Accuracy, BreaksAgreeWithTheReferenceUntilTheFirstCollisions)
{
  // Chaos: small differences grow at every collision. Until the cue ball first reaches the
  // rack the double engine and the reference agree to rounding; after a break they differ.
  for (const ShotScene& scene : workPrecisionScenes())
  {
    if (scene.single_shot)
      continue;
    const Samples reference = referenceRun(scene);
    const MethodResult event = runEventEngine(scene, reference, 1);
    Samples early = reference;
    early.times.resize(8);  // 70 ms: the cue ball has not reached the apex ball yet
    early.positions.resize(8);
    const MethodResult before_rack = runEventEngine(scene, early, 1);
    EXPECT_LT(before_rack.max_error, 1e-12) << scene.name;
    EXPECT_TRUE(std::isfinite(event.max_error)) << scene.name;
  }
}
