// types.h - scalar, vector and matrix types shared by the whole engine.
//
// The floating-point type `Real` is chosen at configure time (CMake option CDMPM_SINGLE_PRECISION);
// double is the default. Spatial dimension is always a template parameter `dim` (2 or 3), so one code
// path serves 2D and 3D.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace cdmpm {

#ifdef CDMPM_SINGLE_PRECISION
using Real = float;
#else
using Real = double;
#endif

template <int dim>
using Vec = Eigen::Matrix<Real, dim, 1>;
template <int dim>
using Mat = Eigen::Matrix<Real, dim, dim>;
template <int dim>
using IVec = Eigen::Matrix<int, dim, 1>;

// The vertical axis is the last one (y in 2D, z in 3D); gravity normally points along -vertical.
template <int dim>
constexpr int vertical_axis = dim - 1;

}  // namespace cdmpm
