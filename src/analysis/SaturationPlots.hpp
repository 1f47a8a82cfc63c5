#pragma once
/// The plots of saturationAnalysis, as SVG line charts over time (per object, one colour per object) and
/// saturation profiles at a few times.

#include "analysis/SaturationAnalysis.hpp"
#include "analysis/SvgLinePlot.hpp"

#include <string>
#include <utility>
#include <vector>

namespace poro {

/// (file name, plot): with porous objects absorbedVolume.svg (absorbed volume and pore volume phi V per
/// object), fillFraction.svg (fraction filled and mean saturation), wetFront.svg (wetMin, wetMax); always
/// densityError.svg (mean and max), energy.svg (kinetic, potential change and their sum) and fluidExtent.svg
/// (lowest and highest fluid particle along the axis); per object with saturation data
/// saturationProfiles_<object>.svg.
std::vector<std::pair<std::string, SvgLinePlot>> saturationPlots(const std::vector<TimeRecord>& records,
                                                                 const AnalysisSettings& settings);

/// Indices of the records whose profile of `objectId` a profile plot shows: those with a profile, at most six,
/// evenly spread and always including the first and the latest.
std::vector<std::size_t> profileTimes(const std::vector<TimeRecord>& records, std::int64_t objectId);

} // namespace poro
