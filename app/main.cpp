// main.cpp - the cdmpm command line.
//
//   cdmpm run SCENE [--out DIR] [--threads N] [--set path=value ...] [--steps N] [--quiet] [--force]
//   cdmpm run [SCENE] --resume DIR [--set time.end=...]   (scene and --set values from DIR/run.json)
//   cdmpm run SCENE --dry-run --ranks N [--threads T] [--core-rate R]   (the partition of a distributed run on N
//         ranks, without its particles: per-rank particles, blocks, halo bytes, memory; run/run_plan.h; prints JSON)
//   cdmpm check SCENE... [--set path=value ...]   (validity, the estimated cost of each run (run/run_estimate.h) and
//         its particles, seeded keeping none: every refusal of seeding too; warnings of what would move the still
//         water before any wave, run/still_level_check.h)
//   cdmpm impulse-wave --velocity V --depth h --thickness s --mass m --width b [--angle deg] [--distance x ...]
//         (Heller & Hager 2010 impulse-wave relations, src/validation/impulse_wave.h; prints JSON)
//   cdmpm linear-waves DIR --depth h [--wall x] [--gravity g] [--box a w]
//         (a finished run's gauge pairs against linear water-wave theory, src/validation/linear_wave_report.h;
//          writes DIR/linear_waves.csv, prints JSON)
//   cdmpm --help | --version
// Exit codes: 0 success, 1 runtime error (I/O), 2 bad input (scene, command line or checkpoint), 3 run went
// unstable, 130/143 interrupted by SIGINT/SIGTERM (checkpoint written, resumable; run/interrupt.h).
#include <CLI/CLI.hpp>
#include <omp.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>

#include "io/checkpoint_format.h"
#include "scene/scene_loader.h"
#include "parallel/omp_wait_policy.h"
#include "run/interrupt.h"
#include "run/run_estimate.h"
#include "run/run_plan.h"
#include "run/runner.h"
#include "run/still_level_check.h"
#include "validation/impulse_wave.h"
#include "validation/linear_wave_report.h"
#ifdef CDMPM_MPI
#include "parallel/communicator.h"
#include "parallel/domain.h"
#endif

namespace {
// Rank 0 speaks for a distributed run (every rank of the MPI build reaches the same verdicts); one process always.
bool speaks() {
#ifdef CDMPM_MPI
  return cdmpm::mpi::rank() == 0;
#else
  return true;
#endif
}
}  // namespace

// `cdmpm check`: each scene's validity, a summary, the estimate of its run and its seeded particle count; exit 2 if
// any is invalid, too big for this machine or refused by seeding.
int check_scenes(const std::vector<std::string>& paths, const std::vector<std::string>& overrides) {
  int status = 0;
  for (const std::string& path : paths) {
    try {
      const cdmpm::Scene scene = cdmpm::load_scene(path, overrides);
      const cdmpm::RunEstimate e = cdmpm::estimate_run(scene);
      cdmpm::check_run_fits(scene, e);
      // Seeded once keeping no particle, as --dry-run does (after the size check, so a scene too big is not walked):
      // what seeding refuses (a body that seeds nothing, material against a wall face off the grid) is refused here
      // too, and the particle count is exact.
      const nlohmann::json seeded = cdmpm::plan_run(scene, cdmpm::PlanOptions{});
      std::cout << scene.path << ": valid " << scene.dim << "D scene '" << scene.name << "', " << scene.materials.size()
                << " material(s), " << scene.bodies.size() << " body(ies), " << scene.boundaries.size()
                << " boundary(ies), " << scene.probes.size() << " probe(s), end time " << scene.time.end << " s\n  "
                << cdmpm::describe(e) << "\n  seeded: " << seeded["particles"].get<uint64_t>() << " particles";
      if (const uint64_t bed = seeded["bed_layer_particles"].get<uint64_t>(); bed > 0)
        std::cout << " and " << bed << " fixed bed-layer particles";
      std::cout << "\n";
      for (const std::string& w : cdmpm::still_level_warnings(scene)) std::cout << "  warning: " << w << "\n";
    } catch (const std::exception& e) {
      std::cerr << "cdmpm: error: " << e.what() << "\n";
      status = 2;
    }
  }
  return status;
}

