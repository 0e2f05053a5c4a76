// csv_table.cpp - reading a CSV table by column (see csv_table.h).
#include "io/csv_table.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cdmpm {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ls(line);
  for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
  return cells;
}

}  // namespace

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) throw std::runtime_error(path + ": cannot read");
  CsvTable t;
  t.path = path;
  t.header = split(line);
  while (std::getline(in, line)) t.rows.push_back(split(line));
  return t;
}

std::vector<std::string> CsvTable::strings(const std::string& column) const {
  const auto it = std::find(header.begin(), header.end(), column);
  if (it == header.end()) throw std::runtime_error(path + ": no column " + column);
  const size_t i = it - header.begin();
  std::vector<std::string> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(i < r.size() ? r[i] : std::string());
  return out;
}

std::vector<double> CsvTable::numbers(const std::string& column) const {
  std::vector<double> out;
  for (const std::string& c : strings(column)) {
    double v = std::numeric_limits<double>::quiet_NaN();
    try {
      v = std::stod(c);
    } catch (const std::exception&) {
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace cdmpm
