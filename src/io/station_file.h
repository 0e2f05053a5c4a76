// station_file.h - stations.nc: the water at every station of the scene's wave gauges and section probes as one
// CF discrete sampling geometry of featureType timeSeries (CF conventions 1.8, section 9 and appendix H.2.1, the
// orthogonal multidimensional array representation: every station sampled at the same times), the time series
// of probes.csv with each station's description:
//   station_name (cf_role timeseries_id), x [y] (domain coordinates), easting, northing (map, when the scene is
//   georeferenced: 2D along the transect's azimuth from the domain's origin), bed (geo: hazard/bed_height.h),
//   still_level; and per station and time eta, d, u [v], q [qx, qy] (probe/section.cpp; a wave gauge has eta
//   only, its other variables are the fill value).
// Written at the end of a run, by one process, from probes.csv (so a resumed run's file holds the whole run);
// its values are those of probes.csv.
#pragma once

#include <string>
#include <vector>

#include "probe/probe.h"

namespace cdmpm {

// Writes `path` if there is at least one station; `bed` holds the bed height under each station. Throws
// std::runtime_error if probes.csv lacks a column or the file cannot be written.
void write_station_file(const std::string& path, const std::string& probes_csv, const std::vector<Station>& stations,
                        const std::vector<double>& bed, const Scene& scene);

}  // namespace cdmpm
