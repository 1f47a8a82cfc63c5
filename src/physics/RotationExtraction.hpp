#pragma once
/// Rotation part of a deformation gradient by the iterative method of Müller et al. 2016 ("A Robust Method to
/// Extract the Rotational Part of Deformations", METHOD.md §6.5.2): warm-started from the previous rotation,
/// omega = sum_c (R_c x F_c) / (|sum_c R_c . F_c| + 1e-9) over the columns c, R <- exp(omega) R as a unit
/// quaternion, until |omega| < 1e-9 or 10 iterations. Robust for inverted and degenerate F (no SVD). Near the
/// maximum of tr(R^T F) the step is the Newton step on the same function (same fixed point, quadratic rather
/// than linear convergence; RotationExtraction.cpp).

#include "core/Types.hpp"

namespace poro {

/// Returns the rotation of `f`, starting from `previous` (a rotation matrix).
Mat3 extractRotation(const Mat3& f, const Mat3& previous);

} // namespace poro
