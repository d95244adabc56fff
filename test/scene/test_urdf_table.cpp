// Tables from URDF: the shipped files describe the geometry PHYSICS.md gives, and a broken
// description is refused with a message that names what is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <tuple>

#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/scene/ball_colours.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

using cue_sim::TableDescriptionError;
using cue_sim::tableFromUrdf;
using cue_sim::tableFromUrdfFile;
using cue_sim::tableUrdfPath;
using cue_sim::physics::PhysicsParams;
using cue_sim::physics::TableModel;

namespace
{
void expectSameGeometry(const TableModel& a, const TableModel& b)
{
  EXPECT_NEAR(a.clothLength(), b.clothLength(), 1e-9);
  EXPECT_NEAR(a.clothWidth(), b.clothWidth(), 1e-9);
  std::map<std::string, const cue_sim::physics::CushionSegment*> segments;
  for (const auto& s : b.segments())
    segments[s.name] = &s;
  ASSERT_EQ(a.segments().size(), b.segments().size());
  for (const auto& s : a.segments())
  {
    ASSERT_TRUE(segments.count(s.name)) << s.name;
    EXPECT_NEAR((s.start - segments[s.name]->start).norm(), 0, 1e-9) << s.name;
    EXPECT_NEAR((s.end - segments[s.name]->end).norm(), 0, 1e-9) << s.name;
    EXPECT_NEAR((s.normal - segments[s.name]->normal).norm(), 0, 1e-9) << s.name;
  }
  ASSERT_EQ(a.pockets().size(), b.pockets().size());
  std::map<std::string, const cue_sim::physics::Pocket*> pockets;
  for (const auto& p : b.pockets())
    pockets[p.name] = &p;
  for (const auto& p : a.pockets())
  {
    ASSERT_TRUE(pockets.count(p.name)) << p.name;
    EXPECT_NEAR((p.centre - pockets[p.name]->centre).norm(), 0, 1e-9);
    EXPECT_NEAR(p.radius, pockets[p.name]->radius, 1e-9);
  }
  EXPECT_EQ(a.circles().size(), b.circles().size());
}

std::string minimalTable(const std::string& extra_links, bool with_cloth = true)
{
  std::string urdf = R"(<robot name="test"><link name="table"/>)";
  if (with_cloth)
    urdf +=
        R"(<link name="cloth"><collision><origin xyz="0 0 -0.01"/><geometry><box size="2 1 0.02"/></geometry></collision></link>
               <joint name="j_cloth" type="fixed"><parent link="table"/><child link="cloth"/></joint>)";
  return urdf + extra_links + "</robot>";
}

