// process_memory.h - the process's resident memory, for bytes-per-particle figures (Linux /proc).
//
// peak_rss_bytes: the peak resident set size (VmHWM), grid, buffers and process baseline included.
// reset_peak_rss: restarts the peak at the current resident size (writing 5 to /proc/self/clear_refs), so a
// benchmark case measures its own peak. Both are no-ops returning 0 where /proc is unavailable.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

namespace cdmpm {

inline void reset_peak_rss() {
  std::ofstream f("/proc/self/clear_refs");
  if (f) f << "5";
}

inline double peak_rss_bytes() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) * 1024.0;  // reported in kB
  return 0;
}

}  // namespace cdmpm
