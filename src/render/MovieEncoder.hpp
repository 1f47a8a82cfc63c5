#pragma once
/// renderCase -movie: the frames as an MP4 (H.264) through ffmpeg, which PoroSPH does not install (it is optional).

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// The path of ffmpeg on PATH, or "" when it is not installed.
std::string findFfmpeg();

/// Encodes `frames` (PNG files of one size, in order) at `frameRate` into `movie` with `ffmpeg`: H.264, yuv420p
/// (plays everywhere; odd sizes are padded by a pixel). ffmpeg writes a temporary sibling that replaces `movie` only
/// when every frame was read and sent and ffmpeg exited with status 0; SIGPIPE is ignored meanwhile (an ffmpeg that
/// dies is reported, not fatal) and restored after. Throws OutputError naming the unreadable frame, the failed
/// write or ffmpeg's exit status and last words; `movie` then stays as it was.
void encodeMovie(const std::string& ffmpeg, const std::vector<std::filesystem::path>& frames, double frameRate,
                 const std::filesystem::path& movie);

} // namespace poro
