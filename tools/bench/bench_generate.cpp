// bench-generate: what the map generators cost, for the same inputs in one run. Normal from
// height at 4096^2 (Sobel) next to an OpenCV pipeline (cv2.Sobel on both axes plus normalise,
// tools/bench/opencv_normals.py, through /usr/bin/python3), height from normal at 2048^2, AO at
// 2048^2 (16 directions x 16 steps), and an 8192^2 material, with the process's peak memory.
// Inputs are the bricks sample's height resized (a real map, not noise).
//
// Run: build/release/tools/bench-generate [runs, default 3]
#include "core/generators/Generators.h"
#include "core/generators/ImageFilters.h"
#include "core/image/ImageIO.h"
#include "tools/bench/MedianTime.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#ifndef RELIEF_SOURCE_DIR
#error "RELIEF_SOURCE_DIR must point at the source tree (for the samples)"
#endif

namespace {

using namespace relief;

using bench::medianMilliseconds;

double peakRssMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

core::GeneratedMap generate(core::GeneratorKind kind, const core::Image& input,
                            std::vector<std::pair<const char*, double>> options = {}) {
  core::GeneratorValues values = core::defaultGeneratorValues(kind);
  for (const auto& [name, value] : options) {
    values[std::size_t(core::findGeneratorOption(kind, name))] = value;
  }
  auto result = core::runGenerator({kind, {&input}, values, 1.0});
  if (!result) {
    std::fprintf(stderr, "bench-generate: %s\n", result.error().c_str());
    std::exit(1);
  }
  return std::move(result).value();
}

// Runs the OpenCV peer on the same heights; returns its median milliseconds or -1.
double openCvMilliseconds(const core::Image& height, int runs) {
  const std::string raw = "/tmp/relief-bench-height.f32";
  std::ofstream(raw, std::ios::binary)
      .write(reinterpret_cast<const char*>(height.data()),
             std::streamsize(height.valueCount() * sizeof(float)));
  const std::string command =
      "/usr/bin/python3 '" RELIEF_SOURCE_DIR "/tools/bench/opencv_normals.py' " +
      std::to_string(height.width()) + " " + std::to_string(height.height()) + " " + raw + " " +
      std::to_string(runs) + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  double milliseconds = -1.0;
  if (pipe) {
    if (std::fscanf(pipe, "%lf", &milliseconds) != 1)
      milliseconds = -1.0;
    pclose(pipe);
  }
  std::remove(raw.c_str());
  return milliseconds;
}

}  // namespace

int main(int argc, char* argv[]) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  auto source = core::loadImage(RELIEF_SOURCE_DIR "/samples/bricks/bricks_height.png");
  if (!source) {
    std::fprintf(stderr, "bench-generate: %s\n", source.error().c_str());
    return 1;
  }
  const core::Image height4k = core::resizeImage(source.value(), 4096, 4096);
  const core::Image height2k = core::resizeImage(source.value(), 2048, 2048);
  const core::GeneratedMap normals2k =
      generate(core::GeneratorKind::Normal, height2k, {{"strength", 60.0}});

  struct Row {
    std::string what;
    double milliseconds;
    std::string target;
  };
  std::vector<Row> rows;
  const double relief4k = medianMilliseconds(runs, [&] {
    generate(core::GeneratorKind::Normal, height4k, {{"edge", 1.0}});
  });
  const double opencv4k = openCvMilliseconds(height4k, runs);
  rows.push_back({"normal from height 4096^2 (sobel, clamp)", relief4k,
                  opencv4k > 0 ? "<= OpenCV" : "OpenCV missing"});
  rows.push_back({"  OpenCV peer: cv2.Sobel x2 + normalise 4096^2", opencv4k,
                  opencv4k > 0 ? "" : "install python3-opencv (tools/install-deps.sh --bench)"});
  rows.push_back(
      {"height from normal 2048^2 (mirror-padded)",
       medianMilliseconds(runs, [&] { generate(core::GeneratorKind::Height, normals2k.image); }),
       "<= 2000"});
  rows.push_back(
      {"height from normal 2048^2 (tileable)",
       medianMilliseconds(runs,
                          [&] {
                            generate(core::GeneratorKind::Height, normals2k.image, {{"edge", 0.0}});
                          }),
       ""});
  rows.push_back({"ambient occlusion 2048^2 (16 dirs x 16 steps)",
                  medianMilliseconds(runs,
                                     [&] {
                                       generate(core::GeneratorKind::AmbientOcclusion, height2k,
                                                {{"directions", 16}, {"steps", 16}});
                                     }),
                  "<= 3000"});
  const double rssBefore8k = peakRssMegabytes();

  // An 8192^2 material: normal from height, height back from it (mirror-padded, the costly
  // case), AO; one run each.
  const core::Image height8k = core::resizeImage(source.value(), 8192, 8192);
  core::GeneratedMap normals8k;
  rows.push_back(
      {"8192^2: normal from height",
       medianMilliseconds(
           1,
           [&] {
             normals8k = generate(core::GeneratorKind::Normal, height8k, {{"strength", 240.0}});
           }),
       ""});
  rows.push_back(
      {"8192^2: height from normal (mirror-padded)",
       medianMilliseconds(1, [&] { generate(core::GeneratorKind::Height, normals8k.image); }), ""});
  rows.push_back(
      {"8192^2: ambient occlusion (16 x 16)",
       medianMilliseconds(1, [&] { generate(core::GeneratorKind::AmbientOcclusion, height8k); }),
       ""});

  std::printf("bench-generate: median of %d runs (8192^2 rows: 1 run), compute only\n\n", runs);
  std::printf("| work                                               |       ms | target |\n");
  std::printf("|----------------------------------------------------|----------|--------|\n");
  for (const Row& row : rows) {
    std::printf("| %-50s | %8.0f | %s |\n", row.what.c_str(), row.milliseconds, row.target.c_str());
  }
  std::printf("\npeak RSS: %.0f MB after the 2048/4096 rows, %.0f MB with the 8192^2 material\n",
              rssBefore8k, peakRssMegabytes());
  return 0;
}
