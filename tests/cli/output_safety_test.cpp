// Outputs are never lost and never half-written: an unwritable place or two renders racing for one file
// leave the old file or a complete new one, and a render is refused before it starts when its outputs
// cannot be written or its size is beyond what the device can hold. (A full disk is tested on the writers
// themselves, tests/cpu/atomic_output_test.cpp: lavapipe's device memory is a file too, and a file-size
// limit on the whole process would stop the device first.)
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/image.h"
#include "support/run_command.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

std::string freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "raylab_output_safety_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string fileBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << file.rdbuf();
  return bytes.str();
}

std::string shellQuote(const std::string& word) { return "'" + word + "'"; }

std::vector<std::string> smallRender(const std::string& exr, const std::string& png, const std::string& seed = "0") {
  return {"render", "--width", "48", "--height", "32", "--spp", "2", "--seed", seed, "--out", exr, "--png", png};
}

std::string shellLine(const std::vector<std::string>& args) {
  std::string line = shellQuote(RAYLAB_BINARY);
  for (const std::string& arg : args) line += " " + shellQuote(arg);
  return line;
}

TEST(OutputSafety, DevicesAndDirectoriesAreRefusedAsOutputsBeforeRendering) {
  const std::string dir = freshDir("special");
  for (const auto& [option, path] : std::vector<std::pair<std::string, std::string>>{
           {"--png", "/dev/full"}, {"--out", "/dev/zero"}, {"--png", dir}}) {
    std::vector<std::string> args = {"render", "--width", "8", "--height", "8", "--spp", "1", "--out",
                                     dir + "/a.exr", "--png", dir + "/a.png"};
    const std::size_t at = option == "--out" ? 8 : 10;
    args[at] = path;
    if (option == "--png" && path == dir) args[at] = dir + "/";  // a directory given where a file belongs
    const CommandResult result = runRaylab(args);
    EXPECT_NE(result.exitCode, 0) << path << ": " << result.output;
    EXPECT_EQ(result.output.find("first sample"), std::string::npos) << "rendered before refusing: " << result.output;
  }
  const CommandResult full = runRaylab({"render", "--width", "8", "--height", "8", "--png", "/dev/full"});
  EXPECT_EQ(full.exitCode, 2) << full.output;  // not a .png name
  EXPECT_TRUE(fs::is_character_file("/dev/full")) << "/dev/full was replaced";
}

