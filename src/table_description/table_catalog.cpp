#include "cue_sim/table_description/table_catalog.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
std::vector<std::string> tableNames()
{
  return {"7ft", "9ft", "carom", "snooker"};
}

namespace
{
bool readable(const std::string& path)
{
  return std::ifstream(path).good();
}
}  // namespace

std::string tableUrdfPath(const std::string& name_or_path)
{
  if (name_or_path.find('/') != std::string::npos ||
      (name_or_path.size() > 5 && name_or_path.substr(name_or_path.size() - 5) == ".urdf"))
  {
    if (!readable(name_or_path))
      throw TableDescriptionError("cannot read URDF file '" + name_or_path + "'");
    return name_or_path;
  }
  std::string dirs;
  if (const char* env = std::getenv("CUE_SIM_URDF_DIR"))
    dirs = std::string(env) + ":";
  dirs += CUE_SIM_URDF_DIRS;
  std::istringstream list(dirs);
  std::string dir;
  while (std::getline(list, dir, ':'))
  {
    const std::string candidate = dir + "/table_" + name_or_path + ".urdf";
    if (!dir.empty() && readable(candidate))
      return candidate;
  }
  std::string known;
  for (const auto& n : tableNames())
    known += (known.empty() ? "" : ", ") + n;
  throw TableDescriptionError("unknown table '" + name_or_path + "' (known: " + known +
                              "; or give a path to a .urdf file)");
}

}  // namespace cue_sim
