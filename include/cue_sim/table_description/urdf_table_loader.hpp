// Builds a TableModel from a URDF description (urdfdom; no ROS). The link naming convention
// is in README.md, "Describing a table in URDF".
#pragma once

#include <stdexcept>
#include <string>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
/// Thrown for a URDF that does not parse or does not describe a table; what() says what is
/// missing or wrong, naming the link.
class TableDescriptionError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The table described by a URDF document. `root_frame` is the link that is the table frame.
physics::TableModel tableFromUrdf(const std::string& urdf_xml, const std::string& root_frame = "table");

/// The same, read from a file.
physics::TableModel tableFromUrdfFile(const std::string& path, const std::string& root_frame = "table");

}  // namespace cue_sim

#include <Eigen/Geometry>
#include <vector>

namespace cue_sim
{
/// A fixed joint of the table description, for publishing the links as static tf frames.
struct FixedLinkTransform
{
  std::string parent, child;
  Eigen::Vector3d translation;
  Eigen::Quaterniond rotation;
};

/// Every joint of a URDF document (all must be fixed). Throws TableDescriptionError.
std::vector<FixedLinkTransform> fixedLinkTransforms(const std::string& urdf_xml);

}  // namespace cue_sim
