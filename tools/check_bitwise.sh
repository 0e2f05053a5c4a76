#!/bin/bash
# check_bitwise.sh - does a new cdmpm binary give the same results as a reference binary, bit for bit?
# Runs every shipped scene (scenes/*.json) briefly with both binaries and the same --set overrides, then compares
# each pair of output folders with tools/compare_runs.py (probes.csv, icebergs.csv, waves.csv byte for byte; every
# frame's points and data arrays bit for bit; the frame list; the results in summary.json). docs/testing.md.
#
#   bash tools/check_bitwise.sh REF_BINARY NEW_BINARY [OUTDIR]      (OUTDIR default: a new folder under /tmp)
#
# Environment: OMP_WAIT_POLICY (default passive); REF_THREADS / NEW_THREADS (default 2) set --threads of each binary (REF_THREADS=1 NEW_THREADS=2 with
# the same binary twice checks determinism across thread counts; add COMPARE_ARGS="--skip-summary energy,energy_initial,mass_change":
# the energy and mass totals of summary.json are OpenMP reductions, whose last bits depend on the thread count);
# COMPARE_ARGS is passed to compare_runs.py; SCENES="dam_break_2d ice_bar_2d" runs only those.
# Prints a table scene | steps | frames compared | verdict; exit status 0 if all identical, 1 if any differs or
# a run failed, 2 on bad usage. The full reports are in OUTDIR/compare_<scene>.txt, the runs in OUTDIR/{ref,new}.
set -uo pipefail

