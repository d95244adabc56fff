// Coefficients of the ball, cloth, cushion and cue models. SI units throughout (REP 103).
// Defaults and sources: see the parameter table in README.md ("Physics parameters").
#pragma once

#include <string>

namespace cue_sim
{
namespace physics
{
template <typename S>
struct PhysicsParams
{
  S ball_mass = S(0.170097);    ///< m [kg]; a 6 oz pool ball.
  S ball_radius = S(0.028575);  ///< R [m]; a 2.25 in pool ball.
  S gravity = S(9.81);          ///< g [m/s^2].
  S mu_slide = S(0.2);          ///< ball-cloth sliding friction [-]; 0.15-0.4 (Alciatore).
  S mu_roll = S(0.01);          ///< ball-cloth rolling resistance [-]; 0.005-0.015 (Alciatore).
  /// z-spin friction [-]: w_z decays at 5 mu_spin g / (2R) = 10.9 rad/s^2 with the default
  /// 0.4444 R (R in metres, as in pooltool's parameter set); 5-15 rad/s^2 (Alciatore).
  S mu_spin = S(0.4444 * 0.028575);
  S e_ball = S(0.95);  ///< ball-ball restitution [-]; 0.92-0.98 (Alciatore).
  /// Ball-ball friction fit mu_b(v) = a + b exp(-c v_rel) (Alciatore TP A-14); frictional model.
  S mu_ball_a = S(0.009951);
  S mu_ball_b = S(0.108);
  S mu_ball_c = S(1.088);          ///< [s/m]
  S e_cushion = S(0.85);           ///< ball-cushion restitution [-]; 0.6-0.9 (Alciatore, Han 2005).
  S f_cushion = S(0.2);            ///< ball-cushion friction [-] (Han 2005 model).
  S cushion_height = S(0.036576);  ///< h [m], cushion nose above the cloth: 0.64 x 2R (Han 2005 model).
  S cue_mass = S(0.567);           ///< M [kg]; a 20 oz cue.
  S cue_end_mass = S(0.0056699);   ///< m_e [kg], the cue's end mass that drives squirt (TP A-31).
  S cue_tip_radius = S(0.0106);    ///< [m].

  /// Deceleration of a sliding ball's contact-point slip is 7/2 of this [m/s^2].
  S slideDecel() const { return mu_slide * gravity; }
  S rollDecel() const { return mu_roll * gravity; }
  /// Angular deceleration of z-spin [rad/s^2].
  S spinDecel() const { return S(5) * mu_spin * gravity / (S(2) * ball_radius); }

  /// Empty when every coefficient is finite and in its physical range, else which one is not.
  std::string validate() const;

  template <typename T>
  PhysicsParams<T> cast() const
  {
    PhysicsParams<T> p;
    p.ball_mass = T(ball_mass);
    p.ball_radius = T(ball_radius);
    p.gravity = T(gravity);
    p.mu_slide = T(mu_slide);
    p.mu_roll = T(mu_roll);
    p.mu_spin = T(mu_spin);
    p.e_ball = T(e_ball);
    p.mu_ball_a = T(mu_ball_a);
    p.mu_ball_b = T(mu_ball_b);
    p.mu_ball_c = T(mu_ball_c);
    p.e_cushion = T(e_cushion);
    p.f_cushion = T(f_cushion);
    p.cushion_height = T(cushion_height);
    p.cue_mass = T(cue_mass);
    p.cue_end_mass = T(cue_end_mass);
    p.cue_tip_radius = T(cue_tip_radius);
    return p;
  }
};

}  // namespace physics
}  // namespace cue_sim

#include <vector>

namespace cue_sim
{
namespace physics
{
/// One coefficient, declared once: its name as scene files and ROS parameters spell it
/// (config/physics.yaml), its unit, and the range PhysicsParams::validate accepts, with why.
struct ParamField
{
  const char* name;
  double PhysicsParams<double>::*member;
  const char* unit;  ///< "-" for a pure number
  double min, max;   ///< the accepted range, bounds included; NaN for a range that depends on others
  const char* range_reason;
};

/// Every coefficient of PhysicsParams, in the order of config/physics.yaml. cushion_height has a
/// range of its own besides: strictly between R and 2R (validate says why).
const std::vector<ParamField>& physicsParamFields();

}  // namespace physics
}  // namespace cue_sim
