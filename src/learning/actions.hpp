// An environment's action: its box (names, bounds in the cue's own units) and the strike it
// stands for. Every point of the box is a valid strike, so that sampled actions play; what lies
// outside it is refused, naming the component.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/learning/environment.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace learning
{
/// The slowest strike an action may ask for [m/s]: slower moves the cue ball under a centimetre.
constexpr double kMinActionSpeed = 0.05;
/// The largest offset a relative action may add to the ghost-ball aim [rad] (about 11.5 degrees):
/// enough to cover throw and squirt at any cut, small enough that the aim still means the shot.
constexpr double kMaxCutOffset = 0.2;

/// What a relative action aims at: the balls it may choose (ids, in order) and the table.
struct AimContext
{
  const physics::TableState<double>* table = nullptr;
  const physics::TableModel* model = nullptr;
  double ball_radius = 0;
  std::vector<int> choices;  ///< the object balls a relative action chooses among, in id order
};

/// What an action asks for besides the strike's numbers: the ball and pocket a relative action aims
/// at (a game calls them), and in games where the cue ball goes in hand and whether to push out.
struct ShotPlan
{
  physics::CueStrike<double> strike;       ///< planned; the environment adds the execution noise
  int aimed_ball = -1, aimed_pocket = -1;  ///< relative actions: what the aim names (-1 for none)
  bool push_out = false;                   ///< 9-ball: declared (used only where the rules allow it)
};

class ActionLayout
{
public:
  explicit ActionLayout(const EnvOptions& options);
  const BoxSpec& box() const { return box_; }
  /// Whether the action aims at a ball and a pocket (and needs AimContext's choices).
  bool relative() const { return relative_; }
  /// Empty if `action` (box().size() values) is inside the box, else which component is not.
  std::string whyInvalid(const double* action, std::size_t size) const;
  /// The shot `action` plans from the table in `aim`. A relative action with no ball to choose
  /// hits straight up the table.
  ShotPlan plan(const double* action, const AimContext& aim) const;
  /// Games: where in the region the cue ball may go the action places it, as fractions of the
  /// region's length and width (false for tasks whose action has no placement).
  bool placement(const double* action, double& u, double& v) const;

private:
  bool relative_ = false, spin_ = false, place_ = false, push_out_ = false;
  BoxSpec box_;
};

/// The tip offset (a, b) [R] for a point of the square [-1, 1]^2, on the disc of the cue's
/// largest offset: the square's edges go to the disc's rim (the elliptical grid map), so every
/// point of the action's box is a valid tip position and the centre stays the centre.
void squareToTipOffset(double u, double v, double& a, double& b);

/// Where a shot into `pocket` is aimed: the point of the cloth's edge nearest its capture circle's
/// centre, the middle of its mouth. (The centre itself lies behind the mouth: a line to it from
/// along a rail meets the rail's cushion before the mouth.)
Eigen::Vector2d pocketAimPoint(const physics::TableModel& table, const physics::Pocket& pocket);

/// The heading [rad] of the cue ball at `cue` for the ghost-ball aim that sends the ball at
/// `object` to `target`.
double ghostBallHeading(const Eigen::Vector2d& cue, const Eigen::Vector2d& object, const Eigen::Vector2d& target,
                        double ball_radius);

}  // namespace learning
}  // namespace cue_sim
