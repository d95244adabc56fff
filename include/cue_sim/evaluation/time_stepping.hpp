// Time-stepped integration of the same equations of motion the event engine solves exactly:
// the baselines of the work-precision report. The contact models are the engine's own; only the
// time evolution differs.
//
// The friction force switches direction when the slip velocity passes zero. Time-steppers
// end a slip that one step of friction would remove (the friction clamp of game engines), or
// one that reversed within a step, by snapping to rolling; their error at that non-smooth
// point is first order in the step whatever their order elsewhere. Without the clamp RK4
// stalls there: its stages see the friction alternate and cancel.
//
// A ball in the air flies under gravity with its spin carried, and lands through the engine's
// ball-table model and its rule that ends a bounce sequence (a rebound slower than kSettleSpeed
// stays on the cloth). A fixed stepper finds a landing by the ball being below the slate at the
// end of a step, so a rebound slower than about e g h / (1 + e) comes down again within the next
// step, faster than it left: its bounces may never end (on the work-precision jump shot, e_table
// 0.5: at steps of 0.5 ms and more for Euler, 0.2 ms and more for RK4).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace physics
{
enum class Integrator
{
  SymplecticEuler,  ///< semi-implicit Euler: v from the old force, then r from the new v
  RungeKutta4,      ///< classical RK4
  DormandPrince54,  ///< adaptive embedded RK 5(4); contacts and state switches located on its dense output
};

const char* integratorName(Integrator integrator);

struct StepperOptions
{
  Integrator integrator = Integrator::RungeKutta4;
  double step = 1e-4;       ///< fixed step [s] (Euler, RK4); first step (Dormand-Prince)
  double tolerance = 1e-8;  ///< Dormand-Prince: relative and absolute error allowed per step
  double max_time = 120.0;  ///< [s] of simulated time
  long max_steps = 200000000;
};

struct StepperReport
{
  long steps = 0;
  long rejected_steps = 0;  ///< Dormand-Prince steps redone smaller
  long collisions = 0;
  double max_overlap = 0;       ///< deepest ball-ball or ball-cushion penetration seen [m]
  bool tunnelled = false;       ///< a ball crossed a cushion line or passed through a ball
  double energy_gain = 0;       ///< largest rise of kinetic energy over one step or contact [J]
  long slip_reversals = 0;      ///< slips ended by the clamp or by reversing within a step
  bool stalled = false;         ///< Dormand-Prince: the step collapsed below 1e-13 s and it gave up
  bool hit_step_limit = false;  ///< stopped by StepperOptions::max_steps
  bool finished = false;        ///< every ball at rest before max_time
  double end_time = 0;
};

/// Called with (t, balls) at each requested sample time.
using SampleCallback = std::function<void(double, const std::vector<Ball<double>>&)>;

class TimeStepper
{
public:
  TimeStepper(std::shared_ptr<const TableModel> table, const PhysicsParams<double>& params, const ModelChoice& models,
              const StepperOptions& options);

  /// Runs the state (balls already struck) until rest or max_time, sampling at the given
  /// ascending times (fixed steppers sample at the step nearest each time; choose times on the
  /// step grid).
  StepperReport run(TableState<double> state, const std::vector<double>& sample_times,
                    const SampleCallback& sample) const;

private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace physics
}  // namespace cue_sim
