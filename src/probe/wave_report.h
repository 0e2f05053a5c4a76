// wave_report.h - the wave analysis of a run's gauges (probe/wave_analysis.h), written at the end of every run
// of a scene with wave gauges: waves.csv (gauge, x, amplitude, arrival_time: the first crest per gauge, x the
// gauge's first horizontal coordinate; earliest_arrival, the earliest time a wave can reach the gauge, and
// noise_floor, the elevation its crest must exceed (probe/wave_bounds.h); reason: empty for a crest, else
// "not arrived: ..." with amplitude and arrival_time empty) and the summary values "max_amplitude" (largest
// first-crest amplitude), "celerity" (least-squares leading-crest celerity over the gauges with a crest),
// "celerity_pairs" (celerity between consecutive gauges along x with a crest) and "wave_bounds". A celerity
// outside (0, 2 sqrt(g h_max)] is no wave's: it is null, with the reason. Reads the complete probes.csv, so a
// resumed run analyses its whole record.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace cdmpm {

// Returns the summary entries (empty object if the scene has no wave gauge). Throws std::runtime_error if
// probes_csv cannot be read or waves_csv cannot be written.
nlohmann::json wave_report(const Scene& scene, const std::string& probes_csv, const std::string& waves_csv);

}  // namespace cdmpm
