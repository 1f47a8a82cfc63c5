#include "render/MovieEncoder.hpp"

#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "render/ExecutableSearch.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace poro {

namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// SIGPIPE ignored while it lives: an ffmpeg that dies early makes writes into its pipe fail with EPIPE, which is
/// reported, instead of killing renderCase without a word. The disposition before is restored.
class IgnoredSigpipe {
public:
  IgnoredSigpipe() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    restore_ = ::sigaction(SIGPIPE, &ignore, &previous_) == 0;
  }
  ~IgnoredSigpipe() {
    if (restore_) ::sigaction(SIGPIPE, &previous_, nullptr);
  }
  IgnoredSigpipe(const IgnoredSigpipe&) = delete;
  IgnoredSigpipe& operator=(const IgnoredSigpipe&) = delete;

private:
  struct sigaction previous_ {};
  bool restore_ = false;
};

/// The last non-empty line of ffmpeg's log, or "".
std::string lastLine(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string last, line;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

/// The whole file; throws OutputError naming the movie and the frame when it cannot be read or is empty (a frame
/// sent as nothing would leave a gap, or a broken stream, in the movie).
std::string readFrame(const std::filesystem::path& frame, const std::filesystem::path& movie) {
  std::ifstream in(frame, std::ios::binary);
  if (!in)
    throw OutputError(movie.string() + ": cannot read the frame " + frame.string() + " (" + std::strerror(errno) + ")");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad() || bytes.empty())
    throw OutputError(movie.string() + ": cannot read the frame " + frame.string() +
                      (bytes.empty() ? " (empty file)" : " (read error)"));
  return bytes;
}

} // namespace

std::string findFfmpeg() { return findOnPath("ffmpeg"); }

void encodeMovie(const std::string& ffmpeg, const std::vector<std::filesystem::path>& frames, double frameRate,
                 const std::filesystem::path& movie) {
  // The frames go through a pipe in order: their names are times, which no numbered pattern matches. ffmpeg writes
  // a temporary sibling (-f mp4: its name does not end in .mp4), renamed over the movie only when ffmpeg succeeded,
  // so a failure keeps the movie of an earlier run.
  const std::filesystem::path log = movie.parent_path() / "log.ffmpeg";
  const std::filesystem::path temporary = temporarySibling(movie);
  std::ostringstream command;
  command << quoted(ffmpeg) << " -y -loglevel error -f image2pipe -c:v png -framerate " << frameRate
          << " -i - -c:v libx264 -pix_fmt yuv420p -crf 20 -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -f mp4 "
          << quoted(temporary.string()) << " > " << quoted(log.string()) << " 2>&1";
  const auto removeTemporary = [&] {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  };
  const IgnoredSigpipe ignoredSigpipe;
  std::FILE* pipe = ::popen(command.str().c_str(), "w");
  if (!pipe) throw OutputError(movie.string() + ": cannot start " + ffmpeg + " (" + std::strerror(errno) + ")");
  std::string failure; // what went wrong on this side of the pipe
  for (const auto& frame : frames) {
    std::string bytes;
    try {
      bytes = readFrame(frame, movie);
    } catch (const OutputError& e) {
      failure = e.what();
      break;
    }
    if (std::fwrite(bytes.data(), 1, bytes.size(), pipe) != bytes.size()) {
      failure = movie.string() + ": cannot send the frame " + frame.string() + " to ffmpeg (" + std::strerror(errno) +
                ")";
      break;
    }
  }
  if (failure.empty() && std::fflush(pipe) != 0)
    failure = movie.string() + ": cannot send the frames to ffmpeg (" + std::strerror(errno) + ")";
  const int status = ::pclose(pipe); // closes ffmpeg's input: it finishes the file, or stops, and exits
  const bool ffmpegOk = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!failure.empty() || !ffmpegOk) {
    removeTemporary();
    const std::string words = lastLine(log);
    std::ostringstream how;
    if (status == -1) how << "its exit status is unknown (" << std::strerror(errno) << ")";
    else if (WIFEXITED(status)) how << "exit status " << WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) how << "killed by signal " << WTERMSIG(status);
    const std::string ffmpegSays = "ffmpeg failed (" + how.str() + ")" +
                                   (words.empty() ? std::string() : ": " + words) + " (see " + log.string() + ")";
    if (failure.empty()) failure = movie.string() + ": " + ffmpegSays;
    else if (!ffmpegOk) failure += "; " + ffmpegSays;
    throw OutputError(failure + "; an earlier movie is kept");
  }
  commitTemporaryFile(temporary, movie);
  std::error_code ignored;
  std::filesystem::remove(log, ignored);
}

} // namespace poro