# Per-scene overrides, given to both binaries. End times are chosen so that every run covers 4-5 frames and
# takes at most ~20 s with 2 threads on a loaded 2-core host (calving_front_2d, which runs to its first iceberg);
# most take 2-10 s. Measured: docs/testing.md.
# scene | overrides | why this end time
CASES=(
  "absorbing_packet_2d|parameters.cells_per_h=6 output.frames=true time.end=6 time.frame_interval=2|the packet splits, its halves enter the absorbing layers at both ends (boundary/absorbing_layer.cpp); ~2900 steps of 7.5k particles at 6 cells per h (full run 20 s; frames turned on)"
  "absorbing_solitary_3d|output.frames=true time.end=1 time.frame_interval=0.5|the 3D solitary wave starts along the channel (the layer's 3D columns, still water in front of it); ~480 steps of 24k particles (full run 13 s; frames turned on)"
  "absorbing_solitary_2d|parameters.cells_per_h=6 output.frames=true time.end=8 time.frame_interval=2|the solitary wave enters the absorbing layer and its spillway removes water (from 5.5 s); ~3800 steps of 6.1k particles at 6 cells per h (full run 15 s; frames turned on)"
  "capsize_slab_2d|parameters.cells_per_H=8 output.frames=true time.end=1 time.frame_interval=0.25|the slab starts to turn; ~1300 steps of 2.6k particles at h/8 (full run 12 s at h/16; frames turned on)"
  "calving_front_2d|time.end=1.5 time.frame_interval=0.5|the notch overhang breaks off at t = 1.4 s: covers the first iceberg (icebergs.csv, summary first_iceberg); ~930 steps of 20k particles, the longest case"
  "calving_3d|parameters.cells_per_H=6 time.end=1 time.frame_interval=0.25|the 25M-particle scale scene at H/6 instead of H/50 (43k particles): 1 s of ice and water settling; its first iceberg comes after the push (> 10 s), not cheap"
  "eqip_sermia_block_2d|parameters.dx=20 time.end=10 time.frame_interval=5|the driven block (rigid motion, a prescribed tilt about its hinge) toppling into the fjord; ~450 steps of 4.2k particles (full run 160 s)"
  "eqip_sermia_3d|parameters.dx=40 time.end=4 time.frame_interval=2|the same block as an 80 m section of the front in 3D, beside box obstacles, bed layer and absorbing layer; ~90 steps at dx = 40 m (full run 160 s at 20 m)"
  "eqip_sermia_2d|parameters.dx=20 time.end=4 time.frame_interval=1|the glacier settles for 10 s before t = 0 (time.settle; elastic, damped) over the fjord, dry crevasses from the seeded noise, plane-strain ice; 4 s after it at dx = 20 m"
  "dam_break_2d|time.end=0.03 time.frame_interval=0.01|the water column starts to fall; ~1200 steps of 12.8k particles (full run 0.25 s)"
  "dam_break_3d|time.end=0.03 time.frame_interval=0.01|the 3D column starts to fall; ~360 steps of 27.6k particles (full run 0.25 s)"
  "hydrostatic_2d|time.end=1 time.frame_interval=0.25|512 particles settling; 1400 steps (full run 3 s)"
  "ice_bar_2d|time.frame_interval=0.005|the full run (end 0.02 s, 800 steps of 6.4k particles): the bar pulled until it breaks"
  "lake_at_rest_2d|parameters.dx=20 time.end=5 time.frame_interval=2.5|water at rest over the Eqip profile with the well-balanced bed layer (sim/bed_layer.h); ~200 steps of 5.1k particles (full run 60 s at dx = 10 m)"
  "lake_at_rest_3d|time.end=1 time.frame_interval=0.5|the same over the extruded channel (scenes/data/eqip_sermia_channel.asc); ~20 steps (full run 60 s)"
  "ice_shear_2d|time.frame_interval=0.0005|the full run (end 0.002 s, 80 steps of 25.6k particles): the block sheared until it breaks, 64 crack starts, all shear (crack_starts.csv)"
  "lab_bf_2d|output.frames=true time.end=0.2 time.frame_interval=0.05|the block starts to move; ~440 steps of 40k particles (frames are off in the scene: turned on)"
  "lab_cs_2d|output.frames=true time.end=0.2 time.frame_interval=0.05|as lab_bf_2d (40k particles)"
  "lab_gf_2d|output.frames=true time.end=0.2 time.frame_interval=0.05|as lab_bf_2d (41k particles)"
  "rigid_rise_2d|output.frames=true time.frame_interval=0.1|the full run (end 0.3 s, 540 steps of 12.8k particles; frames turned on)"
  "rigid_rise_contact_2d|output.frames=true time.frame_interval=0.1|the full run (end 0.3 s at dx = 0.05 m): the block in contact (sim/rigid_contact.h) with J-bar, FLIP and XPIC(4) water; frames turned on"
  "rigid_rise_float_2d|parameters.dx=0.05 time.end=0.5 time.frame_interval=0.25|the block of rigid_rise_2d with APIC water (continuity interpolated) starting to rise at dx = 0.05 m (full run 10 s at 0.025 m, to the surface and back)"
  "rigid_float_2d|output.frames=true time.end=0.5 time.frame_interval=0.25|the block released at the still level starts to settle (full run 6 s; frames turned on)"
  "eqip_sermia_wedge_2d|time.end=4 time.frame_interval=2|the rigid wedge slides on its failure plane (boundary key within) and reaches the water after about 3 s (full run 160 s)"
  "blob_rise_2d|output.frames=true time.frame_interval=0.1|the full run (end 0.3 s, about 510 steps of 12.8k particles; frames turned on)"
  "ice_rise_2d|output.frames=true time.end=0.05 time.frame_interval=0.025|the ice block's start (5700 steps to 0.3 s at its P-wave time step; ~1000 to 0.05 s)"
  "ice_rise_contact_2d|output.frames=true time.end=0.05 time.frame_interval=0.025|the ice block in a field of its own (sim/field_contact.h) starting to rise; ~1000 steps to 0.05 s"
  "sliding_block_2d|time.end=2 time.frame_interval=0.5|the push starts; ~1000 steps of 20k particles (the first iceberg needs 100+ s: not cheap)"
  "solitary_runup_2d|output.frames=true time.end=1 time.frame_interval=0.25|the solitary wave travels 3 h along the tank (hazard record, solitary_wave initial state); ~1100 steps of 12.6k particles (full run 6.5 s; frames turned on)"
  "handoff_2d|parameters.cells_per_h=4 output.frames=true time.end=2 time.frame_interval=0.5 output.snapshots.times=[0,1,2]|the solitary wave travels 6.5 h along the channel, with gauges, a section and snapshots (hand-off outputs); ~1300 steps of 3.8k particles at 4 cells per h (full run 13 s; frames turned on)"
  "wave_celerity_2d|output.frames=true time.end=0.4 time.frame_interval=0.1|the released box starts the wave; ~680 steps of 22k particles (full run 4.5 s; frames turned on)"
)

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: bash tools/check_bitwise.sh REF_BINARY NEW_BINARY [OUTDIR]" >&2
  exit 2
fi
REF=$(realpath "$1"); NEW=$(realpath "$2")
for b in "$REF" "$NEW"; do
  [ -x "$b" ] || { echo "check_bitwise: $b is not an executable" >&2; exit 2; }
done
OUT=${3:-$(mktemp -d /tmp/check_bitwise.XXXXXX)}
mkdir -p "$OUT/ref" "$OUT/new"
OUT=$(realpath "$OUT")
# Threads wait passively at barriers: on a loaded shared host the default spinning makes a 2-thread run up to 10x
# slower (calving_3d case: 146 s against 11 s wall). It does not change any result.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
REF_THREADS=${REF_THREADS:-2}
NEW_THREADS=${NEW_THREADS:-2}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"

