// main.cpp - the cdmpm command line.
//
//   cdmpm run SCENE [--out DIR] [--threads N] [--set path=value ...] [--resume DIR] [--quiet]
//   cdmpm check SCENE [--set path=value ...]
//   cdmpm --help | --version
// Exit codes: 0 success, 1 runtime error (I/O), 2 bad input (scene or command line), 3 run went unstable.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "scene/scene_loader.h"
#include "sim/runner.h"

int main(int argc, char** argv) {
  CLI::App app{"cdmpm: Material Point Method simulator of glacier calving and the tsunamis it raises"};
  app.set_version_flag("--version", std::string("cdmpm ") + CDMPM_VERSION);
  app.require_subcommand(1);

  std::string scene_path, out_dir, resume_dir;
  std::vector<std::string> overrides;
  int threads = 0;
  long long max_steps = 0;
  bool quiet = false;

  auto* run = app.add_subcommand("run", "Run a scene");
  run->add_option("scene", scene_path, "Scene file (JSON)")->required();
  run->add_option("--out", out_dir, "Output directory (default: output/<scene name>)");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_option("--set", overrides, "Override a scene value, e.g. --set time.end=0.5 (repeatable)");
  run->add_option("--resume", resume_dir, "Continue the run in DIR from its last checkpoint");
  run->add_option("--steps", max_steps, "Stop after N steps (e.g. to measure speed and memory); summary.json says so")
      ->check(CLI::PositiveNumber);
  run->add_flag("--quiet", quiet, "No progress line");

  auto* check = app.add_subcommand("check", "Validate a scene and print a summary of it");
  check->add_option("scene", scene_path, "Scene file (JSON)")->required();
  check->add_option("--set", overrides, "Override a scene value (repeatable)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  cdmpm::Scene scene;
  try {
    scene = cdmpm::load_scene(scene_path, overrides);
  } catch (const cdmpm::SceneError& e) {
    std::cerr << "cdmpm: error: " << e.what() << "\n";
    return 2;
  }
  if (check->parsed()) {
    std::cout << scene.path << ": valid " << scene.dim << "D scene '" << scene.name << "', " << scene.materials.size()
              << " material(s), " << scene.bodies.size() << " body(ies), " << scene.boundaries.size()
              << " boundary(ies), " << scene.probes.size() << " probe(s), end time " << scene.time.end << " s\n";
    return 0;
  }

  cdmpm::RunOptions opt;
  opt.threads = threads;
  opt.progress = !quiet;
  opt.max_steps = max_steps;
  if (!resume_dir.empty()) {
    if (!out_dir.empty() && std::filesystem::path(out_dir) != std::filesystem::path(resume_dir)) {
      std::cerr << "cdmpm: error: --out and --resume name different directories; a resumed run writes into DIR\n";
      return 2;
    }
    opt.out_dir = resume_dir;
    opt.resume = true;
  } else {
    opt.out_dir = out_dir.empty() ? "output/" + scene.name : out_dir;
  }
  try {
    const cdmpm::RunResult r = cdmpm::run_scene(scene, opt);
    std::cout << "cdmpm: " << r.status << "; outputs in " << opt.out_dir << "\n";
    return r.exit_code;
  } catch (const std::exception& e) {
    std::cerr << "cdmpm: error: " << e.what() << "\n";
    return 1;
  }
}
