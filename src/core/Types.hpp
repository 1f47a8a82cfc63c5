#pragma once
/// Scalar, vector and index types shared by every PoroSPH library (METHOD.md §1: double precision throughout).

#include <Eigen/Core>
#include <cstdint>

namespace poro {

using Real = double;
using Vec3 = Eigen::Matrix<double, 3, 1, Eigen::DontAlign>;
using Mat3 = Eigen::Matrix<double, 3, 3, Eigen::DontAlign>;
/// Particle index inside one particle set; 32 bits halve the memory traffic of neighbour lists.
using Index = std::int32_t;

} // namespace poro
