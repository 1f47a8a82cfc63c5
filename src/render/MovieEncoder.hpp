#pragma once
/// renderCase -movie: the frames as an MP4 (H.264) through ffmpeg, which PoroSPH does not install (it is optional).

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// The path of ffmpeg on PATH, or "" when it is not installed.
std::string findFfmpeg();

/// Encodes `frames` (PNG files of one size, in order) at `frameRate` into `movie` with `ffmpeg`: H.264, yuv420p
/// (plays everywhere; odd sizes are padded by a pixel). Throws OutputError with ffmpeg's last words if it fails.
void encodeMovie(const std::string& ffmpeg, const std::vector<std::filesystem::path>& frames, double frameRate,
                 const std::filesystem::path& movie);

} // namespace poro
