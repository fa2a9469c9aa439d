// relief-cli batch (app/cli/BatchCommand.h): many jobs in one process. A bad job fails alone
// and its message names its file and the batch's line; the good jobs' outputs are whole (they
// decode); render jobs (and compare --rendered) run in the render helper with one GL context; a
// batch interrupted in the middle of a save leaves neither a half-written output nor its temporary
// file.
#include "cli/CliRunner.h"
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QThread>

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

namespace relief::test {
namespace {

namespace fs = std::filesystem;

std::string writeManifest(const std::string& folder, const std::string& lines) {
  const std::string path = folder + "/jobs.txt";
  std::ofstream(path) << lines;
  return path;
}

TEST(Batch, ABadJobFailsAloneAndTheGoodJobsOutputsAreWhole) {
  const std::string folder = scratchFolder();
  const std::string samples = sourcePath("samples/bricks");
  const std::string manifest =
      writeManifest(folder,
                    "# colour, a missing map, then a normal map given as a JSON array\n"
                    "compress --in " +
                        samples + "/bricks_color.png --format bc7 --out " + folder +
                        "/color.ktx2 --zstd 19\n"
                        "\n"
                        "compress --in '" +
                        folder + "/no such map.png' --format bc4 --out " + folder +
                        "/missing.ktx2\n"
                        "[\"compress\", \"--in\", \"" +
                        samples +
                        "/bricks_normal.png\", \"--normal\", "
                        "\"--format\", \"bc5\", \"--out\", \"" +
                        folder + "/normal.dds\"]\n");
  const CliRun run = runCli({"batch", q(manifest), "--json"});
  ASSERT_FALSE(run.crashed);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  const QJsonObject summary = QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
  ASSERT_FALSE(summary.isEmpty()) << "standard output is not the JSON summary alone: " << run.out;
  EXPECT_EQ(summary.value("succeeded").toInt(), 2);
  EXPECT_EQ(summary.value("failed").toInt(), 1);
  const QJsonArray jobs = summary.value("jobs").toArray();
  ASSERT_EQ(jobs.size(), 3);
  EXPECT_EQ(jobs[0].toObject().value("line").toInt(), 2);
  const QJsonObject bad = jobs[1].toObject();
  EXPECT_EQ(bad.value("line").toInt(), 4);
  EXPECT_EQ(bad.value("exit").toInt(), 1);
  ASSERT_EQ(bad.value("errors").toArray().size(), 1);
  EXPECT_TRUE(bad.value("errors")[0].toString().contains(q(folder + "/no such map.png")));
  EXPECT_NE(run.err.find("jobs.txt:4: the job failed"), std::string::npos) << run.err;
  EXPECT_EQ(jobs[2].toObject().value("exit").toInt(), 0);
  // The outputs before and after the bad job are whole textures of the map's size.
  for (const char* output : {"color.ktx2", "normal.dds"}) {
    const CliRun decoded =
        runCli({"decode", q(folder + "/" + output), "--out", q(folder + "/" + output + ".png")});
    ASSERT_EQ(decoded.exitCode, 0) << output << ": " << decoded.err;
    const core::Result<core::ImageFileInfo> info =
        core::readImageInfo(folder + "/" + output + ".png");
    ASSERT_TRUE(info.ok()) << info.error();
    EXPECT_EQ(info->width, 1024) << output;
  }
  EXPECT_FALSE(fs::exists(folder + "/missing.ktx2"));
}

TEST(Batch, AManifestThatCannotRunIsRefusedBeforeAnyJob) {
  const std::string folder = scratchFolder();
  const std::string manifest = writeManifest(
      folder, "generate normal --in " + sourcePath("samples/bricks/bricks_height.png") + " --out " +
                  folder + "/n.png\nsquash --in a.png\n");
  const CliRun run = runCli({"batch", q(manifest)});
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("jobs.txt:2: unknown command 'squash'"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(folder + "/n.png")) << "a job ran before the manifest was checked";
}

TEST(Batch, RenderJobsRunInOneProcessBesideTheOthers) {
  const std::string folder = scratchFolder();
  const std::string preset = samplePreset("bricks");
  const std::string manifest = writeManifest(
      folder, "render " + preset + " --out " + folder + "/a.png --size 96x64\n" + "info " +
                  sourcePath("samples/bricks/bricks_height.png") + "\n" + "render " + preset +
                  " --out " + folder + "/b.png --size 48x40 --technique relief\n" +
                  "compare --rendered " + preset + " --size 48x40\n");
  const CliRun run = runCli({"batch", q(manifest)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("size: 1024x1024"), std::string::npos) << "the info job's output";
  EXPECT_NE(run.out.find("the material renders as it is"), std::string::npos)
      << "compare --rendered runs as a render job: " << run.out;
  EXPECT_NE(run.out.find("batch: 4 jobs, 4 succeeded, 0 failed"), std::string::npos) << run.out;
  for (const auto& [name, width, height] : {std::tuple{"a.png", 96, 64}, {"b.png", 48, 40}}) {
    const core::Result<core::ImageFileInfo> info = core::readImageInfo(folder + "/" + name);
    ASSERT_TRUE(info.ok()) << info.error();
    EXPECT_EQ(info->width, width);
    EXPECT_EQ(info->height, height);
  }
}

// SIGTERM arrives while a save is in progress (the test waits for the save's temporary file to
// appear): the process ends, the temporary is gone, and every output that exists reads whole.
TEST(Batch, AnInterruptedBatchLeavesNoHalfWrittenFile) {
  // A folder of its own: the process's scratch folder holds the other tests' outputs when they
  // run in one process (normal.dds is no image).
  const std::string folder = scratchFolder() + "/interrupted";
  fs::create_directories(folder);
  const std::string height = folder + "/height.png";
  QProcess make;
  make.start("oiiotool", {"--pattern", "noise:type=uniform", "4096x4096", "1", "-d", "uint16", "-o",
                          q(height)});
  ASSERT_TRUE(make.waitForFinished(120000) && make.exitCode() == 0) << "oiiotool";
  std::string lines;
  for (int i = 0; i < 6; ++i)
    lines += "generate normal --in " + height + " --out " + folder + "/normal" + std::to_string(i) +
             ".png\n";
  const std::string manifest = writeManifest(folder, lines);
  QProcess batch;
  batch.start(QStringLiteral(RELIEF_CLI_PATH), {"batch", q(manifest)});
  ASSERT_TRUE(batch.waitForStarted());
  bool sawTemporary = false;
  for (int waited = 0; waited < 120000 && !sawTemporary; waited += 2) {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
      sawTemporary = sawTemporary || entry.path().filename().string().rfind(".normal", 0) == 0;
    if (!sawTemporary)
      QThread::msleep(2);
  }
  ASSERT_TRUE(sawTemporary) << "no save was seen in progress";
  ::kill(pid_t(batch.processId()), SIGTERM);
  ASSERT_TRUE(batch.waitForFinished(60000));
  EXPECT_EQ(batch.exitStatus(), QProcess::CrashExit) << "ended by the signal";
  int outputs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    EXPECT_NE(name.front(), '.') << "a temporary file was left: " << name;
    if (name.rfind("normal", 0) == 0) {
      ++outputs;
      EXPECT_TRUE(core::verifyImageData(entry.path().string()).ok()) << name;
    }
  }
  EXPECT_LT(outputs, 6) << "the batch finished before the signal";
}

}  // namespace
}  // namespace relief::test
