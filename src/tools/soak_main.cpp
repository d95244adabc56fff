// soak: a campaign of random shots, each checked at every event (doc/accuracy.md, "Soak campaign").
//   rosrun cue_sim soak --shots 100000 --seed 7          (or devel/lib/cue_sim/soak)
//   rosrun cue_sim soak --replay soak_violations/soak_7_123.yaml
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "cue_sim/evaluation/soak.hpp"

namespace
{
using cue_sim::evaluation::SoakSummary;

void printTally(const char* title, const std::map<std::string, long>& tally)
{
  std::printf("%s:", title);
  for (const auto& [name, count] : tally)
    std::printf(" %s %ld", name.c_str(), count);
  std::printf("\n");
}

/// Each regime's shots per second of one thread (its shots over the time their checks took).
void printRates(const SoakSummary& s)
{
  std::printf("shots/s of a thread by regime:");
  for (const auto& [regime, seconds] : s.regime_seconds)
    std::printf(" %s %.0f", regime.c_str(), static_cast<double>(s.regime_shots.at(regime)) / std::max(seconds, 1e-12));
  std::printf("\n");
}

/// One line on stderr, rewritten in place: how far, how fast, what was found.
void showProgress(const SoakSummary& s, long total)
{
  long violations = 0;
  for (const auto& [kind, count] : s.violations)
    violations += count;
  const double rate = s.seconds > 0 ? static_cast<double>(s.shots) / s.seconds : 0;
  std::fprintf(stderr, "\rsoak: %ld/%ld shots (%.1f %%), %.0f shots/s, %ld events, %ld violations, %.0f s left   ",
               s.shots, total, 100.0 * static_cast<double>(s.shots) / static_cast<double>(total), rate, s.events,
               violations, rate > 0 ? static_cast<double>(total - s.shots) / rate : 0.0);
  std::fflush(stderr);
}

int replay(const std::vector<std::string>& files)
{
  int broken = 0;
  for (const std::string& file : files)
  {
    const cue_sim::Scene scene = cue_sim::loadSceneFile(file);
    const cue_sim::evaluation::SceneCheck check = cue_sim::evaluation::checkScene(scene, true);
    const std::string moving = check.endless.empty() ? "still moving" : "cannot end by physics: " + check.endless;
    std::printf("%s: %ld events, %s, %s\n", file.c_str(), check.events, check.at_rest ? "at rest" : moving.c_str(),
                check.violations.empty() ? "no violation" : "violations:");
    for (const auto& v : check.violations)
      std::printf("  %s: %s\n", v.kind.c_str(), v.detail.c_str());
    broken += !check.violations.empty();
  }
  return broken > 0 ? 1 : 0;
}
}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Random shots over every bundled table, model and coefficient range, checked at every event: no "
      "overlap, nothing off the table or in a cushion, no NaN, no energy gained, the same events "
      "advanced in steps and by the full scan. Each violation is written as a scene file."};
  cue_sim::evaluation::SoakOptions options;
  std::vector<std::string> replays;
  bool quiet = false;
  app.add_option("--shots", options.shots, "how many shots")->check(CLI::Range(1L, 1000000000L));
  app.add_option("--seed", options.seed, "the campaign's seed: shot k of a seed is always the same scene");
  app.add_option("--first", options.first, "the first shot's number (to run shot k alone: --first k --shots 1)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--threads", options.threads, "threads (0: every core)");
  app.add_option("--out", options.out_dir, "where violations are written as scene files (default: soak_violations)");
  app.add_option("--full-scan-every", options.full_scan_every,
                 "compare with the full scan on every this many shots of more than 40 balls (all smaller ones)")
      ->check(CLI::PositiveNumber);
  app.add_option("--replay", replays, "check these scene files instead (a violation's file shows it again)");
  app.add_flag("--quiet", quiet, "no progress line");
  app.add_flag("--airborne", options.airborne,
               "scenes with balls in the air too: thrown, dropped onto others, struck by the sequential cue");
  CLI11_PARSE(app, argc, argv);
  try
  {
    if (!replays.empty())
      return replay(replays);
    if (options.out_dir.empty())
      options.out_dir = "soak_violations";
    const SoakSummary s = cue_sim::evaluation::runSoak(options, [&](const SoakSummary& so_far) {
      if (!quiet)
        showProgress(so_far, options.shots);
    });
    if (!quiet)
      std::fprintf(stderr, "\n");
    long violations = 0;
    for (const auto& [kind, count] : s.violations)
      violations += count;
    std::printf(
        "soak --seed %llu --first %ld --shots %ld: %ld shots, %ld events, %ld at rest, %ld that cannot end by "
        "physics (not counted), %ld compared with the full scan, %.1f s\n",
        static_cast<unsigned long long>(options.seed), options.first, options.shots, s.shots, s.events, s.at_rest,
        s.endless, s.scanned, s.seconds);
    printTally("tables", s.by_table);
    printTally("models", s.by_models);
    printTally("balls", s.by_balls);
    printRates(s);
    std::printf("violations: %ld\n", violations);
    printTally("by kind", s.violations);
    for (const std::string& report : s.reports)
      std::printf("  %s\n", report.c_str());
    return violations > 0 ? 1 : 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "soak: " << e.what() << std::endl;
    return 2;
  }
}
