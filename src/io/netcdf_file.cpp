// netcdf_file.cpp - netCDF files through the C library (netcdf_file.h).
#include "io/netcdf_file.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace cdmpm {

NetcdfFile::NetcdfFile(const std::string& path, Mode mode)
    : path_(path), written_(mode == Mode::Create ? path + ".part" : path), create_(mode == Mode::Create) {
  if (create_) check(nc_create(written_.c_str(), NC_CLOBBER | NC_64BIT_OFFSET, &id_), "cannot create");
  else check(nc_open(written_.c_str(), NC_WRITE, &id_), "cannot open for writing");
}

NetcdfFile::~NetcdfFile() {
  if (id_ < 0) return;
  nc_close(id_);
  if (create_) std::remove(written_.c_str());  // not closed: an error left it unfinished
}

void NetcdfFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR) throw std::runtime_error(written_ + ": netCDF: " + what + ": " + nc_strerror(status));
}

int NetcdfFile::dimension(const std::string& name, size_t length) {
  int d = -1;
  check(nc_def_dim(id_, name.c_str(), length, &d), "dimension " + name);
  return d;
}

int NetcdfFile::variable(const std::string& name, nc_type type, const std::vector<int>& dimensions) {
  int v = -1;
  check(nc_def_var(id_, name.c_str(), type, static_cast<int>(dimensions.size()), dimensions.data(), &v), "variable " + name);
  return v;
}

void NetcdfFile::attribute(int var, const std::string& name, const std::string& text) {
  check(nc_put_att_text(id_, var, name.c_str(), text.size(), text.c_str()), "attribute " + name);
}

void NetcdfFile::attribute(int var, const std::string& name, const std::vector<double>& values) {
  check(nc_put_att_double(id_, var, name.c_str(), NC_DOUBLE, values.size(), values.data()), "attribute " + name);
}

void NetcdfFile::end_definitions() { check(nc_enddef(id_), "end of definitions"); }

void NetcdfFile::put(int var, const std::vector<double>& values) {
  check(nc_put_var_double(id_, var, values.data()), "values of variable " + std::to_string(var));
}

void NetcdfFile::put(int var, const std::vector<size_t>& start, const std::vector<size_t>& count,
                     const std::vector<double>& values) {
  check(nc_put_vara_double(id_, var, start.data(), count.data(), values.data()), "values of variable " + std::to_string(var));
}

void NetcdfFile::put_strings(int var, const std::vector<std::string>& strings, size_t width) {
  std::vector<char> chars(strings.size() * width, '\0');
  for (size_t i = 0; i < strings.size(); ++i) strings[i].copy(&chars[i * width], std::min(width, strings[i].size()));
  check(nc_put_var_text(id_, var, chars.data()), "strings of variable " + std::to_string(var));
}

int NetcdfFile::find_variable(const std::string& name) const {
  int v = -1;
  check(nc_inq_varid(id_, name.c_str(), &v), "variable " + name);
  return v;
}

std::vector<double> NetcdfFile::get(int var, size_t size) const {
  size_t total = 1;
  int ndims = 0;
  check(nc_inq_varndims(id_, var, &ndims), "dimensions of variable " + std::to_string(var));
  std::vector<int> dims(static_cast<size_t>(ndims));
  check(nc_inq_vardimid(id_, var, dims.data()), "dimensions of variable " + std::to_string(var));
  for (int d : dims) {
    size_t n = 0;
    check(nc_inq_dimlen(id_, d, &n), "dimension length");
    total *= n;
  }
  if (total != size)
    throw std::runtime_error(written_ + ": variable " + std::to_string(var) + " holds " + std::to_string(total) +
                             " values, expected " + std::to_string(size));
  std::vector<double> v(size);
  check(nc_get_var_double(id_, var, v.data()), "values of variable " + std::to_string(var));
  return v;
}

void NetcdfFile::close() {
  check(nc_close(id_), "cannot close");
  id_ = -1;
  if (!create_) return;
  std::error_code ec;
  std::filesystem::rename(written_, path_, ec);
  if (ec) throw std::runtime_error(written_ + ": cannot rename to " + path_ + ": " + ec.message());
}

}  // namespace cdmpm
