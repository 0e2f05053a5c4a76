// run_files.h - the files a run writes under its output folder, kept consistent with its checkpoints:
//   probes.csv              one row per probe sample (probe/probes.h),
//   icebergs.csv            scenes with breakable ice: the bodies of intact ice per frame (probe/iceberg_tracker.h),
//   particles_NNNN.vtu      the frames (io/frame_writer.h), listed with their times in particles.pvd; a
//                           distributed run writing pieces (set_pieces): particles_NNNN_rR.vtu from every rank R
//                           and particles_NNNN.pvtu joining them, which particles.pvd lists,
//   checkpoint.bin          the state to resume from (io/checkpoint.h), with the sizes of the two CSV files at
//                           that moment, so that a resumed run cuts them back to where the checkpoint was taken;
//                           a distributed run writing pieces: the manifest of checkpoint_S_rR.bin, every rank's
//                           own particles (S the slot a or b, alternating, so the previous checkpoint stays whole
//                           until the new one is),
//   run.json                provenance: the scene file (absolute path), the --set values, the command line, the
//                           version and git commit; `cdmpm run --resume DIR` reads the scene and --set values here,
//   scene.resolved.json     the scene as loaded: --set values applied, parameters and expressions evaluated,
//   crevasses.csv           scenes with crevassed ice bodies: the realised crevasses (shape/crevasse_field.h),
//   crack_starts.csv        scenes with breakable ice: the crack-start record (probe/crack_starts.h), rewritten
//                           whole at every checkpoint and at the end (the record itself is in the checkpoint).
// A fresh run creates the folder and the files; a resumed run reads the checkpoint into the simulation, the
// probes and the iceberg tracker, and appends to the files.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "hazard/hazard_map.h"
#include "io/checkpoint.h"
#include "probe/iceberg_tracker.h"
#include "probe/probes.h"
#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class RunFiles {
 public:
  RunFiles(const std::string& out_dir, Simulation<dim>& sim, Probes<dim>& probes, IcebergTracker<dim>& icebergs,
           HazardMap<dim>& hazard);
  // Creates the output files (run.json records `command_line`) and probes.csv's header (rank 0 of a distributed
  // run); the run then writes the initial probe sample and frame and gives the hazard record its initial state.
  void start(const std::vector<std::string>& command_line);
  // Loads the checkpoint into the simulation, probes, tracker and hazard record and reopens the files for appending.
  void resume();

  // A probe sample: evaluated on every rank (the probes reduce over the ranks, exactly: math/exact_sum.h), written
  // to probes.csv by rank 0.
  void write_probes();
  // The frame's list entry and particles.pvd (on the whole state), or with pieces only the list entry: the .pvtu
  // is written by write_frame_pieces.
  void write_frame();
  // With pieces, on every rank of a distributed run after write_frame: this rank's piece of the frame of index
  // meta.frame_index, and on rank 0 its .pvtu.
  void write_frame_pieces();
  // Whether write_frame reads particles (a frame written whole), so a distributed run must gather them to rank 0.
  bool frame_reads_particles() const { return !pieces_ && sim_.scene.output.frames; }
  // The bodies of intact ice at the frame of index meta.frame_index, to icebergs.csv (collective: no gather).
  void write_frame_icebergs();
  // Frames as one .pvtu of per-rank pieces and checkpoints as a manifest of per-rank pieces (a distributed run,
  // unless --gather-output) instead of one .vtu and one checkpoint file gathered on rank 0.
  void set_pieces(bool on) { pieces_ = on; }
  // Detection at a probe sample (the first iceberg; collective); true if it was found just now.
  bool sample_icebergs();
  // On every rank (collective in a distributed run): checkpoint.bin, or with pieces every rank's piece and the
  // manifest; and crack_starts.csv.
  void checkpoint();
  // Closes probes.csv (summary.json's wave report reads it) and writes crack_starts.csv.
  void close() {
    csv_.close();
    write_crack_starts();
  }
  std::filesystem::path path(const std::string& name) const { return out_ / name; }

  CheckpointMeta meta;  // frame and probe indices, frames written, ... (what a checkpoint records)

 private:
  void open_tables(bool append);
  void write_provenance(const std::vector<std::string>& command_line) const;
  void write_crevasses() const;
  void write_crack_starts() const;
  void update_meta();
  void checkpoint_pieces();
  void remove_pieces(char keep) const;
  std::filesystem::path out_;
  Simulation<dim>& sim_;
  Probes<dim>& probes_;
  IcebergTracker<dim>& icebergs_;
  HazardMap<dim>& hazard_;
  std::ofstream csv_, bergs_;
  bool pieces_ = false;
  char slot_ = 0;  // the slot (a or b) of the pieces the manifest names (0: none yet)
};

}  // namespace cdmpm