std::string errorOf(const std::string& urdf)
{
  try
  {
    tableFromUrdf(urdf);
  }
  catch (const TableDescriptionError& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(UrdfTable, SevenFootFileMatchesTheBuiltInGeometry)
{
  expectSameGeometry(tableFromUrdfFile(tableUrdfPath("7ft")), TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
}

TEST(UrdfTable, NineFootAndCaromFilesMatch)
{
  expectSameGeometry(tableFromUrdfFile(tableUrdfPath("9ft")), TableModel::pool("9ft", 2.54, 1.27, 0.118, 0.137));
  expectSameGeometry(tableFromUrdfFile(tableUrdfPath("carom")), TableModel::carom("carom", 2.84, 1.42));
}

TEST(UrdfTable, UnknownTableNamesTheKnownOnes)
{
  try
  {
    tableUrdfPath("bagatelle");
    FAIL();
  }
  catch (const TableDescriptionError& e)
  {
    EXPECT_NE(std::string(e.what()).find("7ft, 9ft, carom, snooker"), std::string::npos);
  }
}

TEST(UrdfTable, BrokenDescriptionsSayWhatIsMissing)
{
  EXPECT_NE(errorOf("<robot name='x'><link name='table'/"), "");  // not XML
  EXPECT_NE(errorOf(minimalTable("", false)).find("no link named 'cloth'"), std::string::npos);
  EXPECT_NE(errorOf(minimalTable("")).find("no cushion links"), std::string::npos);
  const std::string cushion_without_box =
      R"(<link name="cushion_a"><collision><geometry><cylinder radius="1" length="1"/></geometry></collision></link>
         <joint name="j" type="fixed"><parent link="table"/><child link="cushion_a"/></joint>)";
  EXPECT_NE(errorOf(minimalTable(cushion_without_box)).find("'cushion_a' needs a <collision> with <box>"),
            std::string::npos);
  const std::string moving_joint =
      R"(<link name="cushion_a"><collision><geometry><box size="1 0.05 0.04"/></geometry></collision></link>
         <joint name="j" type="revolute"><parent link="table"/><child link="cushion_a"/><axis xyz="0 0 1"/>
         <limit lower="0" upper="1" effort="1" velocity="1"/></joint>)";
  EXPECT_NE(errorOf(minimalTable(moving_joint)).find("must be fixed"), std::string::npos);
  const std::string wrong_root = R"(<robot name="t"><link name="base"/></robot>)";
  EXPECT_NE(errorOf(wrong_root).find("root link must be 'table'"), std::string::npos);
}

/// A straight cushion along the cloth's edge: its nose line through `xyz`, turned `yaw` about z
/// from one along +x with the playing area on its +y side; `length` [m].
std::string cushionLink(const std::string& name, const std::string& xyz, double yaw, double length)
{
  std::ostringstream link;
  link.precision(17);
  link << "<link name='cushion_" << name << "'><collision><origin xyz='0 -0.025 0.02'/><geometry><box size='" << length
       << " 0.05 0.04'/></geometry></collision></link><joint name='j_" << name
       << "' type='fixed'><parent link='table'/><child link='cushion_" << name << "'/><origin xyz='" << xyz
       << "' rpy='0 0 " << yaw << "'/></joint>";
  return link.str();
}

/// The 2 m x 1 m cloth of minimalTable closed by four cushions, but for those named in `leave_out`.
std::string closedTable(const std::string& leave_out = "", const std::string& extra = "")
{
  std::string links;
  if (leave_out.find("foot") == std::string::npos)
    links += cushionLink("foot", "1 0 0", M_PI / 2, 1.0);
  if (leave_out.find("head") == std::string::npos)
    links += cushionLink("head", "-1 0 0", -M_PI / 2, 1.0);
  if (leave_out.find("near") == std::string::npos)
    links += cushionLink("near", "0 -0.5 0", 0, 2.0);
  if (leave_out.find("far") == std::string::npos)
    links += cushionLink("far", "0 0.5 0", M_PI, 2.0);
  return minimalTable(links + extra);
}

TEST(UrdfTable, AMinimalClosedTableLoads)
{
  const TableModel t = tableFromUrdf(closedTable());
  ASSERT_EQ(t.segments().size(), 4u);
  for (const auto& s : t.segments())
    if (s.name == "cushion_near")
    {
      EXPECT_NEAR((s.start - Eigen::Vector2d(-1, -0.5)).norm(), 0, 1e-12);
      EXPECT_NEAR((s.normal - Eigen::Vector2d(0, 1)).norm(), 0, 1e-12);
    }
  EXPECT_EQ(t.whyOpen(), "");
  const std::string pocket =
      R"(<link name="pocket_p"><collision><geometry><cylinder radius="0.06" length="0.1"/></geometry></collision></link>
         <joint name="k" type="fixed"><parent link="table"/><child link="pocket_p"/><origin xyz="1.05 0.55 0"/></joint>)";
  const TableModel with_pocket = tableFromUrdf(closedTable("", pocket));
  ASSERT_EQ(with_pocket.pockets().size(), 1u);
  EXPECT_NEAR(with_pocket.pockets()[0].radius, 0.06, 1e-12);
}

