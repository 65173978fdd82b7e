// Helpers shared by the tests that run `prism view` as a program: a scratch
// directory per test, running shell commands, and reading pictures with OIIO.
#pragma once

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace prism::test {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// A fresh directory named after the running test, removed afterwards.
class ScratchDir {
public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("prism_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

private:
  fs::path path_;
};

inline std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

struct RunResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs a shell command in `dir`, capturing its stdout and stderr.
inline RunResult run(const fs::path& dir, const std::string& command) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string line =
      "cd " + quoted(dir) + " && " + command + " >" + quoted(out) + " 2>" + quoted(err);
  const int status = std::system(line.c_str());
  RunResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

struct Picture {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<std::uint8_t> pixels; // interleaved, row 0 at the top
  const std::uint8_t* at(int x, int y) const {
    return &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels)];
  }
};

inline std::optional<Picture> readPicture(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return std::nullopt;
  const OIIO::ImageSpec& spec = in->spec();
  Picture p;
  p.width = spec.width;
  p.height = spec.height;
  p.channels = spec.nchannels;
  p.pixels.resize(std::size_t(p.width) * std::size_t(p.height) * std::size_t(p.channels));
  if (!in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::UINT8, p.pixels.data()))
    return std::nullopt;
  return p;
}

// True when a and b have the same size and equal RGB in every pixel.
inline bool sameRgb(const Picture& a, const Picture& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y)[c] != b.at(x, y)[c]) return false;
  return true;
}

// Where `small` appears pixel for pixel (RGB) inside `big`, if anywhere.
inline std::optional<std::pair<int, int>> findExact(const Picture& big, const Picture& small) {
  for (int oy = 0; oy + small.height <= big.height; ++oy) {
    for (int ox = 0; ox + small.width <= big.width; ++ox) {
      bool match = true;
      for (int y = 0; y < small.height && match; ++y)
        for (int x = 0; x < small.width && match; ++x)
          for (int c = 0; c < 3 && match; ++c)
            match = big.at(ox + x, oy + y)[c] == small.at(x, y)[c];
      if (match) return std::make_pair(ox, oy);
    }
  }
  return std::nullopt;
}

} // namespace prism::test
