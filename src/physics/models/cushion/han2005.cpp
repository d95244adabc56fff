// Han 2005, "Dynamics in carom and three cushion billiards", J. Mech. Sci. Technol. 19(4): one
// impulse where the cushion's nose, cushion_height above the cloth, touches the ball. Normal
// impulse from e_cushion along the contact normal; friction f_cushion times it against the
// contact point's slip, capped by the no-slip impulse. Spin changes the rebound.
#include "physics/models/cushion/nose_contact.hpp"
#include "physics/models/friction_impulse.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class HanCushion : public CushionModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>& p) const override { return p.f_cushion; }
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override
  {
    const NoseContact<S> nose(normal, p);
    const S approach = nose.approach(ball);
    if (!(approach > S(0)))
      return;
    const S m = p.ball_mass, normal_impulse = (S(1) + p.e_cushion) * m * approach;
    // Tangential inverse mass at the contact: 1/m + R^2/I = 7/(2m).
    const Vec3<S> impulse =
        normal_impulse * nose.normal + frictionImpulse(nose.slip(ball), p.f_cushion * normal_impulse, S(3.5) / m);
    nose.push(ball, impulse, p);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cushion, han2005, HanCushion)

}  // namespace physics
}  // namespace cue_sim
