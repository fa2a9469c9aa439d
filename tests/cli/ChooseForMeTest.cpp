// `relief-cli compress --preset P --budget|--target-flip|--target-psnr --out-dir D` (choose for
// me, renderer/CompressionChooser.h) as a user runs it, on a 64x64 cut of the cobblestones
// (colour, normal, height). The budget is never exceeded by the files written, whose bytes are
// what the JSON reports and whose formats are the ones it names; a budget below the smallest
// combination (one byte) is refused naming that size, and writes nothing; a target met is met as
// measured; bad goals are command-line errors (exit 2).
#include "cli/CliRunner.h"
#include "core/base/ByteSize.h"
#include "core/compression/TextureFile.h"
#include "support/CroppedSample.h"
#include "support/TestPaths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <filesystem>

namespace relief::test {
namespace {

namespace fs = std::filesystem;

constexpr int kCut = 64;

std::string cutMaterial() {
  return croppedSamplePreset("cobblestones", kCut, scratchFolder() + "/choose-material");
}

CliRun choose(const std::string& preset, const QStringList& goal, const std::string& outDir) {
  QStringList arguments = {"compress", "--preset", q(preset)};
  arguments << goal << "--out-dir" << q(outDir) << "--size"
            << "128x96"
            << "--json";
  return runCli(arguments);
}

// const, so that [] reads (a QJsonObject's non-const [] makes a reference).
const QJsonObject json(const CliRun& run) {
  return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
}

// The smallest and the largest combination: each map's fewest and most bytes, summed.
std::pair<double, double> combinationBounds(const QJsonObject& report) {
  double smallest = 0.0, largest = 0.0;
  for (const QJsonValue& map : report["maps"].toArray()) {
    double least = 1e300, most = 0.0;
    for (const QJsonValue& candidate : map["candidates"].toArray()) {
      least = std::min(least, candidate["bytes"].toDouble());
      most = std::max(most, candidate["bytes"].toDouble());
    }
    smallest += least;
    largest += most;
  }
  return {smallest, largest};
}

int filesIn(const std::string& folder) {
  if (!fs::exists(folder))
    return 0;
  return int(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(ChooseForMe, TheBudgetHoldsAndTheFilesAreTheChoice) {
  const std::string preset = cutMaterial();
  const std::string root = scratchFolder() + "/choose-budget";
  fs::remove_all(root);

  // A budget of one byte: refused, naming the smallest size these maps ship at; nothing
  // written. The report still lists every candidate, which gives the test its bounds.
  const std::string tightDir = root + "/tight";
  CliRun tight = choose(preset, {"--budget", "1"}, tightDir);
  EXPECT_EQ(tight.exitCode, 1);
  const QJsonObject all = json(tight);
  ASSERT_EQ(all["maps"].toArray().size(), 3);
  EXPECT_FALSE(all["met"].toBool());
  // The views are rendered at the --size asked for (the chooser once ignored it).
  EXPECT_EQ(all["viewSize"].toString(), QStringLiteral("128x96"));
  const auto [smallest, largest] = combinationBounds(all);
  ASSERT_LT(smallest, largest);
  EXPECT_NE(tight.err.find("cannot be met"), std::string::npos) << tight.err;
  EXPECT_NE(tight.err.find(core::describeByteSize(std::uint64_t(smallest))), std::string::npos)
      << tight.err;
  EXPECT_EQ(all["closest"]["bytes"].toDouble(), smallest);
  EXPECT_EQ(filesIn(tightDir), 0);

  // A budget halfway: met, never exceeded, and the files are what the report says.
  const double budget = std::floor((smallest + largest) / 2.0);
  const std::string middleDir = root + "/middle";
  CliRun middle = choose(preset, {"--budget", QString::number(budget, 'f', 0)}, middleDir);
  ASSERT_EQ(middle.exitCode, 0) << middle.err;
  const QJsonObject report = json(middle);
  ASSERT_TRUE(report["met"].toBool());
  const double total = report["total"]["bytes"].toDouble();
  EXPECT_LE(total, budget);
  double onDisk = 0.0;
  for (const QJsonValue& map : report["maps"].toArray()) {
    const std::string file = map["file"].toString().toStdString();
    ASSERT_TRUE(fs::exists(file)) << file;
    onDisk += double(fs::file_size(file));
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(file);
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_EQ(core::textureFormatInfo(texture->format).name, map["format"].toString().toStdString())
        << file;
    EXPECT_EQ(texture->levels.size(), 7u) << file << ": a full chain of a 64x64 map";
    EXPECT_TRUE(texture->zstdInFile) << file;
    // Candidates are screened at fast; the chosen one ships at the quality asked for (the
    // default, normal), and its row gives that file's bytes.
    int chosen = 0;
    for (const QJsonValue& candidate : map["candidates"].toArray()) {
      const bool picked = candidate["chosen"].toBool();
      chosen += picked ? 1 : 0;
      EXPECT_EQ(candidate["quality"].toString(),
                picked ? QStringLiteral("normal") : QStringLiteral("fast"))
          << file;
      if (picked) {
        EXPECT_EQ(candidate["bytes"].toDouble(), double(fs::file_size(file))) << file;
      }
    }
    EXPECT_EQ(chosen, 1) << file;
    // The very blocks `compress` writes at normal quality with the same chain and RDO trade.
    const QString slot = map["slot"].toString();
    const std::string source =
        fs::path(preset).parent_path() / ("cobblestones_" + slot.toStdString() + ".png");
    const std::string alone = root + "/alone_" + slot.toStdString() + ".ktx2";
    QStringList arguments = {"compress", "--in",    q(source), "--format", map["format"].toString(),
                             "--mips",   "--quiet", "--out",   q(alone)};
    if (slot != QStringLiteral("color"))
      arguments << ("--" + slot);
    if (map["rdo"].toDouble() > 0.0)
      arguments << "--rdo" << QString::number(map["rdo"].toDouble()) << "--zstd"
                << "19";
    ASSERT_EQ(runCli(arguments).exitCode, 0) << source;
    core::Result<core::CompressedTexture> reference = core::loadCompressedTexture(alone);
    ASSERT_TRUE(reference.ok()) << reference.error();
    ASSERT_EQ(reference->levels.size(), texture->levels.size()) << file;
    for (std::size_t level = 0; level < texture->levels.size(); ++level)
      EXPECT_EQ(reference->levels[level].data, texture->levels[level].data) << file << level;
  }
  EXPECT_EQ(onDisk, total);
  EXPECT_TRUE(fs::exists(middleDir + "/choice.json"));
  // Rendered together, the choice has an error, which no view hides.
  EXPECT_GT(report["total"]["flip"].toDouble(), 0.0);
  EXPECT_EQ(report["total"]["views"].toArray().size(), 3);
}

TEST(ChooseForMe, QualityTargetsAreMetAsRendered) {
  const std::string preset = cutMaterial();
  const std::string root = scratchFolder() + "/choose-target";
  fs::remove_all(root);
  // Any PSNR above 1 dB: the smallest combination does.
  CliRun easy = choose(preset, {"--target-psnr", "1"}, root + "/easy");
  ASSERT_EQ(easy.exitCode, 0) << easy.err;
  EXPECT_EQ(json(easy)["total"]["bytes"].toDouble(), combinationBounds(json(easy)).first);

  // A FLIP between the best and the worst map alone: met as measured with all maps compressed.
  double worstAlone = 0.0;
  for (const QJsonValue& map : json(easy)["maps"].toArray()) {
    for (const QJsonValue& candidate : map["candidates"].toArray())
      worstAlone = std::max(worstAlone, candidate["flip"].toDouble());
  }
  const double target = worstAlone * 1.5;
  CliRun met = choose(preset, {"--target-flip", QString::number(target)}, root + "/met");
  ASSERT_EQ(met.exitCode, 0) << met.err;
  EXPECT_LE(json(met)["total"]["flip"].toDouble(), target);

  // Below what any map alone reaches: refused.
  CliRun unreachable = choose(preset, {"--target-flip", "0.000001"}, root + "/none");
  EXPECT_EQ(unreachable.exitCode, 1);
  EXPECT_NE(unreachable.err.find("cannot be reached"), std::string::npos) << unreachable.err;
  EXPECT_EQ(filesIn(root + "/none"), 0);
}

TEST(ChooseForMe, BadGoalsAreCommandLineErrors) {
  const std::string preset = sourcePath("samples/tiles/tiles.relief");
  const std::string out = scratchFolder() + "/choose-bad";
  for (const char* budget : {"0", "abc", "-5MB", "6XB", ""}) {
    CliRun run = choose(preset, {"--budget", budget}, out);
    EXPECT_EQ(run.exitCode, 2) << budget << ": " << run.err;
    EXPECT_NE(run.err.find("--budget"), std::string::npos) << run.err;
  }
  CliRun none = choose(preset, {}, out);
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.err.find("give one goal"), std::string::npos) << none.err;
  CliRun two = choose(preset, {"--budget", "6MB", "--target-flip", "0.01"}, out);
  EXPECT_EQ(two.exitCode, 2);
  CliRun flip = choose(preset, {"--target-flip", "1.5"}, out);
  EXPECT_EQ(flip.exitCode, 2);
  CliRun device = choose(preset, {"--budget", "6MB", "--device", "phone"}, out);
  EXPECT_EQ(device.exitCode, 2);
  EXPECT_NE(device.err.find("desktop or mobile"), std::string::npos) << device.err;
  CliRun noOutDir = runCli({"compress", "--preset", q(preset), "--budget", "6MB"});
  EXPECT_EQ(noOutDir.exitCode, 2);
  EXPECT_NE(noOutDir.err.find("--out-dir"), std::string::npos) << noOutDir.err;
  CliRun noPreset = runCli({"compress", "--budget", "6MB", "--out-dir", q(out)});
  EXPECT_EQ(noPreset.exitCode, 2);
  EXPECT_NE(noPreset.err.find("give --preset"), std::string::npos) << noPreset.err;
  EXPECT_EQ(filesIn(out), 0);
}

}  // namespace
}  // namespace relief::test
