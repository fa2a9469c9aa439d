// 8192x8192 maps through the commands that read them, with their peak memory measured (the
// child's maximum resident set, from wait4) and compared with the same command on a 16x16 map
// in the same run, so the libraries', the sanitizers' and the GL driver's fixed cost cancel.
// The bounds are stated in docs/limits.md: a map is held as 32-bit floats (256 MiB for one
// channel at 8192x8192); `info` streams the pixels and holds none of them; `compress` holds
// the map and its blocks; `render` the map and the GL texture with its mips (on llvmpipe the
// driver's texture memory is the process's own).
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

extern char** environ;

namespace relief::test {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
// One float channel of an 8192x8192 map.
constexpr double kFloatMapMiB = 8192.0 * 8192.0 * 4.0 / kMiB;

struct Measured {
  int exitCode = -1;
  double peakMiB = 0.0;
};

// Runs a program and returns its exit code and peak resident memory.
Measured runMeasured(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  Measured measured;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    return measured;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid)
    return measured;
  measured.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  measured.peakMiB = double(usage.ru_maxrss) * 1024.0 / kMiB;  // ru_maxrss is in KiB
  return measured;
}

class LargeMap : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // AddressSanitizer holds freed memory back (256 MiB by default) to catch use after free;
    // a small quarantine keeps what is measured close to what the program holds.
    ::setenv("ASAN_OPTIONS", "detect_leaks=0:quarantine_size_mb=16", 1);
    s_folder = scratchFolder() + "/large";
    std::filesystem::create_directories(s_folder);
    for (const auto& [name, size] : {std::pair{"large", "8192x8192"}, {"small", "16x16"}}) {
      const Measured made = runMeasured({"oiiotool", "--pattern", "fill:top=0:bottom=1", size, "1",
                                         "-d", "uint16", "-o", s_folder + "/" + name + ".png"});
      ASSERT_EQ(made.exitCode, 0) << "oiiotool could not write the " << size << " map";
    }
  }

  // The command's extra peak on the 8192x8192 map over the 16x16 one, in MiB.
  static double extraPeakMiB(const std::vector<std::string>& before,
                             const std::vector<std::string>& after) {
    double peaks[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
      std::vector<std::string> arguments = {RELIEF_CLI_PATH};
      arguments.insert(arguments.end(), before.begin(), before.end());
      arguments.push_back(s_folder + (i == 0 ? "/large.png" : "/small.png"));
      arguments.insert(arguments.end(), after.begin(), after.end());
      const Measured run = runMeasured(arguments);
      EXPECT_EQ(run.exitCode, 0) << arguments[1] << " failed on " << arguments[before.size() + 1];
      peaks[i] = run.peakMiB;
    }
    std::printf("%s: peak %.0f MiB on 8192x8192, %.0f MiB on 16x16\n", before.front().c_str(),
                peaks[0], peaks[1]);
    return peaks[0] - peaks[1];
  }

  static inline std::string s_folder;
};

TEST_F(LargeMap, InfoStreamsTheImageAndHoldsNoneOfIt) {
  EXPECT_LT(extraPeakMiB({"info"}, {}), 32.0);
}

TEST_F(LargeMap, CompressHoldsTheMapAndItsBlocks) {
  // The float map (256 MiB), BC4 blocks (32 MiB) and working rows; not a second full copy.
  EXPECT_LT(extraPeakMiB({"compress", "--in"}, {"--height", "--format", "bc4", "--quality", "fast",
                                                "--out", s_folder + "/out.dds"}),
            1.6 * kFloatMapMiB);
}

TEST_F(LargeMap, RenderHoldsTheMapAndTheTextureWithItsMips) {
  // The float map (256 MiB) and the R32F texture with its mips (341 MiB) in llvmpipe.
  EXPECT_LT(
      extraPeakMiB({"render", "--height"}, {"--size", "64x64", "--out", s_folder + "/render.png"}),
      3.0 * kFloatMapMiB);
}

}  // namespace
}  // namespace relief::test
