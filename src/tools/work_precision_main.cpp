// work_precision: error against run time for the event engine and the time-steppers.
//   rosrun cue_sim work_precision --out doc/work_precision        (full report, minutes)
//   rosrun cue_sim work_precision --quick --out build/wp_quick     (single shots, coarse steps)
// Writes results.csv, results.md and, with gnuplot installed, work_precision.png; and for the
// integrated impacts cushion_impact.{csv,md,png} and ball_impact.{csv,md,png}, and for sustained
// contact in the air contact_precision.{csv,md,png} (--impacts-only for these alone,
// --contacts-only for the last).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cue_sim/evaluation/ball_impact_precision.hpp"
#include "cue_sim/evaluation/contact_precision.hpp"
#include "cue_sim/evaluation/cushion_precision.hpp"
#include "cue_sim/evaluation/work_precision.hpp"

namespace
{
using cue_sim::evaluation::MethodResult;
using cue_sim::evaluation::ShotScene;
using cue_sim::physics::Integrator;

std::string notes(const MethodResult& r)
{
  if (r.method == "event")
    return "";
  std::ostringstream out;
  if (r.stepper.tunnelled)
    out << "tunnelled; ";
  if (r.stepper.max_overlap > 0)
    out << "overlap " << std::setprecision(2) << r.stepper.max_overlap << " m; ";
  if (r.stepper.energy_gain > 1e-12)
    out << "energy +" << std::setprecision(2) << r.stepper.energy_gain << " J; ";
  if (r.stepper.stalled)
    out << "step collapsed, gave up; ";
  else if (r.stepper.hit_step_limit)
    out << "stopped at the step limit; ";
  else if (!r.stepper.finished)
    out << "not at rest; ";
  return out.str();
}

/// Draws a plot script's PNG; says so if gnuplot is missing or fails.
void runGnuplot(const std::filesystem::path& script)
{
  const std::string command = "gnuplot '" + script.string() + "' 2>&1";
  if (std::system(command.c_str()) != 0)
    std::cerr << "work_precision: gnuplot failed or is missing; the plot script is " << script << "\n";
}

void writePlot(const std::filesystem::path& dir, const std::vector<std::string>& scenes)
{
  std::ofstream gp(dir / "work_precision.gp");
  gp << "set terminal pngcairo size 1500,900 font ',10'\n"
     << "set output '" << (dir / "work_precision.png").string() << "'\n"
     << "set datafile separator ','\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
     << "set xlabel 'run time per shot [s]'\nset ylabel 'largest position error [m]'\nset grid\n"
     << "set key top right noenhanced\nset yrange [1e-17:1e3]\nset offsets graph 0.04, graph 0.04, 0, 0\nset multiplot "
        "layout 2,3 title 'cue\\_sim: error "
        "against run time (reference: "
        "long-double event engine)'\n";
  for (const auto& scene : scenes)
  {
    gp << "set title '" << scene << "' noenhanced\n"
       << "plot for [m in 'event symplectic_euler rk4 dopri54'] '" << (dir / "results.csv").string()
       << "' using (strcol(1) eq '" << scene << "' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) "
       << "with linespoints pointsize 1.5 title m\n";
  }
  gp << "unset multiplot\n";
  gp.close();
  runGnuplot(dir / "work_precision.gp");
}
/// One integrated impact model's report: what it measures and on what.
struct ImpactReport
{
  std::string stem;      ///< file names: <stem>.csv, .md, .gp, .png
  std::string model;     ///< the integrated model
  std::string kind;      ///< "cushion" or "ball-ball"
  std::string arrivals;  ///< what the test set is, for the table's caption
  std::vector<cue_sim::evaluation::CushionPrecision> results;
  std::vector<cue_sim::evaluation::CushionModelCost> costs;
};

/// The tolerances an impact report runs.
std::vector<double> impactTolerances(bool quick)
{
  return quick ? std::vector<double>{1e-3, 1e-6} : std::vector<double>{1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6,
                                                                       1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 3e-9, 1e-9};
}

/// The reference each impact report measures against: the same impact in long double at this
/// tolerance.
constexpr double kImpactReferenceTolerance = 1e-10;

/// Writes an integrated impact's error against its tolerance and run time (table, csv, plot),
/// then every model of its kind: cost, rounding and difference from it.
void writeImpactReport(const std::filesystem::path& dir, const ImpactReport& report)
{
  std::ofstream md(dir / (report.stem + ".md"));
  std::ofstream csv(dir / (report.stem + ".csv"));
  csv << "tolerance,seconds_per_impact,max_velocity_error,max_spin_error\n";
  md << "### Integrated " << report.kind << " impact (" << report.model << "): error against its tolerance\n\n"
     << report.arrivals << ", default coefficients; the reference is each impact in long double with tolerance "
     << kImpactReferenceTolerance << ". Errors per unit of speed.\n\n"
     << "| tolerance | time per impact [s] | largest velocity error | largest R x spin error |\n|---|---|---|---|\n";
  for (const auto& r : report.results)
  {
    csv << r.tolerance << "," << r.seconds_per_impact << "," << r.max_velocity_error << "," << r.max_spin_error << "\n";
    md << std::setprecision(3) << "| " << r.tolerance << " | " << r.seconds_per_impact << " | " << r.max_velocity_error
       << " | " << r.max_spin_error << " |\n";
    std::cerr << "  tolerance " << r.tolerance << ": " << r.seconds_per_impact * 1e9 << " ns, velocity error "
              << r.max_velocity_error << "\n";
  }
  csv.close();
  md << "\n### Every " << report.kind << " model at the default coefficients\n\n"
     << "The same arrivals. Own error: against the same model in long double (rounding, and the tolerance for "
     << report.model << "). Difference: from " << report.model
     << "'s result in long double, which is what choosing a model changes.\n\n"
     << "| model | time per impact [s] | own velocity error | own R x spin error | velocity difference from "
     << report.model << " | R x spin difference |\n|---|---|---|---|---|---|\n";
  for (const auto& c : report.costs)
  {
    md << std::setprecision(3) << "| " << c.model << " | " << c.own.seconds_per_impact << " | "
       << c.own.max_velocity_error << " | " << c.own.max_spin_error << " | " << c.velocity_difference << " | "
       << c.spin_difference << " |\n";
    std::cerr << "  " << c.model << ": " << c.own.seconds_per_impact * 1e9 << " ns, own error "
              << c.own.max_velocity_error << ", from " << report.model << " " << c.velocity_difference << "\n";
  }
  std::ofstream gp(dir / (report.stem + ".gp"));
  gp << "set terminal pngcairo size 900,600 font ',10'\n"
     << "set output '" << (dir / (report.stem + ".png")).string() << "'\n"
     << "set datafile separator ','\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
     << "set xlabel 'run time per impact [s]'\nset ylabel 'largest error per unit speed'\nset grid\n"
     << "set title '" << report.model << " " << report.kind
     << " impact: error against run time (labels: tolerance)'\nset key top right\n"
     << "plot '" << (dir / (report.stem + ".csv")).string()
     << "' using 2:3 skip 1 with linespoints pointsize 1.5 title 'velocity', '' using 2:4 skip 1 with linespoints "
        "pointsize 1.5 title 'R x spin', '' using 2:3:1 skip 1 with labels offset 0,1 notitle\n";
  gp.close();
  runGnuplot(dir / (report.stem + ".gp"));
}

/// Sustained contact in the air: contact_tolerance against the error of balls on their supports
/// after 0.5 s, against long double at the registry's tightest tolerance (contact_precision.*).
void contactSection(const std::filesystem::path& dir, bool quick)
{
  namespace ev = cue_sim::evaluation;
  constexpr double kReference = 1e-12, kDuration = 0.5;
  const std::vector<double> tolerances =
      quick ? std::vector<double>{2e-10, 1e-11} : std::vector<double>{2e-10, 1e-10, 5e-11, 2e-11, 1e-11, 5e-12, 2e-12};
  std::cerr << "work_precision: sustained contact (contact_tolerance), reference " << kReference << " in long double\n";
  const std::vector<ev::ContactPrecision> results =
      ev::contactPrecision(tolerances, kReference, kDuration, quick ? 1 : 5);
  std::ofstream csv(dir / "contact_precision.csv");
  std::ofstream md(dir / "contact_precision.md");
  csv << "tolerance,seconds,max_position_error,max_velocity_error\n";
  md << "### Sustained contact in the air: error against contact_tolerance\n\n";
  for (const std::string& scene : ev::contactPrecisionScenes())
    md << "- " << scene << "\n";
  md << "\nEach run for " << kDuration << " s of the table's time at the default coefficients; the reference is each "
     << "in long double at contact_tolerance " << kReference << ". Time: the four runs, median of repeats.\n\n"
     << "| contact_tolerance [m] | time [s] | largest position error [m] | largest velocity error [m/s] | "
        "position error by scene [m] |\n"
     << "|---|---|---|---|---|\n";
  for (const ev::ContactPrecision& r : results)
  {
    csv << r.tolerance << "," << r.seconds_per_run << "," << r.max_position_error << "," << r.max_velocity_error
        << "\n";
    md << std::setprecision(3) << "| " << r.tolerance << " | " << r.seconds_per_run << " | " << r.max_position_error
       << " | " << r.max_velocity_error << " |";
    for (const double e : r.position_error)
      md << " " << e;
    md << " |\n";
    std::cerr << "  contact_tolerance " << r.tolerance << ": " << r.seconds_per_run << " s, position error "
              << r.max_position_error << " m\n";
  }
  csv.close();
  std::ofstream gp(dir / "contact_precision.gp");
  gp << "set terminal pngcairo size 900,600 font ',10'\n"
     << "set output '" << (dir / "contact_precision.png").string() << "'\n"
     << "set datafile separator ','\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
     << "set xlabel 'run time of the four scenes [s]'\nset ylabel 'largest error after 0.5 s'\nset grid\n"
     << "set title 'sustained contact: error against run time (labels: contact\\_tolerance)'\nset key top right\n"
     << "plot '" << (dir / "contact_precision.csv").string()
     << "' using 2:3 skip 1 with linespoints pointsize 1.5 title 'position [m]', '' using 2:4 skip 1 with linespoints "
        "pointsize 1.5 title 'velocity [m/s]', '' using 2:3:1 skip 1 with labels offset 0,1 notitle\n";
  gp.close();
  runGnuplot(dir / "contact_precision.gp");
}

/// The integrated impacts (mathavan2010 at the cushion, mathavan2014 between balls): each one's
/// error against its tolerance and run time, and every model of its kind beside it.
void impactSections(const std::filesystem::path& dir, bool quick)
{
  namespace ev = cue_sim::evaluation;
  const int repeats = quick ? 1 : 15;
  std::cerr << "work_precision: cushion impact (mathavan2010), reference tolerance " << kImpactReferenceTolerance
            << "\n";
  writeImpactReport(dir, {"cushion_impact", "mathavan2010", "cushion",
                          "56 balls meeting a cushion at 1 m/s (incidence 5 to 90 degrees, topspin -1 to 2 V/R, side "
                          "spin -2 to 2 V/R with rolling topspin)",
                          ev::cushionImpactPrecision(impactTolerances(quick), kImpactReferenceTolerance, repeats),
                          ev::cushionModelCosts(kImpactReferenceTolerance, repeats)});
  std::cerr << "work_precision: ball-ball impact (mathavan2014), reference tolerance " << kImpactReferenceTolerance
            << "\n";
  writeImpactReport(dir, {"ball_impact", "mathavan2014", "ball-ball",
                          "48 cue balls meeting an object ball at rest at 1 m/s (cut 0 to 75 degrees, topspin -1 to 2 "
                          "V/R, side spin -2 to 2 V/R with rolling topspin); errors of both balls summed",
                          ev::ballImpactPrecision(impactTolerances(quick), kImpactReferenceTolerance, repeats),
                          ev::ballModelCosts(kImpactReferenceTolerance, repeats)});
}
}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Error against run time of the event engine and time-steppers, against a long-double reference."};
  std::string out_dir = "work_precision";
  bool quick = false;
  double budget = 30.0;
  app.add_option("--out", out_dir, "output folder (results.csv, results.md, work_precision.png)");
  app.add_flag("--quick", quick, "single shots, steps 1e-2 to 1e-4 s, one repeat: a check, not a report");
  app.add_option("--budget", budget, "stop refining a method once one run takes longer [s]");
  bool plot_only = false;
  app.add_flag("--plot-only", plot_only, "only redraw the plot from the folder's results.csv");
  bool contacts_only = false;
  app.add_flag("--contacts-only", contacts_only,
               "only sustained contact's error against contact_tolerance (contact_precision.*)");
  bool impacts_only = false;
  app.add_flag("--impacts-only", impacts_only,
               "only the integrated impacts' error against their tolerance (cushion_impact.*, ball_impact.*)");
  CLI11_PARSE(app, argc, argv);

  const std::filesystem::path dir(out_dir);
  std::filesystem::create_directories(dir);
  if (contacts_only)
  {
    contactSection(dir, quick);
    return 0;
  }
  if (impacts_only)
  {
    impactSections(dir, quick);
    contactSection(dir, quick);
    return 0;
  }
  if (plot_only)
  {
    std::vector<std::string> names;
    for (const ShotScene& scene : cue_sim::evaluation::workPrecisionScenes())
      names.push_back(scene.name);
    writePlot(dir, names);
    return 0;
  }
  std::vector<double> steps = {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6, 1e-6};
  std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  if (quick)
  {
    steps = {1e-2, 1e-3, 1e-4};
    tolerances = {1e-3, 1e-6, 1e-9};
  }

  std::ofstream csv(dir / "results.csv");
  csv << "scene,method,step_s_or_tolerance,seconds,max_error_m,final_error_m,work,notes\n";
  std::ofstream md(dir / "results.md");
  std::vector<std::string> scene_names;
  std::ostringstream verdicts;
  for (const ShotScene& scene : cue_sim::evaluation::workPrecisionScenes())
  {
    if (quick && !scene.single_shot)
      continue;
    scene_names.push_back(scene.name);
    std::cerr << "work_precision: " << scene.name << "\n";
    const auto reference = cue_sim::evaluation::referenceRun(scene);
    std::vector<MethodResult> results;
    results.push_back(cue_sim::evaluation::runEventEngine(scene, reference, quick ? 3 : 21));
    for (const Integrator integrator :
         {Integrator::SymplecticEuler, Integrator::RungeKutta4, Integrator::DormandPrince54})
      for (double parameter : integrator == Integrator::DormandPrince54 ? tolerances : steps)
      {
        MethodResult r = cue_sim::evaluation::runStepper(scene, reference, integrator, parameter, 1);
        if (!quick && r.seconds < 0.2)
          r = cue_sim::evaluation::runStepper(scene, reference, integrator, parameter, 5);
        results.push_back(r);
        std::cerr << "  " << r.method << " " << parameter << ": " << r.seconds << " s, error " << r.max_error << "\n";
        if (r.seconds > budget)
          break;
      }
    md << "### " << scene.name << " (" << reference.times.back() << " s to rest)\n\n"
       << "| method | step [s] or tolerance | time per shot [s] | largest error [m] | final error [m] | events or "
          "steps | notes |\n"
       << "|---|---|---|---|---|---|---|\n";
    double fastest_1mm = -1;
    for (const auto& r : results)
    {
      csv << scene.name << "," << r.method << "," << r.parameter << "," << r.seconds << "," << r.max_error << ","
          << r.final_error << "," << r.work << "," << notes(r) << "\n";
      md << std::setprecision(3) << "| " << r.method << " | " << (r.method == "event" ? "-" : [&] {
        std::ostringstream s;
        s << r.parameter;
        return s.str();
      }()) << " | "
         << r.seconds << " | " << r.max_error << " | " << r.final_error << " | " << r.work << " | " << notes(r)
         << " |\n";
      if (r.method != "event" && r.max_error <= 1e-3 && (fastest_1mm < 0 || r.seconds < fastest_1mm))
        fastest_1mm = r.seconds;
    }
    md << "\n";
    if (scene.single_shot)
    {
      const MethodResult& event = results.front();
      verdicts << "- " << scene.name << ": event engine error " << std::setprecision(3) << event.max_error << " m in "
               << event.seconds << " s; the fastest time-stepper within 1e-3 m took "
               << (fastest_1mm < 0 ? std::string("(none reached it)") : std::to_string(fastest_1mm) + " s") << ": "
               << (event.max_error < 1e-9 && (fastest_1mm < 0 || event.seconds < fastest_1mm) ? "goal met"
                                                                                              : "GOAL NOT MET")
               << "\n";
    }
  }
  md << "### Goal: for single shots, error below 1e-9 m in less time than any time-stepper needs for 1e-3 m\n\n"
     << verdicts.str();
  // How the time-steppers fare on the extreme cases (the event engine's own stability suite is
  // test/physics/test_stability.cpp).
  md << "\n### Time-steppers on extreme cases\n\n"
     << "| case | method | step [s] or tolerance | ends | tunnels | deepest overlap [m] | energy gained [J] | slips "
        "snapped | "
        "largest error [m] |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const ShotScene& scene : cue_sim::evaluation::stabilityScenes())
  {
    std::cerr << "work_precision: stability, " << scene.name << "\n";
    const auto reference = cue_sim::evaluation::referenceRun(scene);
    for (const Integrator integrator :
         {Integrator::SymplecticEuler, Integrator::RungeKutta4, Integrator::DormandPrince54})
      for (double step : integrator == Integrator::DormandPrince54 ? std::vector<double>{1e-4, 1e-8}
                         : quick                                   ? std::vector<double>{1e-2, 1e-4}
                                                                   : std::vector<double>{1e-2, 1e-3, 1e-4, 1e-5})
      {
        const MethodResult r = cue_sim::evaluation::runStepper(scene, reference, integrator, step, 1);
        md << std::setprecision(3) << "| " << scene.name << " | " << r.method << " | " << step << " | "
           << (r.stepper.finished         ? "yes"
               : r.stepper.stalled        ? "no: the step collapsed"
               : r.stepper.hit_step_limit ? "no: step limit"
                                          : "no")
           << " | " << (r.stepper.tunnelled ? "yes" : "no") << " | " << r.stepper.max_overlap << " | "
           << r.stepper.energy_gain << " | " << r.stepper.slip_reversals << " | " << r.max_error << " |\n";
      }
  }
  md << "\nThe integrated cushion impact's error against its tolerance: cushion_impact.md, cushion_impact.png; "
        "sustained contact's against contact_tolerance: contact_precision.md, contact_precision.png.\n";
  md.close();
  impactSections(dir, quick);
  contactSection(dir, quick);
  csv.close();
  std::cout << verdicts.str();
  writePlot(dir, scene_names);
  return 0;
}
