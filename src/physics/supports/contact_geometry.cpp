#include "physics/supports/contact_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace physics
{
const char* surfaceName(Surface surface)
{
  switch (surface)
  {
    case Surface::Ball:
      return "ball";
    case Surface::Slate:
      return "slate";
    case Surface::Face:
      return "face";
    case Surface::Edge:
      return "edge";
    case Surface::PostSide:
      return "post side";
    case Surface::Rim:
      return "rim";
  }
  return "unknown";
}

namespace
{
/// The gap to a point at distance `d` (the vector from the nearest point of a curve or a point to
/// the centre) with the curvature part of H given: n = d / |d|, gap = |d| - reach.
template <typename S>
void fromOffset(const Vec3<S>& d, S reach, ContactGeometry<S>& c)
{
  const S distance = d.norm();
  c.gap = distance - reach;
  c.n = distance > S(0) ? Vec3<S>(d / distance) : Vec3<S>::UnitZ();
}
}  // namespace

template <typename S>
ContactGeometry<S> ballContact(const Vec3<S>& r, const Vec3<S>& other, S R)
{
  // The distance between centres: its Hessian is (I - n n^T) / |d| (a sphere of radius 2R).
  ContactGeometry<S> c;
  c.surface = Surface::Ball;
  const Vec3<S> d = r - other;
  fromOffset(d, S(2) * R, c);
  const S distance = d.norm();
  if (distance > S(0))
    c.H = (Mat3<S>::Identity() - c.n * c.n.transpose()) / distance;
  return c;
}

template <typename S>
ContactGeometry<S> slateContact(const Vec3<S>& r, S R)
{
  ContactGeometry<S> c;
  c.surface = Surface::Slate;
  c.gap = r.z() - R;
  return c;
}

template <typename S>
ContactGeometry<S> cushionContact(const TableGeometry<S>& g, int k, const Vec3<S>& r, S R)
{
  const auto& seg = g.segments[static_cast<std::size_t>(k)];
  ContactGeometry<S> c;
  const Vec2<S> p = r.template head<2>() - seg.start;
  c.along = seg.direction.dot(p);
  c.across = seg.normal.dot(p);
  const Vec3<S> normal(seg.normal.x(), seg.normal.y(), S(0));
  const S above = r.z() - g.nose_height;
  if (!(above > S(0)))
  {
    // The face: a plane, no curvature.
    c.surface = Surface::Face;
    c.gap = c.across - R;
    c.n = normal;
    return c;
  }
  // The nose's edge: a line along the segment at the nose's height. The distance to a line has the
  // Hessian (I - e e^T - n n^T) / |d|, e along the line.
  c.surface = Surface::Edge;
  fromOffset(Vec3<S>(std::max(c.across, S(0)) * normal + above * Vec3<S>::UnitZ()), R, c);
  const Vec3<S> e(seg.direction.x(), seg.direction.y(), S(0));
  const S distance = c.gap + R;
  if (distance > S(0))
    c.H = (Mat3<S>::Identity() - e * e.transpose() - c.n * c.n.transpose()) / distance;
  return c;
}

template <typename S>
ContactGeometry<S> postContact(const TableGeometry<S>& g, int k, const Vec3<S>& r, S R)
{
  const auto& post = g.circles[static_cast<std::size_t>(k)];
  ContactGeometry<S> c;
  const Vec2<S> s2 = r.template head<2>() - post.centre;
  const S sigma = s2.norm();
  const Vec3<S> s_hat = sigma > S(0) ? Vec3<S>(s2.x() / sigma, s2.y() / sigma, S(0)) : Vec3<S>::UnitX();
  const Vec3<S> t_hat = Vec3<S>::UnitZ().cross(s_hat);
  const S above = r.z() - g.nose_height;
  if (!(above > S(0)))
  {
    // The side: a vertical cylinder; the distance to its axis has the Hessian t t^T / sigma.
    c.surface = Surface::PostSide;
    c.gap = sigma - post.radius - R;
    c.n = s_hat;
    if (sigma > S(0))
      c.H = t_hat * t_hat.transpose() / sigma;
    return c;
  }
  // The rim: a horizontal circle of radius rho. With D^2 = (sigma - rho)^2 + above^2, the Hessian of
  // D is (s s^T + z z^T - n n^T + ((sigma - rho) / sigma) t t^T) / D (chain rule through sigma, whose
  // own Hessian is t t^T / sigma).
  c.surface = Surface::Rim;
  const S out = std::max(sigma - post.radius, S(0));
  fromOffset(Vec3<S>(out * s_hat + above * Vec3<S>::UnitZ()), R, c);
  const S distance = c.gap + R;
  if (distance > S(0) && sigma > S(0))
    c.H = (s_hat * s_hat.transpose() + Vec3<S>::UnitZ() * Vec3<S>::UnitZ().transpose() - c.n * c.n.transpose() +
           (out / sigma) * t_hat * t_hat.transpose()) /
          distance;
  return c;
}

template <typename S>
void wallsTouching(const TableGeometry<S>& g, const Vec3<S>& r, S R, S touch, std::vector<WallTouch>& out)
{
  out.clear();
  const Vec2<S> p = r.template head<2>();
  if ((p.array() > g.clear_low.array()).all() && (p.array() < g.clear_high.array()).all())
    return;  // out of every wall's reach
  const auto inBox = [&](const auto& wall) {
    return !((p.array() < wall.low.array()).any() || (p.array() > wall.high.array()).any());
  };
  for (std::size_t k = 0; k < g.segments.size(); ++k)
    if (inBox(g.segments[k]))
    {
      const ContactGeometry<S> c = cushionContact(g, static_cast<int>(k), r, R);
      if (c.gap <= touch && onCushion(c, g.segments[k].length))
        out.push_back({c.surface, static_cast<int>(k)});
    }
  for (std::size_t k = 0; k < g.circles.size(); ++k)
    if (inBox(g.circles[k]))
    {
      const ContactGeometry<S> c = postContact(g, static_cast<int>(k), r, R);
      if (c.gap <= touch)
        out.push_back({c.surface, static_cast<int>(k)});
    }
}

template <typename S>
bool overTheTop(const TableGeometry<S>& g, const Vec3<S>& r)
{
  if (!(r.z() > g.nose_height))
    return false;
  const Vec2<S> p = r.template head<2>();
  for (const auto& seg : g.segments)
  {
    const S along = seg.direction.dot(p - seg.start), across = seg.normal.dot(p - seg.start);
    if (along >= S(0) && along <= seg.length && across < S(0))
      return true;
  }
  for (const auto& post : g.circles)
    if ((p - post.centre).norm() < post.radius)
      return true;
  return false;
}

#define CUE_SIM_INSTANTIATE_CONTACT_GEOMETRY(S)                                                                        \
  template ContactGeometry<S> ballContact(const Vec3<S>&, const Vec3<S>&, S);                                          \
  template ContactGeometry<S> slateContact(const Vec3<S>&, S);                                                         \
  template ContactGeometry<S> cushionContact(const TableGeometry<S>&, int, const Vec3<S>&, S);                         \
  template ContactGeometry<S> postContact(const TableGeometry<S>&, int, const Vec3<S>&, S);                            \
  template void wallsTouching(const TableGeometry<S>&, const Vec3<S>&, S, S, std::vector<WallTouch>&);                 \
  template bool overTheTop(const TableGeometry<S>&, const Vec3<S>&);
CUE_SIM_INSTANTIATE_CONTACT_GEOMETRY(double)
CUE_SIM_INSTANTIATE_CONTACT_GEOMETRY(long double)

}  // namespace physics
}  // namespace cue_sim
