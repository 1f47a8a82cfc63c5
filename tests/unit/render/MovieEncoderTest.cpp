// renderCase -movie's encoder against stand-ins for ffmpeg (shell scripts): what it does when ffmpeg dies, fails or
// a frame is missing (render/MovieEncoder.hpp).

#include "render/MovieEncoder.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

namespace poro {
namespace {

namespace fs = std::filesystem;

class MovieEncoder : public ::testing::Test {
protected:
  MovieEncoder() {
    dir_ = fs::temp_directory_path() / ("porosph-movie-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write("movie.mp4", "old movie");
  }
  ~MovieEncoder() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  /// A stand-in for ffmpeg: a shell script with `body`, in which $out is its last argument (the output file).
  std::string fakeFfmpeg(const std::string& body) const {
    const fs::path script = dir_ / "ffmpeg";
    write("ffmpeg", "#!/bin/sh\nfor out; do :; done\n" + body + "\n");
    fs::permissions(script, fs::perms::owner_all);
    return script.string();
  }
  std::vector<fs::path> frames(std::size_t bytes) const {
    write("0.png", std::string(bytes, 'a'));
    write("1.png", std::string(bytes, 'b'));
    return {dir_ / "0.png", dir_ / "1.png"};
  }
  /// The entries of the directory other than the script, the frames and the movie: temporaries left behind.
  std::vector<std::string> leftOver() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (name != "ffmpeg" && name != "0.png" && name != "1.png" && name != "movie.mp4" && name != "log.ffmpeg")
        names.push_back(name);
    }
    return names;
  }
  /// The message of the OutputError `f` throws; a test failure if it throws nothing.
  template <class F> static std::string errorOf(F&& f) {
    try {
      f();
    } catch (const OutputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no OutputError";
    return "";
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(MovieEncoder, ASuccessfulEncodeReplacesTheMovie) {
  const std::string ffmpeg = fakeFfmpeg("cat > \"$out\"");
  encodeMovie(ffmpeg, frames(10), 10.0, dir_ / "movie.mp4");
  EXPECT_EQ(read("movie.mp4"), std::string(10, 'a') + std::string(10, 'b'));
  EXPECT_FALSE(fs::exists(dir_ / "log.ffmpeg"));
  EXPECT_TRUE(leftOver().empty());
}

TEST_F(MovieEncoder, AnFfmpegThatDiesIsReportedNotFatal) {
  // It exits before reading: the frames (larger than a pipe's buffer) cannot be written, which would raise SIGPIPE.
  const std::string ffmpeg = fakeFfmpeg("echo 'Unknown encoder libx264' >&2\nexit 1");
  struct sigaction before {};
  ::sigaction(SIGPIPE, nullptr, &before);
  const std::string message = errorOf([&] { encodeMovie(ffmpeg, frames(1 << 20), 10.0, dir_ / "movie.mp4"); });
  EXPECT_TRUE(contains(message, "cannot send the frame")) << message;
  EXPECT_TRUE(contains(message, "exit status 1")) << message;
  EXPECT_TRUE(contains(message, "Unknown encoder libx264")) << message;
  EXPECT_EQ(read("movie.mp4"), "old movie");
  EXPECT_TRUE(leftOver().empty());
  struct sigaction after {};
  ::sigaction(SIGPIPE, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler) << "SIGPIPE is restored";
}

TEST_F(MovieEncoder, AFailedEncodeKeepsTheOldMovie) {
  const std::string ffmpeg = fakeFfmpeg("cat > /dev/null\necho partial > \"$out\"\necho 'disk full' >&2\nexit 1");
  const std::string message = errorOf([&] { encodeMovie(ffmpeg, frames(10), 10.0, dir_ / "movie.mp4"); });
  EXPECT_TRUE(contains(message, "exit status 1")) << message;
  EXPECT_TRUE(contains(message, "disk full")) << message;
  EXPECT_EQ(read("movie.mp4"), "old movie");
  EXPECT_TRUE(leftOver().empty());
}

TEST_F(MovieEncoder, AMissingFrameIsAnErrorNamingIt) {
  const std::string ffmpeg = fakeFfmpeg("cat > \"$out\"");
  std::vector<fs::path> list = frames(10);
  list.insert(list.begin() + 1, dir_ / "0.5.png");
  const std::string message = errorOf([&] { encodeMovie(ffmpeg, list, 10.0, dir_ / "movie.mp4"); });
  EXPECT_TRUE(contains(message, "cannot read the frame " + (dir_ / "0.5.png").string())) << message;
  EXPECT_EQ(read("movie.mp4"), "old movie");
  EXPECT_TRUE(leftOver().empty());
}

TEST_F(MovieEncoder, AnFfmpegKilledBySignalIsAFailure) {
  const std::string ffmpeg = fakeFfmpeg("cat > \"$out\"\nkill -9 $$");
  const std::string message = errorOf([&] { encodeMovie(ffmpeg, frames(10), 10.0, dir_ / "movie.mp4"); });
  EXPECT_TRUE(contains(message, "ffmpeg failed")) << message;
  EXPECT_EQ(read("movie.mp4"), "old movie");
  EXPECT_TRUE(leftOver().empty());
}

} // namespace
} // namespace poro
