// run_files.cpp - the output files of a run and its checkpoints (run_files.h).
#include "run/run_files.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/checkpoint_format.h"
#include "io/frame_writer.h"
#include "io/scene_fingerprint.h"
#include "run/output_dir.h"
#include "io/vtu_writer.h"
#include "parallel/reduction.h"
#ifdef CDMPM_MPI
#include "parallel/communicator.h"
#endif

namespace cdmpm {
namespace fs = std::filesystem;

template <int dim>
RunFiles<dim>::RunFiles(const std::string& out_dir, Simulation<dim>& sim, Probes<dim>& probes, IcebergTracker<dim>& icebergs,
                        HazardMap<dim>& hazard)
    : out_(out_dir), sim_(sim), probes_(probes), icebergs_(icebergs), hazard_(hazard) {}

template <int dim>
void RunFiles<dim>::open_tables(bool append) {
  const auto mode = append ? std::ios::app : std::ios::trunc;
  csv_.open(path("probes.csv"), mode);
  if (!csv_) throw std::runtime_error(path("probes.csv").string() + ": cannot write");
  csv_.precision(10);
  if (!icebergs_.active()) return;
  bergs_.open(path("icebergs.csv"), mode);
  if (!bergs_) throw std::runtime_error(path("icebergs.csv").string() + ": cannot write");
  bergs_.precision(10);
}

template <int dim>
void RunFiles<dim>::write_provenance(const std::vector<std::string>& command_line) const {
  const Scene& scene = sim_.scene;
  const nlohmann::json run = {{"scene_file", fs::absolute(scene.path).lexically_normal().string()},
                              {"overrides", scene.overrides},
                              {"command_line", command_line},
                              {"version", CDMPM_VERSION},
                              {"git_commit", CDMPM_GIT_COMMIT}};
  std::ofstream(path("run.json")) << run.dump(2) << '\n';
  std::ofstream(path("scene.resolved.json")) << scene.resolved.dump(2) << '\n';
  write_crevasses();
}

// crevasses.csv: the realised surface crevasses of every body that has them (shape/crevasse_field.h).
template <int dim>
void RunFiles<dim>::write_crevasses() const {
  const Scene& scene = sim_.scene;
  if (std::none_of(scene.bodies.begin(), scene.bodies.end(), [](const BodySpec& b) { return b.crevasses.has_value(); }))
    return;
  std::ofstream out(path("crevasses.csv"));
  if (!out) throw std::runtime_error(path("crevasses.csv").string() + ": cannot write");
  out.precision(10);
  out << CrevasseField::csv_header(dim) << '\n';
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].crevasses) scene.bodies[i].crevasses->write_csv(out, i);
}

template <int dim>
void RunFiles<dim>::start(const std::vector<std::string>& command_line) {
  prepare_output_dir(out_);
  write_provenance(command_line);
  open_tables(false);
  if (icebergs_.active()) bergs_ << IcebergTracker<dim>::csv_header() << '\n';
  meta.wave_dt_at_start = sim_.wave_dt_at_start;
  meta.scene_fingerprint = scene_fingerprint(sim_.scene);
  csv_ << probes_.csv_header() << '\n';
}

