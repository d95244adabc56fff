#include "cue_sim/table_description/urdf_table_loader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace
{
using physics::CircularCushion;
using physics::CushionSegment;
using physics::Pocket;
using physics::TableModel;

Eigen::Isometry3d toIsometry(const urdf::Pose& pose)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

bool startsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

class UrdfTableReader
{
public:
  UrdfTableReader(const urdf::ModelInterface& model, const std::string& root) : model_(model), root_(root) {}

  TableModel read()
  {
    if (!model_.getRoot() || model_.getRoot()->name != root_)
      fail("the root link must be '" + root_ + "' (the table frame), found '" +
           (model_.getRoot() ? model_.getRoot()->name : std::string("none")) + "'");
    const auto cloth = model_.getLink("cloth");
    if (!cloth)
      fail("no link named 'cloth' (a collision box whose footprint is the playing surface)");
    const auto [cloth_pose, cloth_box] = boxOf(*cloth);
    const Eigen::Vector3d top = cloth_pose * Eigen::Vector3d(0, 0, cloth_box.z() / 2);
    if (std::abs(top.z()) > 1e-6)
      fail("the top of link 'cloth' must be at z = 0 in the table frame, it is at z = " + std::to_string(top.z()));
    if (!isLevel(cloth_pose) || std::abs(std::remainder(yawOf(cloth_pose), M_PI / 2)) > 1e-9)
      fail("link 'cloth' must be level and aligned with the table axes");
    const bool swapped = std::abs(std::sin(yawOf(cloth_pose))) > 0.5;
    const double length = swapped ? cloth_box.y() : cloth_box.x();
    const double width = swapped ? cloth_box.x() : cloth_box.y();

    std::vector<CushionSegment> segments;
    std::vector<CircularCushion> circles;
    std::vector<Pocket> pockets;
    physics::TableEdge edge;
    bool has_rails = false;
    for (const auto& [name, link] : model_.links_)
    {
      if (startsWith(name, "rails_") && link->collision)
      {
        addRail(*link, edge, has_rails);
        continue;
      }
      if (startsWith(name, "cushion_"))
      {
        const auto [pose, size] = boxOf(*link);
        if (!isLevel(pose))
          fail("link '" + name + "' must be level (rotated about z only)");
        const Eigen::Vector3d start = pose * Eigen::Vector3d(-size.x() / 2, size.y() / 2, 0);
        const Eigen::Vector3d end = pose * Eigen::Vector3d(size.x() / 2, size.y() / 2, 0);
        segments.push_back(TableModel::makeSegment(name, start.head<2>(), end.head<2>()));
      }
      else if (startsWith(name, "pocket_"))
      {
        const auto [centre, radius] = cylinderOf(*link);
        pockets.push_back({name, centre, radius});
      }
      else if (startsWith(name, "jaw_"))
      {
        const auto [centre, radius] = cylinderOf(*link);
        circles.push_back({name, centre, radius});
      }
    }
    if (segments.empty())
      fail("no cushion links: name each straight cushion 'cushion_<name>' with a collision box");
    const Eigen::Vector3d centre = cloth_pose.translation();
    const Eigen::Vector2d half(length / 2, width / 2);
    if (has_rails && ((edge.low - (centre.head<2>() - half)).maxCoeff() > 0 ||
                      ((centre.head<2>() + half) - edge.high).maxCoeff() > 0))
      fail("the rails' outer edges must enclose link 'cloth'");
    TableModel table(model_.getName(), centre.head<2>(), length, width, std::move(segments), std::move(circles),
                     std::move(pockets), has_rails ? std::optional<physics::TableEdge>(edge) : std::nullopt,
                     ballsOf(model_.getLink("balls")));
    const std::string open = table.whyOpen();
    if (!open.empty())
      fail(open);
    if (table.balls())
      if (const std::string why = physics::tableDefaults(table).validate(); !why.empty())
        fail("link 'balls' does not fit the engine's defaults: " + why);
    return table;
  }

private:
  /// A rail widens the table's edge to its footprint and sets the rails' top (the highest).
  void addRail(const urdf::Link& link, physics::TableEdge& edge, bool& has_rails) const
  {
    const auto [pose, size] = boxOf(link);
    if (!isLevel(pose))
      fail("link '" + link.name + "' must be level (rotated about z only)");
    Eigen::Vector2d low = Eigen::Vector2d::Constant(HUGE_VAL), high = -low;
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5})
      {
        const Eigen::Vector2d corner = (pose * Eigen::Vector3d(sx * size.x(), sy * size.y(), 0)).head<2>();
        low = low.cwiseMin(corner);
        high = high.cwiseMax(corner);
      }
    const double top = (pose * Eigen::Vector3d(0, 0, size.z() / 2)).z();
    if (!(top > 0))
      fail("link '" + link.name + "': the rail's top must be above the cloth, it is at z = " + std::to_string(top));
    edge.low = has_rails ? edge.low.cwiseMin(low) : low;
    edge.high = has_rails ? edge.high.cwiseMax(high) : high;
    edge.rail_height = has_rails ? std::max(edge.rail_height, top) : top;
    has_rails = true;
  }

  /// The balls the table is played with: link 'balls', a collision sphere (their radius) and an
  /// inertial mass; none when the description has no such link.
  std::optional<physics::TableBalls> ballsOf(const urdf::LinkConstSharedPtr& link) const
  {
    if (!link)
      return std::nullopt;
    if (!link->collision || !link->collision->geometry || link->collision->geometry->type != urdf::Geometry::SPHERE)
      fail("link 'balls' needs a <collision> with <sphere> geometry: the radius of the table's balls");
    if (!link->inertial)
      fail("link 'balls' needs an <inertial> with a <mass>: the mass of one of the table's balls");
    physics::TableBalls balls{static_cast<const urdf::Sphere&>(*link->collision->geometry).radius, link->inertial->mass,
                              link->collision->name};
    if (!balls.set.empty() && !physics::isBallSetName(balls.set))
      fail("link 'balls': the collision's name is the set of balls, " + physics::ballSetNameList() + "; got '" +
           balls.set + "'");
    if (!(balls.radius > 0 && balls.mass > 0))
      fail("link 'balls': the sphere's radius and the mass must be positive, got " + std::to_string(balls.radius) +
           " m and " + std::to_string(balls.mass) + " kg");
    return balls;
  }

  [[noreturn]] void fail(const std::string& why) const
  {
    throw TableDescriptionError("URDF '" + model_.getName() + "': " + why);
  }

  /// The link's pose in the root frame, through its chain of fixed joints.
  Eigen::Isometry3d linkPose(const urdf::Link& link) const
  {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    const urdf::Link* current = &link;
    while (current->parent_joint)
    {
      const auto& joint = *current->parent_joint;
      if (joint.type != urdf::Joint::FIXED)
        fail("joint '" + joint.name + "' must be fixed: a table does not move");
      pose = toIsometry(joint.parent_to_joint_origin_transform) * pose;
      current = current->getParent().get();
    }
    return pose;
  }

  std::pair<Eigen::Isometry3d, Eigen::Vector3d> boxOf(const urdf::Link& link) const
  {
    if (!link.collision || !link.collision->geometry || link.collision->geometry->type != urdf::Geometry::BOX)
      fail("link '" + link.name + "' needs a <collision> with <box> geometry");
    const auto& box = static_cast<const urdf::Box&>(*link.collision->geometry);
    if (!(box.dim.x > 0 && box.dim.y > 0 && box.dim.z > 0))
      fail("link '" + link.name + "': box sizes must be positive");
    return {linkPose(link) * toIsometry(link.collision->origin), Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z)};
  }

  std::pair<Eigen::Vector2d, double> cylinderOf(const urdf::Link& link) const
  {
    if (!link.collision || !link.collision->geometry || link.collision->geometry->type != urdf::Geometry::CYLINDER)
      fail("link '" + link.name + "' needs a <collision> with <cylinder> geometry");
    const auto& cylinder = static_cast<const urdf::Cylinder&>(*link.collision->geometry);
    if (!(cylinder.radius >= 0))
      fail("link '" + link.name + "': cylinder radius must not be negative");
    const Eigen::Isometry3d pose = linkPose(link) * toIsometry(link.collision->origin);
    if (!isLevel(pose))
      fail("link '" + link.name + "': the cylinder's axis must be vertical");
    return {pose.translation().head<2>(), cylinder.radius};
  }

  static bool isLevel(const Eigen::Isometry3d& pose)
  {
    return (pose.linear().col(2) - Eigen::Vector3d::UnitZ()).norm() < 1e-9;
  }
  static double yawOf(const Eigen::Isometry3d& pose) { return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0)); }

  const urdf::ModelInterface& model_;
  std::string root_;
};
/// urdfdom says what is wrong with a description through console_bridge: its messages are
/// collected for the time of one parse, to say why the description is refused.
class ParserMessages : public console_bridge::OutputHandler
{
public:
  ParserMessages() : previous_(console_bridge::getOutputHandler()) { console_bridge::useOutputHandler(this); }
  ~ParserMessages() override { console_bridge::useOutputHandler(previous_); }
  ParserMessages(const ParserMessages&) = delete;
  ParserMessages& operator=(const ParserMessages&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override
  {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN)
      text_ += (text_.empty() ? "" : "; ") + text;
  }
  const std::string& text() const { return text_; }

private:
  console_bridge::OutputHandler* previous_;
  std::string text_;
};

