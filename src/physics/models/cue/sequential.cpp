// The cue's impulse along its axis (Alciatore TP ), down into the slate when the cue is
// elevated; the engine then lands the ball through the ball-table model, which throws it up with
// e_table of that downward speed and its friction at the slate. The two impulses one after the
// other, as pooltool resolves an elevated strike: the cue has left the ball before the slate
// answers (the cue's contact lasts about a millisecond, the slate's well under it).
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class SequentialCue : public CueModel<S>
{
public:
  void strike(Ball<S>& ball, const CueStrike<S>& s, const PhysicsParams<S>& p) const override
  {
    cueImpulse(ball, s, p);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cue, sequential, SequentialCue)

}  // namespace physics
}  // namespace cue_sim
