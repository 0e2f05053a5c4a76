// wave_report.h - the wave analysis of a run's gauges (probe/wave_analysis.h), written at the end of every run
// of a scene with wave gauges: waves.csv (gauge, x, amplitude, arrival_time: first crest per gauge, x the
// gauge's first horizontal coordinate) and the summary values "max_amplitude" (largest first-crest amplitude),
// "celerity" (least-squares leading-crest celerity over the gauges) and "celerity_pairs" (celerity between
// consecutive gauges along x). Reads the complete probes.csv, so a resumed run analyses its whole record.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace cdmpm {

// Returns the summary entries (empty object if the scene has no wave gauge). Throws std::runtime_error if
// probes_csv cannot be read or waves_csv cannot be written.
nlohmann::json wave_report(const Scene& scene, const std::string& probes_csv, const std::string& waves_csv);

}  // namespace cdmpm