# Every shipped scene must have a case: a new scene without one fails the check instead of being skipped silently.
status=0
for f in scenes/*.json; do
  s=$(basename "$f" .json)
  printf '%s\n' "${CASES[@]}" | grep -q "^$s|" || { echo "check_bitwise: no case for $f: add one to CASES" >&2; status=1; }
done

run() {  # run BINARY THREADS SCENE OUTDIR OVERRIDES... ; prints "rc wall_seconds cpu_seconds"
  local bin=$1 threads=$2 scene=$3 dir=$4; shift 4
  local sets=() o rc
  for o in "$@"; do sets+=(--set "$o"); done
  rm -rf "$dir"
  /usr/bin/time -f "%e %U %S" -o "$dir.time" \
      "$bin" run "scenes/$scene.json" --out "$dir" --threads "$threads" --quiet "${sets[@]}" >"$dir.log" 2>&1
  rc=$?
  read -r wall usr sys <"$dir.time"
  echo "$rc $wall $(echo "$usr + $sys" | bc)"
}

echo "check_bitwise: REF $REF (--threads $REF_THREADS)"
echo "               NEW $NEW (--threads $NEW_THREADS)"
echo "               outputs in $OUT"
printf "%-18s %6s %7s %11s %11s  %s\n" scene steps frames REF_wall/cpu NEW_wall/cpu verdict
rows=()
cpu_all=0
t_all=$(date +%s.%N)
for c in "${CASES[@]}"; do
  IFS='|' read -r scene overrides why <<<"$c"
  if [ -n "${SCENES:-}" ] && [[ " $SCENES " != *" $scene "* ]]; then continue; fi
  read -ra ov <<<"$overrides"
  read -r rc_ref t_ref c_ref < <(run "$REF" "$REF_THREADS" "$scene" "$OUT/ref/$scene" "${ov[@]}")
  read -r rc_new t_new c_new < <(run "$NEW" "$NEW_THREADS" "$scene" "$OUT/new/$scene" "${ov[@]}")
  cpu_all=$(echo "$cpu_all + $c_ref + $c_new" | bc)
  /usr/bin/python3 tools/compare_runs.py "$OUT/ref/$scene" "$OUT/new/$scene" ${COMPARE_ARGS:-} --json "$OUT/compare_$scene.json" \
      >"$OUT/compare_$scene.txt" 2>&1
  rc_cmp=$?
  read -r steps frames < <(/usr/bin/python3 -c "
import json, sys
try:
    r = next(iter(json.load(open(sys.argv[1])).values()))
    print(r.get('steps'), r.get('frames', 0))
except Exception:
    print('? 0')" "$OUT/compare_$scene.json")
  if [ "$rc_ref" != 0 ] || [ "$rc_new" != 0 ]; then
    verdict="RUN FAILED (exit REF $rc_ref, NEW $rc_new; see $OUT/{ref,new}/$scene.log)"
    status=1
  elif [ $rc_cmp = 0 ]; then
    verdict="identical"
  else
    verdict="DIFFERENT (see $OUT/compare_$scene.txt)"
    status=1
  fi
  rows+=("$(printf '%-18s %6s %7s %5.1f/%5.1f %5.1f/%5.1f  %s' "$scene" "$steps" "$frames" "$t_ref" "$c_ref" "$t_new" "$c_new" "$verdict")")
  echo "${rows[-1]}"
done
t_all=$(echo "$(date +%s.%N) - $t_all" | bc)

echo
printf '%-18s %6s %7s %11s %11s  %s\n' scene steps frames REF_wall/cpu NEW_wall/cpu verdict
for r in "${rows[@]}"; do echo "$r"; done
printf 'total: wall %.0f s (runs + comparisons), CPU %.0f s (runs of both binaries; %s)\n' "$t_all" "$cpu_all" "$(cut -d' ' -f1-3 /proc/loadavg | sed 's/^/load average /')"
for c in "${CASES[@]}"; do
  IFS='|' read -r scene _ _ <<<"$c"
  [ -n "${SCENES:-}" ] && [[ " $SCENES " != *" $scene "* ]] && continue
  if [ -f "$OUT/compare_$scene.txt" ] && ! grep -q "^ALL IDENTICAL" "$OUT/compare_$scene.txt"; then
    echo; echo "--- $scene"; head -n 20 "$OUT/compare_$scene.txt"
  fi
done
if [ $status = 0 ]; then echo "check_bitwise: ALL IDENTICAL"; else echo "check_bitwise: DIFFERENCES FOUND"; fi
exit $status
