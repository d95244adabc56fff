// The planning examples of doc/research.md, as a user runs them: the code there is the code in
// src/examples/plan_shots.cpp and scripts/plan_shots.py, and both run against a real table,
// strike the shot they chose, and the table then pockets what the prediction said.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "shell_commands.hpp"
#include "table_client.hpp"

namespace
{
std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// The first fenced code block after the line that names `file`.
std::string readmeBlock(const std::string& readme, const std::string& file)
{
  const std::size_t named = readme.find(file + "`");
  if (named == std::string::npos)
    return "";
  const std::size_t open = readme.find("```", named);
  const std::size_t start = readme.find('\n', open) + 1;
  const std::size_t close = readme.find("\n```", start);
  return readme.substr(start, close + 1 - start);
}

/// Runs an example, checks what it says, and that the table did what its prediction said.
void runExample(TableClient& table, const std::string& command)
{
  const auto [code, output] = runCommand(command);
  ASSERT_EQ(code, 0) << output;
  std::smatch found;
  ASSERT_TRUE(std::regex_search(output, found, std::regex("best of 216 shots: .* pockets (-?[0-9]+)"))) << output;
  EXPECT_NE(output.find("struck ball 0"), std::string::npos) << output;
  const int pocketed = std::stoi(found[1]);
  EXPECT_GE(pocketed, 1) << "some break-off shot pockets a ball: " << output;
  const cue_sim::TableState rest = *table.atRest(120);
  int dropped = 0;
  for (const auto& b : rest.balls)
    dropped += b.pocketed;
  EXPECT_EQ(dropped, pocketed) << "the table pockets what the prediction said";
}

TEST(Examples, TheReadmeShowsTheExamplesAsTheyAre)
{
  const std::string root = CUE_SIM_SOURCE_DIR;
  const std::string readme = readFile(root + "/doc/research.md");
  for (const std::string file : {"src/examples/plan_shots.cpp", "scripts/plan_shots.py"})
  {
    const std::string block = readmeBlock(readme, file);
    ASSERT_FALSE(block.empty()) << "doc/research.md has no code block after `" << file << "`";
    EXPECT_EQ(block, readFile(root + "/" + file)) << file;
  }
}

TEST(Examples, TheCppAndPythonPlannersStrikeTheirBestShot)
{
  TableClient table;
  ASSERT_TRUE(table.rack("eight").success);
  runExample(table, "rosrun cue_sim plan_shots");
  ASSERT_TRUE(table.rack("eight").success);
  runExample(table, "rosrun cue_sim plan_shots.py");
}
}  // namespace