TEST(OutputSafety, AnUnwritableDirectoryIsReportedBeforeTheSceneLoads) {
  const CommandResult result = runRaylab({"render", "--width", "8", "--height", "8", "--spp", "1", "--out",
                                          "/proc/raylab-cannot-write-here/x.exr"});
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("--out"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("/proc/raylab-cannot-write-here"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("scene:"), std::string::npos) << "the render ran first: " << result.output;

  // The default out/ folder, where a file named "out" is in the way.
  const std::string dir = freshDir("default_out");
  std::ofstream(dir + "/out") << "not a folder";
  const CommandResult blocked =
      runCommand({"/bin/sh", "-c", "cd " + shellQuote(dir) + " && exec " + shellLine({"render", "--spp", "1"})});
  EXPECT_EQ(blocked.exitCode, 1) << blocked.output;
  EXPECT_NE(blocked.output.find("out/showcase.exr"), std::string::npos) << blocked.output;
  EXPECT_EQ(blocked.output.find("first sample"), std::string::npos) << blocked.output;
}

TEST(OutputSafety, OutAndPngHaveIndependentDefaults) {
  const std::string dir = freshDir("defaults");
  const CommandResult result = runCommand(
      {"/bin/sh", "-c",
       "cd " + shellQuote(dir) + " && exec " +
           shellLine({"render", "--width", "16", "--height", "16", "--spp", "1", "--out", "mine.exr"})});
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(fs::exists(dir + "/mine.exr"));
  EXPECT_TRUE(fs::exists(dir + "/out/showcase.png")) << "--out suppressed the default PNG";
  EXPECT_FALSE(fs::exists(dir + "/out/showcase.exr"));

  const CommandResult none = runRaylab({"render", "--no-exr", "--no-png"});
  EXPECT_EQ(none.exitCode, 2) << none.output;
}

// Two renders of different seeds racing for one file: the file is one of them, whole, never a mix.
TEST(OutputSafety, ConcurrentRendersLeaveOneCompleteFile) {
  const std::string dir = freshDir("concurrent");
  const std::string a = dir + "/a.exr", b = dir + "/b.exr", shared = dir + "/shared.exr";
  ASSERT_EQ(runRaylab(smallRender(a, dir + "/a.png", "1")).exitCode, 0);
  ASSERT_EQ(runRaylab(smallRender(b, dir + "/b.png", "2")).exitCode, 0);
  const std::string race = shellLine(smallRender(shared, dir + "/s1.png", "1")) + " & " +
                           shellLine(smallRender(shared, dir + "/s2.png", "2")) + " & wait";
  const CommandResult result = runCommand({"/bin/sh", "-c", race});
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string bytes = fileBytes(shared);
  EXPECT_TRUE(bytes == fileBytes(a) || bytes == fileBytes(b)) << "the shared file equals neither render";
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

// lavapipe's maxStorageBufferRange is 128 MiB: 8,388,608 pixels of the float4 accumulation buffer. Beyond
// that (and at 2^27 pixels, where the kernel used to crash) the render is refused, naming the limit.
TEST(OutputSafety, ImagesBeyondTheDeviceLimitAreRefusedNamingTheLimit) {
  const std::string dir = freshDir("huge");
  for (const auto& [width, height] : std::vector<std::pair<std::string, std::string>>{{"3000", "3000"},
                                                                                      {"11586", "11586"}}) {
    const CommandResult result = runRaylab(
        {"render", "--width", width, "--height", height, "--spp", "1", "--out", dir + "/h.exr", "--no-png"});
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("maxStorageBufferRange"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--width/--height"), std::string::npos) << result.output;
  }
  EXPECT_FALSE(fs::exists(dir + "/h.exr"));
}

// Two outputs of one command on one file: refused before work, naming both options; nothing is written. The
// heat map used to overwrite the render's own default outputs.
TEST(OutputSafety, OutputsThatNameOneFileTwiceAreRefusedBeforeWork) {
  const std::string dir = freshDir("twice");
  const std::vector<std::vector<std::string>> cases = {
      {"--heatmap", "out/minimal.png"},  // its PNG is the default --png, its EXR the default --out
      {"--out", dir + "/a.exr", "--png", dir + "/a.png", "--heatmap", dir + "/a.png"},
      {"--out", dir + "/a.exr", "--png", dir + "/b.png", "--heatmap", dir + "/a.png"},  // heat map's EXR is --out
      {"--out", dir + "/a.exr", "--png", dir + "/b.png", "--heatmap", dir + "/../twice/./a.png"},
  };
  for (const std::vector<std::string>& outputs : cases) {
    std::vector<std::string> args = {"render", RAYLAB_SOURCE_DIR "/assets/scenes/minimal.gltf", "--width", "8",
                                     "--height", "8", "--spp", "1"};
    args.insert(args.end(), outputs.begin(), outputs.end());
    const CommandResult result = runRaylab(args, {}, dir);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("would both write"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("first sample"), std::string::npos) << "rendered before refusing: " << result.output;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "a refused command wrote something";
}

// A typo'd directory is not created: only directories below the working directory are.
TEST(OutputSafety, MissingDirectoriesOutsideTheWorkingDirectoryAreNotCreated) {
  const std::string dir = freshDir("directories");
  const std::string outside = fs::temp_directory_path() / "raylab_output_safety_test" / "no_such_dir";
  fs::remove_all(outside);
  const CommandResult refused = runRaylab(
      {"render", "--width", "8", "--height", "8", "--spp", "1", "--out", outside + "/x.exr", "--no-png"}, {}, dir);
  EXPECT_EQ(refused.exitCode, 1) << refused.output;
  EXPECT_NE(refused.output.find("does not exist"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(outside));
  const CommandResult root = runRaylab({"render", "--width", "8", "--height", "8", "--png", "/nonexistent_dir/x.png",
                                        "--no-exr"}, {}, dir);
  EXPECT_EQ(root.exitCode, 1) << root.output;
  EXPECT_FALSE(fs::exists("/nonexistent_dir"));
  const CommandResult below = runRaylab(
      {"render", "--width", "8", "--height", "8", "--spp", "1", "--out", "results/run1/x.exr", "--no-png"}, {}, dir);
  EXPECT_EQ(below.exitCode, 0) << below.output;
  EXPECT_TRUE(fs::exists(dir + "/results/run1/x.exr"));
}

// Every input file goes through one reader: a FIFO, /dev/zero and a directory are refused at once (they used to
// hang, grow without bound, or be taken as an empty script).
TEST(OutputSafety, SpecialFilesAreRefusedAsInputsWithoutHanging) {
  const std::string dir = freshDir("inputs");
  const std::string fifo = dir + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& input : {fifo, std::string("/dev/zero"), dir}) {
    const std::string expected = input == dir ? "is a directory" : "not a regular file";
    const CommandResult eval = runCommand(
        {"/usr/bin/timeout", "20", RAYLAB_BINARY, "brdf", "eval", "--in", input, "--out", dir + "/v.csv"});
    EXPECT_EQ(eval.exitCode, 1) << input << ": " << eval.output;
    EXPECT_NE(eval.output.find(expected), std::string::npos) << eval.output;
    const CommandResult view = runCommand({"/usr/bin/timeout", "20", RAYLAB_BINARY, "view", "--script", input,
                                           "--frames", "1"});
    EXPECT_EQ(view.exitCode, 1) << input << ": " << view.output;
    EXPECT_NE(view.output.find(expected), std::string::npos) << view.output;
  }
}

}  // namespace
}  // namespace raylab::test