TEST(UrdfTable, ATableThatLetsABallOutIsRefusedWithWhereItIsOpen)
{
  // A cushion missing: the head end is open from corner to corner.
  const std::string no_head = errorOf(closedTable("head"));
  EXPECT_NE(no_head.find("open at its edge from (-1, 0.499) to (-1, -0.499) m"), std::string::npos) << no_head;
  // One cushion alone.
  EXPECT_NE(errorOf(closedTable("head foot far")).find("open at its edge"), std::string::npos);
  // A cushion of almost no length.
  const std::string tiny = errorOf(closedTable("", cushionLink("tiny", "0 0 0", 0, 0.001)));
  EXPECT_NE(tiny.find("cushion 'cushion_tiny' is 0.001 m long, at least 0.01 m"), std::string::npos) << tiny;
  // A pool table without its pockets (links and joints): every mouth is open.
  std::ifstream file(tableUrdfPath("7ft"));
  std::stringstream text;
  text << file.rdbuf();
  const std::string urdf = text.str();
  const std::regex pocket_link(R"(<link name="pocket_[\s\S]*?</link>)");
  const std::regex pocket_joint(R"(<joint name="table_to_pocket_[\s\S]*?</joint>)");
  const std::string without = std::regex_replace(std::regex_replace(urdf, pocket_link, ""), pocket_joint, "");
  ASSERT_EQ(without.find("pocket_"), std::string::npos);
  const std::string no_pockets = errorOf(without);
  EXPECT_NE(no_pockets.find("open at its edge"), std::string::npos) << no_pockets;
  // Joints to links that are not there: urdfdom's own words say which.
  const std::string dangling = errorOf(std::regex_replace(urdf, pocket_link, ""));
  EXPECT_NE(dangling.find("pocket_"), std::string::npos) << dangling;
}

// The rails (issue 33): their top is where a ball that clears a cushion lands, and their outer
// edges are the table's edge. The bundled tables' rails are flush with the cushions' nose and
// reach as far as the tables built in code assume.
TEST(UrdfTable, TheRailsGiveTheTablesEdgeAndTheirTop)
{
  for (const auto& [name, built] :
       {std::pair<std::string, TableModel>{"7ft", TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137)},
        {"9ft", TableModel::pool("9ft", 2.54, 1.27, 0.118, 0.137)},
        {"carom", TableModel::carom("carom", 2.84, 1.42)}})
  {
    SCOPED_TRACE(name);
    const TableModel loaded = tableFromUrdfFile(tableUrdfPath(name));
    EXPECT_LT((loaded.edge().low - built.edge().low).norm(), 1e-9);
    EXPECT_LT((loaded.edge().high - built.edge().high).norm(), 1e-9);
    EXPECT_NEAR(loaded.edge().rail_height, PhysicsParams<double>().cushion_height, 1e-9);
    EXPECT_TRUE(std::isnan(built.edge().rail_height));  // in code: flush with the nose
  }
  const auto withRail = [&](const std::string& xyz, const std::string& size) {
    const std::string rail = R"(<link name="rails_a"><collision><origin xyz=")" + xyz + R"("/><geometry><box size=")" +
                             size + R"("/></geometry></collision></link>
        <joint name="j_rails_a" type="fixed"><parent link="table"/><child link="rails_a"/></joint>)";
    return closedTable("", rail);
  };
  EXPECT_EQ(errorOf(withRail("0 0 0.01", "3 2 0.02")), "");
  EXPECT_NE(errorOf(withRail("0 0 -0.02", "3 2 0.02")).find("rail's top must be above the cloth"), std::string::npos);
  EXPECT_NE(errorOf(withRail("0 0 0.01", "1 0.5 0.02")).find("must enclose link 'cloth'"), std::string::npos);
  const TableModel railed = tableFromUrdf(withRail("0 0 0.01", "3 2 0.02"));
  EXPECT_NEAR(railed.edge().high.x(), 1.5, 1e-12);
  EXPECT_NEAR(railed.edge().rail_height, 0.02, 1e-12);
}

