// netcdf_file.h - a netCDF file written through the netCDF C library (Unidata, NetCDF Users Guide): dimensions,
// variables, attributes and values, every call checked (a failure throws std::runtime_error naming the file and
// what failed). Files are written in the classic 64-bit-offset format (CDF-2), which holds no time stamps, so the
// same values give the same bytes.
//
// A created file is written as NAME.part and renamed to NAME by close(), so a file that is cut short (an error,
// a killed run) never stands under its final name; a file opened for update is written in place.
#pragma once

#include <netcdf.h>

#include <string>
#include <vector>

namespace cdmpm {

class NetcdfFile {
 public:
  enum class Mode { Create, Update };
  NetcdfFile(const std::string& path, Mode mode);
  ~NetcdfFile();
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  // Definitions (a created file, before end_definitions).
  int dimension(const std::string& name, size_t length);
  int variable(const std::string& name, nc_type type, const std::vector<int>& dimensions);
  // Attributes of a variable, or of the file with NC_GLOBAL.
  void attribute(int var, const std::string& name, const std::string& text);
  void attribute(int var, const std::string& name, const std::vector<double>& values);
  void attribute(int var, const std::string& name, double value) { attribute(var, name, std::vector<double>{value}); }
  void end_definitions();

  // Values: a whole variable, or the hyperslab [start, start + count).
  void put(int var, const std::vector<double>& values);
  void put(int var, const std::vector<size_t>& start, const std::vector<size_t>& count, const std::vector<double>& values);
  // A character variable (strings, width) from strings padded with NUL.
  void put_strings(int var, const std::vector<std::string>& strings, size_t width);
  int find_variable(const std::string& name) const;
  // The `size` values of a whole variable.
  std::vector<double> get(int var, size_t size) const;

  // Closes the file (a created one renamed to its final name).
  void close();

 private:
  void check(int status, const std::string& what) const;
  std::string path_, written_;
  int id_ = -1;
  bool create_ = false;
};

}  // namespace cdmpm