template <int dim>
void RunFiles<dim>::resume() {
  const std::string ckpt = path("checkpoint.bin").string();
  // What the scene seeds (over all ranks of a distributed run, each of which reads its share of the checkpoint,
  // partitioned again and migrated by Simulation::restore).
  const auto seeded = static_cast<size_t>(global::sum(double(sim_.particles.size())));
  const auto seeded_solids = static_cast<size_t>(global::sum(double(sim_.particles.solid_count())));
  CheckpointShare share;
  CheckpointShare* mine = nullptr;
#ifdef CDMPM_MPI
  if (sim_.domain()) share.rank = mpi::rank(), share.ranks = mpi::size(), mine = &share;
#endif
  meta = read_checkpoint(ckpt, sim_.particles, mine);
  slot_ = meta.pieces.empty() ? 0 : checkpoint_piece_slot(meta.pieces.front().file);
  validate_checkpoint(ckpt, meta, sim_.particles, sim_.scene);
  // Sinks remove particles, so a checkpoint of a scene with sinks may hold fewer than the scene seeds.
  const bool fewer_allowed = !sim_.sinks.empty();
  const auto n = static_cast<size_t>(global::sum(double(sim_.particles.size())));
  const auto ns = static_cast<size_t>(global::sum(double(sim_.particles.solid_count())));
  const bool fits = fewer_allowed ? n <= seeded && ns <= seeded_solids : n == seeded && ns == seeded_solids;
  if (!fits)
    throw std::runtime_error(ckpt + ": checkpoint holds " + std::to_string(n) + " particles (" + std::to_string(ns) +
                             " ice), the scene seeds " + (fewer_allowed ? "at most " : "") + std::to_string(seeded) + " (" +
                             std::to_string(seeded_solids) + " ice): resume with the scene and --set values of the run that wrote it");
  sim_.restore(meta.time, meta.steps, static_cast<Real>(meta.wave_dt_at_start), mine ? &share.keys : nullptr);
  if (!probes_.load_state(meta.probe_state))
    throw std::runtime_error(ckpt + ": checkpoint holds the state of other probes than the scene's");
  if (!sim_.rigid.load(meta.rigid_bodies))
    throw std::runtime_error(ckpt + ": checkpoint holds the state of another set of rigid bodies than the scene's");
  if (!hazard_.load_state(meta.hazard))
    throw std::runtime_error(ckpt + ": checkpoint holds a hazard record that does not fit the scene's columns");
  icebergs_.first_ = meta.first_iceberg;
  if (!sim_.crack_starts.load(meta.crack_starts))
    throw std::runtime_error(ckpt + ": checkpoint holds a crack-start record of another dimension");
  restore_output_size(path("probes.csv"), meta.probes_csv_bytes);
  if (icebergs_.active()) restore_output_size(path("icebergs.csv"), meta.icebergs_csv_bytes);
  open_tables(true);
}

template <int dim>
void RunFiles<dim>::write_probes() {
  const std::vector<double> row = probes_.sample(sim_);  // on every rank: the probes' reductions are collective
  sim_.on_root([&] {
    csv_ << sim_.time();
    for (double v : row) csv_ << ',' << v;
    csv_ << '\n';
    csv_.flush();
  });
}

// The frame of index meta.frame_index (if the scene writes frames), listed in particles.pvd.
template <int dim>
void RunFiles<dim>::write_frame() {
  if (sim_.scene.output.frames) {
    char name[64];
    std::snprintf(name, sizeof name, pieces_ ? "particles_%04lld.pvtu" : "particles_%04lld.vtu", meta.frame_index);
    if (!pieces_) cdmpm::write_frame(path(name).string(), sim_);
    meta.frames.emplace_back(sim_.time(), name);
    write_pvd(path("particles.pvd").string(), meta.frames);
  }
}

template <int dim>
void RunFiles<dim>::write_frame_icebergs() {
  if (!icebergs_.active()) return;
  const std::vector<IceBody<dim>> bodies = icebergs_.detect();
  sim_.on_root([&] { icebergs_.write_rows(bergs_, meta.frame_index, bodies); });
}

template <int dim>
bool RunFiles<dim>::sample_icebergs() {
  const auto bodies = icebergs_.sample();
  if (!bodies) return false;
  sim_.on_root([&] { icebergs_.write_rows(bergs_, meta.frame_index, *bodies); });
  return true;
}

template <int dim>
void RunFiles<dim>::write_frame_pieces() {
  if (!pieces_ || !sim_.scene.output.frames) return;
#ifdef CDMPM_MPI
  const int me = mpi::rank(), ranks = mpi::size();
  mpi::barrier();  // rank 0 has prepared the folder (start)
#else
  const int me = 0, ranks = 1;
#endif
  std::vector<std::string> pieces;
  for (int r = 0; r < ranks; ++r) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04lld_r%d.vtu", meta.frame_index, r);
    pieces.push_back(name);
  }
  char pvtu[64];
  std::snprintf(pvtu, sizeof pvtu, "particles_%04lld.pvtu", meta.frame_index);
  write_frame_piece(path(pieces[me]).string(), sim_, me == 0 ? path(pvtu).string() : std::string(), pieces);
}

