// The tables that ship with the package, by name, without ROS.
#pragma once

#include <string>
#include <vector>

namespace cue_sim
{
/// "7ft", "9ft", "carom", "snooker".
std::vector<std::string> tableNames();

/// The URDF file of a shipped table, or of `name_or_path` itself if it names a file. Looks in
/// $CUE_SIM_URDF_DIR, then the source and install trees. Throws TableDescriptionError.
std::string tableUrdfPath(const std::string& name_or_path);

}  // namespace cue_sim
