// 8192x8192 maps through the commands that read them, with the peak of the heap bytes each
// command holds (counted by the sanitizer build's malloc hooks, tools/sanitizers/HeapPeak.cpp)
// compared with the same command on a 16x16 map in the same run, so the libraries' and the GL
// driver's fixed cost cancels. The bounds are stated in docs/limits.md: a map is held as 32-bit
// floats (256 MiB for one channel at 8192x8192); `info` streams the pixels and holds none of
// them; `compress` holds the map and its blocks; `render` the map and the GL texture with its
// mips (on llvmpipe the driver's texture memory is the process's own heap).
//
// The heap's peak, not the resident set's: the resident set also holds what the allocator and
// the sanitizer's shadow and quarantine keep, which vary with the runtime and the thread count
// (a bound on it failed by 3% on one CI run and passed on the next).
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace relief::test {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
// One float channel of an 8192x8192 map.
constexpr double kFloatMapMiB = 8192.0 * 8192.0 * 4.0 / kMiB;

struct Measured {
  int exitCode = -1;
  double peakMiB = -1.0;  // the heap's peak; negative when the program did not report it
};

// Runs a program and returns its exit code and the peak of its live heap bytes, which a
// sanitizer build's executables write to RELIEF_HEAP_PEAK_FILE at exit.
Measured runMeasured(const std::vector<std::string>& arguments, const std::string& peakFile) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  std::filesystem::remove(peakFile);
  ::setenv("RELIEF_HEAP_PEAK_FILE", peakFile.c_str(), 1);
  pid_t pid = 0;
  Measured measured;
  const bool started = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) == 0;
  ::unsetenv("RELIEF_HEAP_PEAK_FILE");
  int status = 0;
  if (!started || waitpid(pid, &status, 0) != pid)
    return measured;
  measured.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  long long peakBytes = -1;
  if (std::ifstream report(peakFile); report >> peakBytes)
    measured.peakMiB = double(peakBytes) / kMiB;
  return measured;
}

class LargeMap : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    s_folder = scratchFolder() + "/large";
    std::filesystem::create_directories(s_folder);
    for (const auto& [name, size] : {std::pair{"large", "8192x8192"}, {"small", "16x16"}}) {
      const Measured made = runMeasured({"oiiotool", "--pattern", "fill:top=0:bottom=1", size, "1",
                                         "-d", "uint16", "-o", s_folder + "/" + name + ".png"},
                                        s_folder + "/oiiotool.peak");
      ASSERT_EQ(made.exitCode, 0) << "oiiotool could not write the " << size << " map";
    }
  }

  void SetUp() override {
#if !defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "the heap's peak is counted by the sanitizer build's hooks (make test)";
#endif
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
      const Measured run = runMeasured(arguments, s_folder + "/cli.peak");
      EXPECT_EQ(run.exitCode, 0) << arguments[1] << " failed on " << arguments[before.size() + 1];
      EXPECT_GE(run.peakMiB, 0.0) << arguments[1] << " did not report its heap's peak";
      peaks[i] = run.peakMiB;
    }
    std::printf("%s: heap peak %.1f MiB on 8192x8192, %.1f MiB on 16x16\n", before.front().c_str(),
                peaks[0], peaks[1]);
    return peaks[0] - peaks[1];
  }

  static inline std::string s_folder;
};

TEST_F(LargeMap, InfoStreamsTheImageAndHoldsNoneOfIt) {
  EXPECT_LT(extraPeakMiB({"info"}, {}), 8.0);
}

TEST_F(LargeMap, CompressHoldsTheMapAndItsBlocks) {
  // The float map (256 MiB), the BC4 blocks (32 MiB) and the file's bytes (32 MiB, encoded whole
  // before the atomic save): 1.25x. Not a second copy of the map, nor the PNG's inflated rows
  // beside it (PngReader inflates into the map's own buffer).
  EXPECT_LT(extraPeakMiB({"compress", "--in"}, {"--height", "--format", "bc4", "--quality", "fast",
                                                "--out", s_folder + "/out.dds"}),
            1.3 * kFloatMapMiB);
}

TEST_F(LargeMap, RenderHoldsTheMapAndTheTextureWithItsMips) {
  // The float map (256 MiB), the R32F texture with its mips (341 MiB) in llvmpipe, and the two
  // mip levels core's chain holds while it makes the next (levels 1 and 2, 80 MiB; the chain the
  // map ships with, built on the CPU: renderer/TextureCache.h): 2.64x.
  EXPECT_LT(
      extraPeakMiB({"render", "--height"}, {"--size", "64x64", "--out", s_folder + "/render.png"}),
      2.7 * kFloatMapMiB);
}

}  // namespace
}  // namespace relief::test
