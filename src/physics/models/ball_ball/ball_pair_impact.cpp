#include "physics/models/ball_ball/ball_pair_impact.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// Where a unit impulse k acts: on a (at a_at, from a's centre) and on b (at b_at).
template <typename S>
struct UnitImpulse
{
  Vec3<S> on_a = Vec3<S>::Zero(), a_at = Vec3<S>::Zero(), on_b = Vec3<S>::Zero(), b_at = Vec3<S>::Zero();
};
}  // namespace

template <typename S>
typename BallPairImpact<S>::Setup ballPairImpact(const Ball<S>& a, const Ball<S>& b, const Vec3<S>& normal,
                                                 const PhysicsParams<S>& p, S mu_ball, S mu_cloth)
{
  const S m = p.ball_mass, R = p.ball_radius, inertia = S(0.4) * m * R * R;
  const Vec3<S> up = Vec3<S>::UnitZ(), side = up.cross(normal);
  const Vec3<S> a_contact = R * normal, b_contact = -R * normal, foot = -R * up;
  Eigen::Matrix<S, 3, 2> contact_plane, cloth_plane;  // orthonormal tangent bases
  contact_plane << side, up;
  cloth_plane << normal, side;

  typename BallPairImpact<S>::Setup setup;
  setup.velocity0 << a.v, b.v;
  setup.velocity0(2) = setup.velocity0(5) = S(0);
  setup.spin0 << a.w, b.w;
  setup.radius = R;
  setup.mu = {mu_ball, mu_cloth, mu_cloth};
  setup.load.setZero();
  setup.load(0, 0) = S(1);
  setup.load(1, 2) = S(-1);  // a is pressed by the contact's downward friction on it
  setup.load(2, 2) = S(1);   // b by the opposite
  for (int k = 0; k < BallPairImpact<S>::kImpulses; ++k)
  {
    UnitImpulse<S> unit;
    unit.a_at = a_contact;
    unit.b_at = b_contact;
    if (k == 0)
    {
      unit.on_a = -normal;
      unit.on_b = normal;
    }
    else if (k < 3)
    {
      unit.on_a = contact_plane.col(k - 1);
      unit.on_b = -unit.on_a;
    }
    else if (k < 5)
    {
      unit.on_a = cloth_plane.col(k - 3);
      unit.a_at = foot;
    }
    else
    {
      unit.on_b = cloth_plane.col(k - 5);
      unit.b_at = foot;
    }
    Vec3<S> dva = unit.on_a / m, dvb = unit.on_b / m;
    dva.z() = dvb.z() = S(0);  // the cloth takes the vertical part
    const Vec3<S> dwa = unit.a_at.cross(unit.on_a) / inertia, dwb = unit.b_at.cross(unit.on_b) / inertia;
    setup.velocity_per_impulse.col(k) << dva, dvb;
    setup.spin_per_impulse.col(k) << dwa, dwb;
    setup.slip_per_impulse.col(k) << contact_plane.transpose() *
                                         (dva + dwa.cross(a_contact) - dvb - dwb.cross(b_contact)),
        cloth_plane.transpose() * (dva + dwa.cross(foot)), cloth_plane.transpose() * (dvb + dwb.cross(foot));
    setup.approach_per_impulse(k) = (dva - dvb).dot(normal);
  }
  const Vec3<S> va = setup.velocity0.template head<3>(), vb = setup.velocity0.template tail<3>();
  setup.slip0 << contact_plane.transpose() * (va + a.w.cross(a_contact) - vb - b.w.cross(b_contact)),
      cloth_plane.transpose() * (va + a.w.cross(foot)), cloth_plane.transpose() * (vb + b.w.cross(foot));
  setup.approach0 = (va - vb).dot(normal);
  return setup;
}

template BallPairImpact<double>::Setup ballPairImpact(const Ball<double>&, const Ball<double>&, const Vec3<double>&,
                                                      const PhysicsParams<double>&, double, double);
template BallPairImpact<long double>::Setup ballPairImpact(const Ball<long double>&, const Ball<long double>&,
                                                           const Vec3<long double>&, const PhysicsParams<long double>&,
                                                           long double, long double);

}  // namespace physics
}  // namespace cue_sim
