// A ball landing on the slate (pooltool's FrictionalInelasticTable): the normal speed comes back
// times the restitution, and Coulomb friction mu_table at the contact point acts against its slip,
// capped by the impulse that stops it (the impact law is slate_bounce.hpp's).
#include "physics/models/ball_table/slate_bounce.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class FrictionalTable : public BallTableModel<S>
{
public:
  void resolve(Ball<S>& ball, S restitution, const PhysicsParams<S>& p) const override
  {
    ball = slateImpact(ball, SlateContact<S>{restitution, p.mu_table}, p.ball_radius);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(ball_table, frictional, FrictionalTable)

}  // namespace physics
}  // namespace cue_sim