// The scene and --set values a resumed run starts from: those DIR/run.json recorded (the scene given on the
// command line, if any, replaces its scene file), then the new --set values (a resume may change time.end and
// the output intervals; the checkpoint's scene fingerprint refuses any other change). An output folder written
// before run.json existed needs the scene and its --set values on the command line.
void resume_inputs(const std::string& dir, std::string& scene_path, std::vector<std::string>& overrides) {
  const std::filesystem::path file = std::filesystem::path(dir) / "run.json";
  if (!std::filesystem::is_regular_file(file)) {
    if (!scene_path.empty()) return;
    throw std::runtime_error(dir + ": no run.json: not the output folder of a cdmpm run (give the scene file too)");
  }
  nlohmann::json run;
  try {
    run = nlohmann::json::parse(std::ifstream(file));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!run.is_object() || !run.contains("scene_file") || !run["scene_file"].is_string() || !run.contains("overrides") ||
      !run["overrides"].is_array() ||
      !std::all_of(run["overrides"].begin(), run["overrides"].end(), [](const auto& o) { return o.is_string(); }))
    throw std::runtime_error(file.string() + ": expected an object with \"scene_file\" (a string) and \"overrides\" (strings)");
  if (scene_path.empty()) scene_path = run["scene_file"].get<std::string>();
  std::vector<std::string> all = run["overrides"].get<std::vector<std::string>>();
  all.insert(all.end(), overrides.begin(), overrides.end());
  overrides = std::move(all);
}

