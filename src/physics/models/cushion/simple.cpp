// The normal velocity is reversed and scaled by e_cushion; tangential velocity and spin are kept
// (Lander 1999's restitution model applied to a fixed wall).
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class SimpleCushion : public CushionModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>&) const override { return S(0); }
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override
  {
    const S v_n = ball.v.dot(normal);
    if (v_n < S(0))
      ball.v -= (S(1) + p.e_cushion) * v_n * normal;
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cushion, simple, SimpleCushion)

}  // namespace physics
}  // namespace cue_sim
