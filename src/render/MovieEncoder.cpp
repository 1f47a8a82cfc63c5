#include "render/MovieEncoder.hpp"

#include "core/Error.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace poro {

namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

} // namespace

std::string findFfmpeg() {
  const char* path = std::getenv("PATH");
  std::stringstream list(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(list, dir, ':');) {
    const std::string candidate = (std::filesystem::path(dir) / "ffmpeg").string();
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

void encodeMovie(const std::string& ffmpeg, const std::vector<std::filesystem::path>& frames, double frameRate,
                 const std::filesystem::path& movie) {
  // The frames go through a pipe in order: their names are times, which no numbered pattern matches.
  const std::filesystem::path log = movie.parent_path() / "log.ffmpeg";
  std::ostringstream command;
  command << quoted(ffmpeg) << " -y -loglevel error -f image2pipe -c:v png -framerate " << frameRate
          << " -i - -c:v libx264 -pix_fmt yuv420p -crf 20 -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' "
          << quoted(movie.string()) << " > " << quoted(log.string()) << " 2>&1";
  std::FILE* pipe = ::popen(command.str().c_str(), "w");
  if (!pipe) throw OutputError(movie.string() + ": cannot start " + ffmpeg);
  for (const auto& frame : frames) {
    std::ifstream in(frame, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (std::fwrite(bytes.data(), 1, bytes.size(), pipe) != bytes.size()) break;
  }
  const int status = ::pclose(pipe);
  if (status != 0) {
    std::ifstream in(log);
    std::string last, line;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    throw OutputError(movie.string() + ": ffmpeg failed" + (last.empty() ? std::string() : ": " + last) + " (see " +
                      log.string() + ")");
  }
  std::filesystem::remove(log);
}

} // namespace poro
