// A ball landing on the slate without friction (pooltool's FrictionlessInelasticTable): the normal
// speed comes back times the restitution; the horizontal velocity and the spin are kept.
#include "physics/models/ball_table/slate_bounce.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class FrictionlessTable : public BallTableModel<S>
{
public:
  void resolve(Ball<S>& ball, S restitution, const PhysicsParams<S>& p) const override
  {
    ball = slateImpact(ball, SlateContact<S>{restitution, S(0)}, p.ball_radius);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(ball_table, frictionless, FrictionlessTable)

}  // namespace physics
}  // namespace cue_sim