// The bookkeeping a checkpoint records (on the whole state: rank 0 of a distributed run), and crack_starts.csv.
template <int dim>
void RunFiles<dim>::update_meta() {
  meta.time = sim_.time();
  meta.steps = sim_.steps();
  meta.probes_csv_bytes = static_cast<uint64_t>(fs::file_size(path("probes.csv")));
  meta.icebergs_csv_bytes = icebergs_.active() ? static_cast<uint64_t>(fs::file_size(path("icebergs.csv"))) : 0;
  meta.first_iceberg = icebergs_.first_;
  meta.crack_starts = sim_.crack_starts.save();
  write_crack_starts();
  meta.rigid_bodies = sim_.rigid.save();
  meta.probe_state = probes_.save_state();
  meta.hazard = hazard_.save_state();
  meta.pieces.clear();
}

template <int dim>
void RunFiles<dim>::checkpoint() {
  if (pieces_) return checkpoint_pieces();
  sim_.with_whole_state([&] {
    update_meta();
    write_checkpoint(path("checkpoint.bin").string(), sim_.particles, meta);
    remove_pieces(0);  // of a distributed run this one resumed
  });
  slot_ = 0;
}

// Removes the checkpoint pieces (checkpoint_S_rR.bin) of every slot but `keep`: those the manifest no longer names.
template <int dim>
void RunFiles<dim>::remove_pieces(char keep) const {
  if (slot_ == 0) return;  // no pieces since this run started or resumed
  std::vector<fs::path> old;
  for (const auto& entry : fs::directory_iterator(out_)) {
    const std::string name = entry.path().filename().string();
    const char slot = checkpoint_piece_slot(name);
    if (slot && slot != keep) old.push_back(entry.path());
  }
  for (const auto& f : old) fs::remove(f);
}

// Every rank writes its particles to the slot the manifest does not name; once all have (the gather), rank 0
// replaces the manifest and removes the previous slot's pieces (io/checkpoint.h).
template <int dim>
void RunFiles<dim>::checkpoint_pieces() {
#ifdef CDMPM_MPI
  const char slot = slot_ == 'a' ? 'b' : 'a';
  const CheckpointPiece mine =
      write_checkpoint_piece(path(checkpoint_piece_name(slot, mpi::rank())).string(), sim_.particles, sim_.domain()->keys());
  mpi::Bytes b;
  mpi::put(b, mine.n), mpi::put(b, mine.ns), mpi::put(b, mine.bytes), mpi::put(b, mine.crc);
  const std::vector<mpi::Bytes> all = mpi::gather(b);
  slot_ = slot;
  if (mpi::rank() == 0) {
    const mpi::LocalScope local;
    update_meta();
    for (size_t r = 0; r < all.size(); ++r) {
      mpi::Reader read{all[r]};
      CheckpointPiece& piece = meta.pieces.emplace_back();
      piece.file = checkpoint_piece_name(slot, static_cast<int>(r));
      piece.n = read.get<uint64_t>(), piece.ns = read.get<uint64_t>(), piece.bytes = read.get<uint64_t>();
      piece.crc = read.get<uint32_t>();
    }
    write_checkpoint_manifest(path("checkpoint.bin").string(), dim, meta);
    remove_pieces(slot);
  }
  mpi::barrier();
#endif
}

template <int dim>
void RunFiles<dim>::write_crack_starts() const {
  if (!sim_.crack_starts.active()) return;
  std::ofstream os(path("crack_starts.csv"));
  sim_.crack_starts.write_csv(os);
  if (!os) throw std::runtime_error(path("crack_starts.csv").string() + ": cannot write");
}

template class RunFiles<2>;
template class RunFiles<3>;

}  // namespace cdmpm
