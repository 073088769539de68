// Every writer of an output file (EXR, PNG, text through writeFileAtomically) on a full disk: the write fails
// with an error naming the file, the previous file is kept byte for byte, and no temporary is left behind.
// A file-size limit (RLIMIT_FSIZE, with SIGXFSZ ignored) stands in for the full disk: writes past it fail
// with EFBIG, as they would with ENOSPC.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/image.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "raylab_atomic_output_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string bytesOf(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << file.rdbuf();
  return bytes.str();
}

// Files may grow to `bytes` while alive.
class DiskFull {
 public:
  explicit DiskFull(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &saved_);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~DiskFull() { setrlimit(RLIMIT_FSIZE, &saved_); }

 private:
  rlimit saved_{};
};

Image noise(std::uint32_t size) {
  Image image(size, size);
  std::uint32_t state = 1;
  for (float& value : image.rgba) {
    state = state * 1664525u + 1013904223u;
    value = float(state >> 8) / float(1u << 24);
  }
  return image;
}

void expectFailureKeepsOld(const fs::path& dir, const std::string& name, const std::function<void()>& write) {
  const fs::path target = dir / name;
  write();  // the good file
  const std::string before = bytesOf(target);
  ASSERT_GT(before.size(), 4096u) << "too small to be cut short by the limit";
  std::string message;
  {
    const DiskFull full(4096);
    try {
      write();
    } catch (const Error& error) {
      message = error.what();
    }
  }
  EXPECT_NE(message.find(target.string()), std::string::npos) << "no error naming the file: '" << message << "'";
  EXPECT_EQ(bytesOf(target), before) << name << ": the previous file was damaged";
  std::vector<std::string> left;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename());
  EXPECT_EQ(left, std::vector<std::string>{name}) << "a temporary was left behind";
}

TEST(AtomicOutput, ExrOnAFullDiskFailsAndKeepsTheOldFile) {
  const Image image = noise(64);
  const fs::path dir = freshDir("exr");
  expectFailureKeepsOld(dir, "frame.exr", [&] { writeExr((dir / "frame.exr").string(), image); });
}

TEST(AtomicOutput, PngOnAFullDiskFailsAndKeepsTheOldFile) {
  const Image image = noise(64);
  const fs::path dir = freshDir("png");
  expectFailureKeepsOld(dir, "frame.png", [&] { writePng((dir / "frame.png").string(), image, 0.0f, ToneMap::kClamp); });
}

TEST(AtomicOutput, TextOnAFullDiskFailsAndKeepsTheOldFile) {
  const fs::path dir = freshDir("text");
  const std::string text(100000, 'x');
  expectFailureKeepsOld(dir, "values.csv", [&] { writeFileAtomically((dir / "values.csv").string(), text); });
}

TEST(AtomicOutput, ARewrittenFileIsReplacedWholeAndKeepsOrdinaryPermissions) {
  const fs::path dir = freshDir("replace");
  const fs::path target = dir / "report.json";
  writeFileAtomically(target.string(), "first");
  writeFileAtomically(target.string(), "second, longer");
  EXPECT_EQ(bytesOf(target), "second, longer");
  const fs::perms perms = fs::status(target).permissions();
  EXPECT_NE(perms & fs::perms::others_read, fs::perms::none) << "mkstemp's private mode leaked into the output";
}

TEST(AtomicOutput, CheckOutputPathRefusesDevicesDirectoriesAndUnwritableFolders) {
  const fs::path dir = freshDir("check");
  // Missing directories are created below the working directory only (a typo must not create /nonexistent_dir).
  const fs::path here = fs::current_path();
  fs::current_path(dir);
  EXPECT_NO_THROW(checkOutputPath((dir / "new" / "deeper" / "x.exr").string(), "--out"));
  EXPECT_NO_THROW(checkOutputPath("relative/x.exr", "--out"));
  fs::current_path(here);
  EXPECT_TRUE(fs::is_directory(dir / "new" / "deeper") && fs::is_directory(dir / "relative"));
  EXPECT_THROW(checkOutputPath((dir / "elsewhere" / "x.exr").string(), "--out"), Error);
  EXPECT_FALSE(fs::exists(dir / "elsewhere"));
  for (const std::string& bad : {std::string("/dev/full"), dir.string(), std::string("/proc/raylab/x.exr")}) {
    try {
      checkOutputPath(bad, "--png");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("--png"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace raylab::test
