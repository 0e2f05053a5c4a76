#!/usr/bin/python3
"""cf_rules.py - the rules of the CF metadata conventions 1.8 (cfconventions.org) that cdmpm's netCDF outputs
implement, checked on a file (Debian has no CF checker):

    /usr/bin/python3 tests/tools/cf_rules.py FILE.nc ...     (prints each violation; exit status 1 if any)

  2.6.2  the global attribute Conventions is "CF-1.8";
  3.1    every numeric variable except the grid mapping has units, valid UDUNITS strings of the set cdmpm writes
         (m, s, m s-1, m2 s-1, "seconds since YYYY-MM-DD hh:mm:ss");
  3.2    every variable has a long_name;
  3.3    a standard_name is one of the CF standard name table and its units are that name's canonical units;
  2.5.1  _FillValue has the variable's type; coordinate variables hold no fill values;
  4.4    the time coordinate's units are "seconds since" a reference date and time;
  5      a coordinate variable (one dimension, named as it) is strictly monotonic; every name in a coordinates
         attribute is a variable whose dimensions (but a string's length) are among the data variable's;
  5.6    a grid_mapping attribute names a variable with crs_wkt and, for a projection CF names, its
         grid_mapping_name (appendix F) and that mapping's parameters;
  7.3    cell_methods is "name: method" with a dimension or standard name and a CF method;
  9      a file with featureType timeSeries has exactly one variable with cf_role timeseries_id, a time coordinate,
         and every data variable dimensioned (station) or (station, time) (appendix H.2.1, orthogonal arrays).
"""
import re
import sys

import numpy as np
from netCDF4 import Dataset

# CF standard name table (version 84): the names cdmpm uses and their canonical units.
STANDARD_NAMES = {
    "time": "s",
    "projection_x_coordinate": "m",
    "projection_y_coordinate": "m",
    "sea_surface_height_above_mean_sea_level": "m",
    "sea_floor_depth_below_sea_surface": "m",
    "barotropic_sea_water_x_velocity": "m s-1",
    "barotropic_sea_water_y_velocity": "m s-1",
}
UNITS = {"m", "s", "m s-1", "m2 s-1"}
TIME_UNITS = re.compile(r"^seconds since \d{4}-\d{2}-\d{2} \d{2}:\d{2}:\d{2}$")
# Appendix F: the grid mappings cdmpm writes and their required parameters.
GRID_MAPPINGS = {
    "transverse_mercator": ["scale_factor_at_central_meridian", "longitude_of_central_meridian",
                            "latitude_of_projection_origin", "false_easting", "false_northing"],
    "polar_stereographic": ["straight_vertical_longitude_from_pole", "latitude_of_projection_origin",
                            "false_easting", "false_northing"],
    "lambert_conformal_conic": ["standard_parallel", "longitude_of_central_meridian", "latitude_of_projection_origin",
                                "false_easting", "false_northing"],
}
METHODS = {"point", "sum", "maximum", "median", "mid_range", "minimum", "mean", "mode", "range", "standard_deviation",
           "variance"}


