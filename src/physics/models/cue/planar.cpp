// The cue's impulse along its axis (Alciatore TP) with its downward part taken by the
// cloth: the ball stays on it whatever the cue's elevation, as in the engines that keep balls in
// the plane (FastFiz; pooltool before its airborne state). The elevation still tilts the spin
// axis (masse) and shortens the horizontal speed by cos(theta).
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class PlanarCue : public CueModel<S>
{
public:
  void strike(Ball<S>& ball, const CueStrike<S>& s, const PhysicsParams<S>& p) const override
  {
    applyCueStrike(ball, s, p);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cue, planar, PlanarCue)

}  // namespace physics
}  // namespace cue_sim