urdf::ModelInterfaceSharedPtr parse(const std::string& urdf_xml)
{
  ParserMessages messages;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model)
    throw TableDescriptionError(
        "the table description is not valid URDF: " +
        (messages.text().empty() ? std::string("urdfdom could not parse it") : messages.text()));
  return model;
}
}  // namespace

physics::TableModel tableFromUrdf(const std::string& urdf_xml, const std::string& root_frame)
{
  return UrdfTableReader(*parse(urdf_xml), root_frame).read();
}

physics::TableModel tableFromUrdfFile(const std::string& path, const std::string& root_frame)
{
  std::ifstream file(path);
  if (!file)
    throw TableDescriptionError("cannot read URDF file '" + path + "'");
  std::stringstream text;
  text << file.rdbuf();
  return tableFromUrdf(text.str(), root_frame);
}

std::vector<FixedLinkTransform> fixedLinkTransforms(const std::string& urdf_xml)
{
  const urdf::ModelInterfaceSharedPtr model = parse(urdf_xml);
  std::vector<FixedLinkTransform> out;
  for (const auto& [name, joint] : model->joints_)
  {
    if (joint->type != urdf::Joint::FIXED)
      throw TableDescriptionError("URDF '" + model->getName() + "': joint '" + name + "' must be fixed");
    const auto& pose = joint->parent_to_joint_origin_transform;
    out.push_back({joint->parent_link_name, joint->child_link_name,
                   Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z),
                   Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)});
  }
  return out;
}

}  // namespace cue_sim