def violations(path):
    """The list of rule violations of a file, each "FILE: VARIABLE: rule: what"."""
    out = []
    with Dataset(path) as ds:
        def bad(var, rule, what):
            out.append(f"{path}: {var}: {rule}: {what}")

        if getattr(ds, "Conventions", None) != "CF-1.8":
            bad("(global)", "2.6.2", f"Conventions is {getattr(ds, 'Conventions', None)!r}, expected 'CF-1.8'")
        mappings = {v for v in ds.variables.values() if hasattr(v, "crs_wkt") or hasattr(v, "grid_mapping_name")}
        for name, v in ds.variables.items():
            attrs = v.ncattrs()
            if "long_name" not in attrs:
                bad(name, "3.2", "no long_name")
            if v in mappings:
                continue
            if v.dtype.kind == "f" or v.dtype.kind == "i":
                units = getattr(v, "units", None)
                if units is None:
                    bad(name, "3.1", "no units")
                elif units not in UNITS and not TIME_UNITS.match(units):
                    bad(name, "3.1", f"units {units!r} not a UDUNITS string of the expected set")
            if "_FillValue" in attrs and np.asarray(v.getncattr("_FillValue")).dtype != v.dtype:
                bad(name, "2.5.1", "_FillValue of another type than the variable")
            std = getattr(v, "standard_name", None)
            if std is not None:
                if std not in STANDARD_NAMES:
                    bad(name, "3.3", f"standard_name {std!r} not in the CF standard name table")
                else:
                    units = getattr(v, "units", "")
                    canonical = STANDARD_NAMES[std]
                    if not (units == canonical or (canonical == "s" and TIME_UNITS.match(units))):
                        bad(name, "3.3", f"units {units!r} not those of {std} ({canonical})")
            if std == "time" or name == "time":
                if not TIME_UNITS.match(getattr(v, "units", "")):
                    bad(name, "4.4", "time units not 'seconds since YYYY-MM-DD hh:mm:ss'")
            if v.dimensions == (name,):  # a coordinate variable
                values = np.asarray(v[:], dtype=float)
                if np.ma.is_masked(v[:]) or np.isnan(values).any():
                    bad(name, "2.5.1", "a coordinate variable holds fill values")
                d = np.diff(values)
                if len(values) > 1 and not (np.all(d > 0) or np.all(d < 0)):
                    bad(name, "5", "coordinate variable not strictly monotonic")
            for c in getattr(v, "coordinates", "").split():
                if c not in ds.variables:
                    bad(name, "5", f"coordinates names {c!r}, not a variable")
                    continue
                dims = ds.variables[c].dimensions
                if ds.variables[c].dtype.kind == "S":  # a string-valued one: its last dimension is the string length
                    dims = dims[:-1]
                if not set(dims) <= set(v.dimensions):
                    bad(name, "5", f"coordinate {c!r} has dimensions {dims} outside {v.dimensions}")
            gm = getattr(v, "grid_mapping", None)
            if gm is not None:
                if gm not in ds.variables:
                    bad(name, "5.6", f"grid_mapping names {gm!r}, not a variable")
                else:
                    m = ds.variables[gm]
                    if not hasattr(m, "crs_wkt"):
                        bad(gm, "5.6", "grid mapping without crs_wkt")
                    mapping = getattr(m, "grid_mapping_name", None)
                    if mapping is not None:
                        for p in GRID_MAPPINGS.get(mapping, []):
                            if not hasattr(m, p):
                                bad(gm, "5.6", f"{mapping} without {p}")
            cm = getattr(v, "cell_methods", None)
            if cm is not None:
                match = re.fullmatch(r"(\w+): (\w+)", cm)
                if not match or match.group(2) not in METHODS or (
                        match.group(1) not in v.dimensions and match.group(1) not in STANDARD_NAMES):
                    bad(name, "7.3", f"cell_methods {cm!r}")
        if getattr(ds, "featureType", None) == "timeSeries":
            ids = [n for n, v in ds.variables.items() if getattr(v, "cf_role", None) == "timeseries_id"]
            if len(ids) != 1:
                bad("(global)", "9.5", f"{len(ids)} variables with cf_role timeseries_id, expected 1")
            if "time" not in ds.variables:
                bad("(global)", "9.1", "no time coordinate")
            station = ds.variables[ids[0]].dimensions[0] if ids else None
            for name, v in ds.variables.items():
                if v in mappings or name == "time" or (ids and name == ids[0]):
                    continue
                if v.dimensions not in ((station,), (station, "time")):
                    bad(name, "9.3.1", f"dimensions {v.dimensions}, expected ({station},) or ({station}, time)")
    return out


def main():
    found = []
    for path in sys.argv[1:]:
        found += violations(path)
    for line in found:
        print(line)
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