// The balls a table is played with (issue 34): each bundled table names its own in a 'balls'
// link, the engine's coefficients start from them, and a description without one keeps the
// pool ball.
TEST(UrdfTable, EachBundledTableNamesItsBalls)
{
  const PhysicsParams<double> pool;
  for (const auto& [name, radius, mass] : {std::tuple<std::string, double, double>{"7ft", 0.028575, 0.170097},
                                           {"9ft", 0.028575, 0.170097},
                                           {"carom", 0.03075, 0.210},     // UMB: 61-61.5 mm, 205-220 g
                                           {"snooker", 0.02625, 0.142}})  // WPBSA: 52.5 mm
  {
    SCOPED_TRACE(name);
    const TableModel table = tableFromUrdfFile(tableUrdfPath(name));
    ASSERT_TRUE(table.balls().has_value());
    EXPECT_EQ(table.balls()->radius, radius);
    EXPECT_EQ(table.balls()->mass, mass);
    const PhysicsParams<double> p = cue_sim::physics::tableDefaults(table);
    EXPECT_EQ(p.ball_radius, radius);
    EXPECT_EQ(p.ball_mass, mass);
    EXPECT_EQ(p.mu_slide, pool.mu_slide);  // nothing else comes from the table
    EXPECT_EQ(p.cushion_height, pool.cushion_height);
    EXPECT_EQ(p.validate(), "");
    EXPECT_EQ(table.balls()->set, name == "carom" || name == "snooker" ? name : "pool");
    EXPECT_EQ(cue_sim::ballSetName(cue_sim::ballSetFor(table)), table.balls()->set);
  }
  EXPECT_EQ(pool.ball_radius, 0.028575);  // the pool ball, for a table that names none
  EXPECT_FALSE(TableModel::carom("carom", 2.84, 1.42).balls().has_value());
}

TEST(UrdfTable, ABallsLinkIsCheckedAndSaysWhatIsWrong)
{
  const auto balls = [](const std::string& geometry, const std::string& inertial) {
    return R"(<link name="balls">)" + inertial + "<collision><geometry>" + geometry + R"(</geometry></collision></link>
        <joint name="j_balls" type="fixed"><parent link="table"/><child link="balls"/></joint>)";
  };
  const std::string mass =
      R"(<inertial><mass value="0.2"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>)";
  const TableModel read = tableFromUrdf(closedTable("", balls(R"(<sphere radius="0.03"/>)", mass)));
  ASSERT_TRUE(read.balls().has_value());
  EXPECT_EQ(read.balls()->radius, 0.03);
  EXPECT_EQ(read.balls()->mass, 0.2);
  EXPECT_FALSE(tableFromUrdf(closedTable("", "")).balls().has_value());
  EXPECT_NE(
      errorOf(closedTable("", balls(R"(<box size="1 1 1"/>)", mass))).find("'balls' needs a <collision> with <sphere>"),
      std::string::npos);
  EXPECT_NE(errorOf(closedTable("", balls(R"(<sphere radius="0.03"/>)", ""))).find("'balls' needs an <inertial>"),
            std::string::npos);
  // The collision's name is the set of balls, for pictures.
  const std::string named = balls(R"(<sphere radius="0.03"/>)", mass);
  const auto withSet = [&](const std::string& set) {
    std::string link = named;
    link.replace(link.find("<collision>"), 11, "<collision name=\"" + set + "\">");
    return closedTable("", link);
  };
  EXPECT_EQ(tableFromUrdf(withSet("snooker")).balls()->set, "snooker");
  EXPECT_NE(errorOf(withSet("bagatelle")).find("pool, carom or snooker; got 'bagatelle'"), std::string::npos);
  // A ball too small for the engine's cushion nose (h must lie between R and 2R).
  const std::string why = errorOf(closedTable("", balls(R"(<sphere radius="0.01"/>)", mass)));
  EXPECT_NE(why.find("link 'balls'"), std::string::npos) << why;
  EXPECT_NE(why.find("cushion_height"), std::string::npos) << why;
}