int main(int argc, char** argv) {
  cdmpm::choose_omp_wait_policy(argv);  // may execute the program again (parallel/omp_wait_policy.h)
#ifdef CDMPM_MPI
  const cdmpm::mpi::Session mpi_runtime(argc, argv);  // `mpirun -np N cdmpm run SCENE` (docs/architecture.md)
#endif
  CLI::App app{"cdmpm: Material Point Method simulator of glacier calving and the tsunamis it raises"};
  app.set_version_flag("--version", std::string("cdmpm ") + CDMPM_VERSION);
  app.require_subcommand(1);

  std::string scene_path, out_dir, resume_dir;
  std::vector<std::string> overrides;
  int threads = 0;
  long long max_steps = 0;
  bool quiet = false;

  auto* run = app.add_subcommand("run", "Run a scene");
  run->add_option("scene", scene_path, "Scene file (JSON); with --resume DIR, default the one DIR/run.json names");
  run->add_option("--out", out_dir, "Output directory (default: output/<scene name>)");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_option("--set", overrides, "Override a scene value, e.g. --set time.end=0.5 (repeatable)");
  run->add_option("--resume", resume_dir,
                  "Continue the run in DIR from its last checkpoint, with the scene and --set values of DIR/run.json");
  run->add_option("--steps", max_steps, "Stop after N steps (e.g. to measure speed and memory); summary.json says so")
      ->check(CLI::PositiveNumber);
  run->add_flag("--quiet", quiet, "No progress line");
  bool force = false, gather_output = false, dry_run = false;
  run->add_flag("--force", force, "Run even if the estimate exceeds the machine's memory or the frame limit");
  cdmpm::PlanOptions plan;
  run->add_flag("--dry-run", dry_run,
                "Do not run: seed the scene keeping no particle, partition it for --ranks ranks as a distributed run "
                "does, and print (JSON) each rank's particles, blocks, halo bytes per step, memory and a projected "
                "step time (run/run_plan.h); writes nothing");
  run->add_option("--ranks", plan.ranks, "With --dry-run: the number of ranks to plan for (default 1)")
      ->check(CLI::Range(1, 1 << 20));
  run->add_option("--core-rate", plan.core_rate,
                  "With --dry-run: particle-steps per second per core for the projected step time (default 1e6 in "
                  "3D, 2e6 in 2D)")
      ->check(CLI::PositiveNumber);
#ifdef CDMPM_MPI
  run->add_option("--rebalance", cdmpm::rebalance_threshold,
                  "Distributed run: partition the blocks again when the particle imbalance max/mean over the ranks "
                  "exceeds this at a particle sort (default 1.1; results do not depend on it)")
      ->check(CLI::Range(1.0, 1e9));
  run->add_flag("--gather-output", gather_output,
                "Distributed run: write each frame as one .vtu and the checkpoint as one file, gathered on rank 0, as "
                "one process does, instead of per-rank pieces under a .pvtu and a checkpoint manifest");
#endif

  std::vector<std::string> check_paths;
  auto* check = app.add_subcommand("check", "Validate scenes and print, for each, a summary and what a run would cost");
  check->add_option("scenes", check_paths, "Scene files (JSON)")->required();
  check->add_option("--set", overrides, "Override a scene value (repeatable)");

  cdmpm::ImpulseWaveInput wave;
  std::vector<double> distances;
  auto* impulse = app.add_subcommand("impulse-wave", "Heller & Hager (2010) 2D impulse-wave relations; prints JSON");
  impulse->add_option("--velocity", wave.slide_velocity, "Slide impact velocity V_s [m/s]")->required()->check(CLI::PositiveNumber);
  impulse->add_option("--depth", wave.depth, "Still-water depth h [m]")->required()->check(CLI::PositiveNumber);
  impulse->add_option("--thickness", wave.thickness, "Slide thickness s [m]")->required()->check(CLI::PositiveNumber);
  impulse->add_option("--mass", wave.mass, "Slide mass m_s over the width b [kg]")->required()->check(CLI::PositiveNumber);
  impulse->add_option("--width", wave.width, "Slide width b [m]")->required()->check(CLI::PositiveNumber);
  impulse->add_option("--water-density", wave.water_density, "Water density [kg/m^3] (default 1000)")->check(CLI::PositiveNumber);
  impulse->add_option("--angle", wave.angle_degrees, "Slide impact angle alpha [degrees] (default 90)")->check(CLI::Range(0.0, 90.0));
  impulse->add_option("--distance", distances, "Distances x from impact [m] at which to give the amplitude (repeatable)");

  std::string waves_dir;
  cdmpm::LinearWaveOptions linear;
  double wall_x = 0;
  auto* linear_cmd = app.add_subcommand(
      "linear-waves", "Carry each gauge's record to the next gauge by linear water-wave theory and compare the first "
                      "crests; writes DIR/linear_waves.csv, prints JSON");
  linear_cmd->add_option("dir", waves_dir, "Output directory of a finished run (waves.csv, probes.csv)")->required();
  linear_cmd->add_option("--depth", linear.depth, "Still-water depth h between the gauges [m]")->required()
      ->check(CLI::PositiveNumber);
  linear_cmd->add_option("--gravity", linear.gravity, "Gravitational acceleration g [m/s^2] (default 9.81)")
      ->check(CLI::PositiveNumber);
  auto* wall_opt = linear_cmd->add_option("--wall", wall_x, "x of a fully reflecting end wall beyond the gauges [m]");
  std::vector<double> box;
  auto* box_opt = linear_cmd->add_option("--box", box, "The run released a box of water a high and w wide against the "
                                                      "wall at x = 0: compare every gauge with the Cauchy-Poisson "
                                                      "solution (writes DIR/cauchy_poisson.csv) [m m]")
                      ->expected(2)->check(CLI::PositiveNumber);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (impulse->parsed()) {
    const cdmpm::ImpulseWave w = cdmpm::heller_hager_2010(wave);
    nlohmann::json out = {{"F", w.F}, {"S", w.S}, {"M", w.M}, {"P", w.P}, {"max_amplitude", w.max_amplitude},
                          {"max_height", w.max_height}, {"max_location", w.max_location}, {"in_range", w.in_range}};
    out["amplitude_at"] = nlohmann::json::array();
    for (double x : distances) out["amplitude_at"].push_back({{"x", x}, {"amplitude", w.amplitude_at(x, wave.depth)}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }

  if (linear_cmd->parsed()) {
    if (wall_opt->count() > 0) linear.wall_x = wall_x;
    if (box_opt->count() > 0) linear.box = cdmpm::LinearWaveOptions::Box{box[0], box[1]};
    try {
      std::cout << cdmpm::linear_wave_report(waves_dir, linear).dump(2) << "\n";
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "cdmpm: error: " << e.what() << "\n";
      return 2;
    }
  }

  if (check->parsed()) return check_scenes(check_paths, overrides);
  // More threads than a few per core only slows a run down, and the OpenMP runtime fails on absurd counts with an
  // error of its own: refused up front (a --dry-run plans for another machine and may name any count).
  if (const int limit = std::max(8, 4 * omp_get_num_procs()); threads > limit && !dry_run) {
    std::cerr << "cdmpm: error: --threads " << threads << ": at most " << limit << " (4 per core of this machine's "
              << omp_get_num_procs() << ", at least 8)\n";
    return 2;
  }
  cdmpm::Scene scene;
  try {
    if (!resume_dir.empty()) resume_inputs(resume_dir, scene_path, overrides);
    if (scene_path.empty()) throw std::runtime_error("run: a scene file is required (or --resume DIR)");
    scene = cdmpm::load_scene(scene_path, overrides);
#ifdef CDMPM_MPI
    const int ranks_here = cdmpm::mpi::node_size(), ranks = cdmpm::mpi::size();
#else
    const int ranks_here = 1, ranks = 1;
#endif
    cdmpm::check_run_fits(scene, cdmpm::estimate_run(scene), force || dry_run, ranks_here, ranks);
    if (speaks() && !dry_run)
      for (const std::string& w : cdmpm::still_level_warnings(scene)) std::cerr << "cdmpm: warning: " << w << "\n";
    if (dry_run) {
      plan.threads = threads > 0 ? threads : 1;
      const nlohmann::json out = cdmpm::plan_run(scene, plan);
      if (speaks()) std::cout << out.dump(2) << "\n";
      return 0;
    }
  } catch (const std::exception& e) {  // SceneError, or anything else a hostile file provokes: input error
    if (speaks()) std::cerr << "cdmpm: error: " << e.what() << "\n";
    return 2;
  }

  cdmpm::RunOptions opt;
  opt.command_line.assign(argv, argv + argc);
  opt.threads = threads;
  opt.progress = !quiet && speaks();
  opt.max_steps = max_steps;
  opt.gather_output = gather_output;
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
  cdmpm::install_interrupt_handlers();
  // A failure mid-run: the message and the exit code (2 for input, 1 otherwise). One rank of a distributed run that
  // fails ends them all, the others would wait for it forever.
  auto fail = [](const std::exception& e, int code) {
#ifdef CDMPM_MPI
    if (cdmpm::mpi::size() > 1) cdmpm::mpi::abort(e.what(), code);
#endif
    std::cerr << "cdmpm: error: " << e.what() << "\n";
    return code;
  };
  try {
    const cdmpm::RunResult r = cdmpm::run_scene(scene, opt);
    if (speaks()) std::cout << "cdmpm: " << r.status << "; outputs in " << opt.out_dir << "\n";
    return r.exit_code;
  } catch (const cdmpm::CheckpointError& e) {
    return fail(e, 2);
  } catch (const cdmpm::SceneError& e) {  // found while building the run, e.g. a body that seeds no particle
    return fail(e, 2);
  } catch (const std::bad_alloc&) {  // the cause named: a rank of a distributed run that ran out of memory
    return fail(std::runtime_error("out of memory: an allocation failed (std::bad_alloc)"), 1);
  } catch (const std::exception& e) {
    return fail(e, 1);
  }
}
