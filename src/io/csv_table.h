// csv_table.h - a comma-separated table with a header line (probes.csv, waves.csv) read back by column name, for
// the analyses that run on a run's outputs (probe/wave_report.cpp, validation/linear_wave_report.cpp).
#pragma once

#include <string>
#include <vector>

namespace cdmpm {

struct CsvTable {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // cells as written; a short row has empty cells at its end

  // The column's cells; throws std::runtime_error naming the file if there is no such column.
  std::vector<std::string> strings(const std::string& column) const;
  // The column as numbers; a cell that is empty or not a number ("nan") is NaN.
  std::vector<double> numbers(const std::string& column) const;
};

// Throws std::runtime_error if the file cannot be read or has no header line.
CsvTable read_csv_table(const std::string& path);

}  // namespace cdmpm
