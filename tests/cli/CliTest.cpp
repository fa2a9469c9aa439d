// relief-cli as a user runs it: on the samples, and on bad input (each must be a clear error
// naming the file, a non-zero exit and no crash). `render` runs under the test's X display.
#include "cli/CliRunner.h"
#include "core/compression/Compressor.h"
#include "core/compression/MipChain.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageIO.h"
#include "core/shading/EnvironmentMaps.h"
#include "support/ImageCompare.h"
#include "support/TestPaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QThread>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <sys/stat.h>
#include <unistd.h>

namespace relief::test {
namespace {

int readImageBits(const std::string& path) {
  core::Result<core::ImageFileInfo> info = core::readImageInfo(path);
  return info.ok() ? info->bitsPerChannel : 0;
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The bad files every command that reads an image must refuse cleanly.
std::vector<std::pair<std::string, std::string>> badImageFiles() {
  const std::string folder = scratchFolder();
  const std::string valid = readBytes(sourcePath("samples/tiles/tiles_color.png"));
  std::vector<std::pair<std::string, std::string>> files;
  files.emplace_back(folder + "/missing.png", "not found");

  writeBytes(folder + "/zero.png", "");
  files.emplace_back(folder + "/zero.png", "empty");

  writeBytes(folder + "/text.png", "just some text, not an image\n");
  files.emplace_back(folder + "/text.png", "cannot read");

  writeBytes(folder + "/truncated.png", valid.substr(0, valid.size() / 3));
  files.emplace_back(folder + "/truncated.png", "truncated");

  // Flip one byte inside the first IDAT chunk's data: its CRC no longer matches.
  std::string badCrc = valid;
  const std::size_t idat = badCrc.find("IDAT");
  badCrc[idat + 40] = char(badCrc[idat + 40] ^ 0x5a);
  writeBytes(folder + "/badcrc.png", badCrc);
  files.emplace_back(folder + "/badcrc.png", "damaged");

  // An IHDR that claims 100000x100000 (with a valid CRC).
  std::string huge = valid.substr(0, 33);
  const unsigned char dims[8] = {0, 1, 0x86, 0xa0, 0, 1, 0x86, 0xa0};
  huge.replace(16, 8, reinterpret_cast<const char*>(dims), 8);
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 12; i < 29; ++i) {
    crc ^= static_cast<unsigned char>(huge[i]);
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc = ~crc;
  for (int i = 0; i < 4; ++i)
    huge[std::size_t(29 + i)] = char(crc >> (24 - 8 * i));
  huge += valid.substr(33);
  writeBytes(folder + "/huge.png", huge);
  files.emplace_back(folder + "/huge.png", "100000x100000");
  return files;
}

void expectCleanFailure(const CliRun& run, const std::string& file, const std::string& problem) {
  EXPECT_FALSE(run.crashed) << file;
  EXPECT_NE(run.exitCode, 0) << file;
  const std::string name = file.substr(file.find_last_of('/') + 1);
  EXPECT_NE(run.err.find(name), std::string::npos) << "stderr: " << run.err;
  EXPECT_NE(run.err.find(problem), std::string::npos) << "stderr: " << run.err;
}

TEST(Cli, InfoDescribesAnImage) {
  CliRun run = runCli({QStringLiteral("info"), q(sourcePath("samples/bricks/bricks_height.png"))});
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("size: 1024x1024"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("channels: 1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("bit depth: 16"), std::string::npos) << run.out;
}

// A 16-bit grey PNG without colour chunks is tagged sRGB by PNG's default, but as a height,
// normal, AO or roughness map Relief reads its values as stored; info says so per slot, in text
// and in JSON.
TEST(Cli, InfoSaysHowEachSlotReadsTheFile) {
  const std::string path = scratchFolder() + "/scan_height.png";
  core::Image grey(8, 8, 1, core::ColorSpace::Srgb);
  std::fill(grey.data(), grey.data() + grey.valueCount(), 0.5f);
  grey.setSourceBitsPerChannel(16);
  ASSERT_TRUE(core::saveImage(grey, path, core::SampleFormat::UInt16).ok());
  CliRun run = runCli({QStringLiteral("info"), q(path)});
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("colour space in the file: srgb"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("as height: linear data, values as stored (its name suggests this slot)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("as color: sRGB colour"), std::string::npos) << run.out;
  CliRun json = runCli({QStringLiteral("info"), q(path), QStringLiteral("--json")});
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const QJsonObject object = QJsonDocument::fromJson(QByteArray::fromStdString(json.out)).object();
  EXPECT_EQ(object.value(QStringLiteral("bitsPerChannel")).toInt(), 16);
  EXPECT_EQ(object.value(QStringLiteral("fileColorSpace")).toString(), QStringLiteral("srgb"));
  EXPECT_EQ(object.value(QStringLiteral("slotFromName")).toString(), QStringLiteral("height"));
  const QJsonObject readAs = object.value(QStringLiteral("readAs")).toObject();
  EXPECT_EQ(readAs.value(QStringLiteral("height")).toString(), QStringLiteral("linear"));
  EXPECT_EQ(readAs.value(QStringLiteral("color")).toString(), QStringLiteral("srgb"));
}

TEST(Cli, InfoRefusesBadFilesClearly) {
  for (const auto& [file, problem] : badImageFiles()) {
    expectCleanFailure(runCli({QStringLiteral("info"), q(file)}), file, problem);
  }
}

// info --check (core/generators/MapCheck.h, tests/core/MapCheckTest.cpp): the sample's maps
// agree; its normal map with green inverted (as a DirectX exporter writes it) is found out, with
// exit 1 and the evidence; a one-channel "normal" map and a missing map are refused by name.
TEST(Cli, InfoCheckFindsADirectXNormalMap) {
  CliRun agree = runCli({QStringLiteral("info"), QStringLiteral("--check"),
                         q(sourcePath("samples/bricks/bricks.relief"))});
  EXPECT_EQ(agree.exitCode, 0) << agree.err << agree.out;
  EXPECT_NE(agree.out.find("the maps agree"), std::string::npos) << agree.out;

  const std::string height = sourcePath("samples/bricks/bricks_height.png");
  core::Image normal = core::loadImage(sourcePath("samples/bricks/bricks_normal.png")).value();
  for (int y = 0; y < normal.height(); ++y) {
    for (int x = 0; x < normal.width(); ++x)
      normal.at(x, y, 1) = 1.0f - normal.at(x, y, 1);
  }
  const std::string flipped = scratchFolder() + "/wall_dx.png";
  ASSERT_TRUE(core::saveImage(normal, flipped, core::SampleFormat::UInt8).ok());
  CliRun found =
      runCli({QStringLiteral("info"), QStringLiteral("--check"), QStringLiteral("--normal"),
              q(flipped), QStringLiteral("--height"), q(height), QStringLiteral("--json")});
  EXPECT_EQ(found.exitCode, 1) << found.err;
  const QJsonObject object = QJsonDocument::fromJson(QByteArray::fromStdString(found.out)).object();
  EXPECT_EQ(object.value(QStringLiteral("convention")).toString(), QStringLiteral("directx"));
  EXPECT_FALSE(object.value(QStringLiteral("ok")).toBool(true));
  EXPECT_LT(object.value(QStringLiteral("correlationY")).toDouble(), -0.9);
  const QJsonArray findings = object.value(QStringLiteral("findings")).toArray();
  ASSERT_EQ(findings.size(), 1);
  EXPECT_TRUE(findings[0].toString().startsWith(QStringLiteral("wall_dx.png is a DirectX")))
      << findings[0].toString().toStdString();

  CliRun grey = runCli(
      {QStringLiteral("info"), QStringLiteral("--check"), QStringLiteral("--normal"), q(height)});
  EXPECT_EQ(grey.exitCode, 1);
  EXPECT_NE(grey.err.find("bricks_height.png: the normal map has 1 channel"), std::string::npos)
      << grey.err;
  CliRun missing = runCli({QStringLiteral("info"), QStringLiteral("--check"),
                           QStringLiteral("--normal"), q(scratchFolder() + "/absent.png")});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("absent.png"), std::string::npos) << missing.err;
  EXPECT_EQ(runCli({QStringLiteral("info"), QStringLiteral("--check")}).exitCode, 2);
}

TEST(Cli, RenderRefusesBadMapsClearly) {
  const std::string out = scratchFolder() + "/never.png";
  for (const auto& [file, problem] : badImageFiles()) {
    CliRun run = runCli({QStringLiteral("render"), QStringLiteral("--color"), q(file),
                         QStringLiteral("--out"), q(out)});
    expectCleanFailure(run, file, problem);
  }
  EXPECT_FALSE(QFile::exists(q(out)));
}

TEST(Cli, RenderWritesThePresetsImage) {
  const std::string out = scratchFolder() + "/bricks.png";
  CliRun run = runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--out"),
                       q(out), QStringLiteral("--size"), QStringLiteral("320x200")});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  core::Result<core::Image> image = core::loadImage(out);
  ASSERT_TRUE(image.ok()) << image.error();
  EXPECT_EQ(image->width(), 320);
  EXPECT_EQ(image->height(), 200);
  // The CLI draws the same picture as the renderer's golden image of this view.
  EXPECT_TRUE(matchesBaseline(image.value(), "bricks_plane", 64.0 / 255.0, 0.5 / 255.0));
}

// --stats: a layered march of n layers takes 1 to n + 1 height samples a pixel (parallax.glsl
// stops at the first layer below the surface), whatever the view; the quadtree counts its
// pyramid fetches and four texels for each cell it intersects; the cone technique four texels
// (one gather) and one pyramid or cone fetch per step, so at least five everywhere.
TEST(Cli, RenderStatsCountHeightSamplesPerCoveredPixel) {
  const auto stats = [](const char* technique) {
    const std::string out = scratchFolder() + "/stats-" + technique + ".png";
    CliRun run = runCli(
        {QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--out"), q(out),
         QStringLiteral("--size"), QStringLiteral("160x100"), QStringLiteral("--technique"),
         QString::fromLatin1(technique), QStringLiteral("--set"), QStringLiteral("minSamples=8"),
         QStringLiteral("--set"), QStringLiteral("maxSamples=8"), QStringLiteral("--set"),
         QStringLiteral("shadowMode=off"), QStringLiteral("--stats")});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
  };
  const QJsonObject pom = stats("pom");
  // The frame times: at least 10 frames, ordered fastest <= median <= p90, and the spread is
  // (p90 - fastest) / median.
  const double median = pom.value(QStringLiteral("frame_ms")).toDouble();
  const double fastest = pom.value(QStringLiteral("frame_ms_min")).toDouble();
  const double p90 = pom.value(QStringLiteral("frame_ms_p90")).toDouble();
  EXPECT_GT(fastest, 0.0);
  EXPECT_LE(fastest, median);
  EXPECT_LE(median, p90);
  EXPECT_GE(pom.value(QStringLiteral("frames")).toInt(), 10);
  EXPECT_NEAR(pom.value(QStringLiteral("frame_spread")).toDouble(), (p90 - fastest) / median, 1e-9);
  EXPECT_GT(pom.value(QStringLiteral("pixels")).toDouble(), 1000.0);
  const QJsonObject samples = pom.value(QStringLiteral("samples_per_pixel")).toObject();
  EXPECT_GE(samples.value(QStringLiteral("mean")).toDouble(), 1.0);
  EXPECT_LE(samples.value(QStringLiteral("max")).toDouble(), 9.0);
  EXPECT_LE(samples.value(QStringLiteral("p95")).toDouble(),
            samples.value(QStringLiteral("max")).toDouble());
  const QJsonObject quadtree = stats("quadtree");
  EXPECT_EQ(quadtree.value(QStringLiteral("pixels")).toDouble(),
            pom.value(QStringLiteral("pixels")).toDouble());  // the same surface is covered
  // At least one pyramid fetch everywhere (minified, as at this size, the walk stops at the
  // level the map is read at, without a cell's four texels).
  EXPECT_GE(quadtree.value(QStringLiteral("samples_per_pixel"))
                .toObject()
                .value(QStringLiteral("mean"))
                .toDouble(),
            1.0);
  const QJsonObject cone = stats("cone");
  EXPECT_EQ(cone.value(QStringLiteral("pixels")).toDouble(),
            pom.value(QStringLiteral("pixels")).toDouble());
  EXPECT_GE(cone.value(QStringLiteral("samples_per_pixel"))
                .toObject()
                .value(QStringLiteral("p95"))
                .toDouble(),
            5.0);
}

// --engine grid: Relief's exact trace and the four engine previews side by side, each with its
// UV error against the exact trace; the exact panel's is zero, the engines' are not (bricks, a
// close grazing view where the map is magnified). A bad engine name is a usage error.
TEST(Cli, RenderEngineGridReportsEachEnginesUvError) {
  const std::string out = scratchFolder() + "/engine-grid.png";
  CliRun run =
      runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--out"), q(out),
              QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--pitch"),
              QStringLiteral("20"), QStringLiteral("--distance"), QStringLiteral("0.3"),
              QStringLiteral("--engine"), QStringLiteral("grid"), QStringLiteral("--json")});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const QJsonArray panels = QJsonDocument::fromJson(QByteArray::fromStdString(run.out))
                                .object()
                                .value(QStringLiteral("panels"))
                                .toArray();
  ASSERT_EQ(panels.size(), 5);
  QStringList engines;
  for (const QJsonValue& panel : panels) {
    const QJsonObject error = panel.toObject().value(QStringLiteral("uvErrorTexels")).toObject();
    engines << panel.toObject().value(QStringLiteral("engine")).toString();
    EXPECT_GT(error.value(QStringLiteral("pixels")).toDouble(), 1000.0)
        << engines.back().toStdString();
    if (engines.size() == 1)
      EXPECT_LT(error.value(QStringLiteral("mean")).toDouble(), 0.01);
    else
      EXPECT_GT(error.value(QStringLiteral("mean")).toDouble(), 0.02)
          << engines.back().toStdString();
  }
  EXPECT_EQ(engines.join(','), QStringLiteral("relief,godot,unreal,unity,unity-hdrp"));
  core::Result<core::Image> image = core::loadImage(out);
  ASSERT_TRUE(image.ok()) << image.error();
  EXPECT_EQ(image->width(), 5 * 160 + 4 * 4);
  EXPECT_EQ(image->height(), 120);

  CliRun bad = runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--out"),
                       q(scratchFolder() + "/bad-engine.png"), QStringLiteral("--engine"),
                       QStringLiteral("cryengine")});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--engine cryengine: expected grid or one of godot, unreal"),
            std::string::npos)
      << bad.err;
}

// --cost-table: every technique's frame time and UV error at the view, the cheapest within
// --max-error marked (the fastest of the rows within it); it writes no image, and a bad bound
// or an --out beside it is a usage error.
TEST(Cli, RenderCostTableMarksTheCheapestWithinTheBound) {
  CliRun run =
      runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--cost-table"),
              QStringLiteral("--json"), QStringLiteral("--size"), QStringLiteral("200x150"),
              QStringLiteral("--pitch"), QStringLiteral("20"), QStringLiteral("--distance"),
              QStringLiteral("0.3"), QStringLiteral("--max-error"), QStringLiteral("0.3")});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const QJsonObject table = QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
  const QJsonArray rows = table.value(QStringLiteral("rows")).toArray();
  ASSERT_EQ(rows.size(), 9);
  EXPECT_EQ(table.value(QStringLiteral("maxError")).toDouble(), 0.3);
  QString expected;
  double fastestWithin = 1e9;
  int marked = 0;
  for (const QJsonValue& value : rows) {
    const QJsonObject row = value.toObject();
    const QJsonObject error = row.value(QStringLiteral("uvErrorTexels")).toObject();
    EXPECT_GT(row.value(QStringLiteral("frame_ms_min")).toDouble(), 0.0);
    EXPECT_LE(row.value(QStringLiteral("frame_ms_min")).toDouble(),
              row.value(QStringLiteral("frame_ms")).toDouble());
    EXPECT_GT(error.value(QStringLiteral("pixels")).toDouble(), 1000.0);
    if (error.value(QStringLiteral("mean")).toDouble() <= 0.3 &&
        row.value(QStringLiteral("frame_ms_min")).toDouble() < fastestWithin) {
      fastestWithin = row.value(QStringLiteral("frame_ms_min")).toDouble();
      expected = row.value(QStringLiteral("label")).toString();
    }
    marked += row.value(QStringLiteral("cheapest")).toBool() ? 1 : 0;
  }
  EXPECT_EQ(marked, 1);
  EXPECT_EQ(table.value(QStringLiteral("cheapest")).toString(), expected);
  EXPECT_EQ(rows[0].toObject().value(QStringLiteral("label")).toString(), QStringLiteral("normal"));
  EXPECT_EQ(rows[2].toObject().value(QStringLiteral("label")).toString(),
            QStringLiteral("pom 8-32"));

  for (const QStringList& bad :
       {QStringList{QStringLiteral("--cost-table"), QStringLiteral("--out"),
                    q(scratchFolder() + "/cost.png")},
        QStringList{QStringLiteral("--cost-table"), QStringLiteral("--max-error"),
                    QStringLiteral("-1")},
        QStringList{QStringLiteral("--cost-table"), QStringLiteral("--max-error"),
                    QStringLiteral("lots")}}) {
    CliRun refused = runCli(QStringList{QStringLiteral("render"), q(samplePreset("bricks"))} + bad);
    EXPECT_EQ(refused.exitCode, 2) << bad.join(' ').toStdString() << ": " << refused.err;
  }
}

TEST(Cli, RenderTakesMapsAndParametersAndViewOptions) {
  const std::string out = scratchFolder() + "/maps.png";
  CliRun run = runCli({QStringLiteral("render"),
                       QStringLiteral("--color"),
                       q(sourcePath("samples/tiles/tiles_color.png")),
                       QStringLiteral("--height"),
                       q(sourcePath("samples/tiles/tiles_height.png")),
                       QStringLiteral("--set"),
                       QStringLiteral("tiling=3"),
                       QStringLiteral("--set"),
                       QStringLiteral("normalYDown=true"),
                       QStringLiteral("--yaw"),
                       QStringLiteral("-30"),
                       QStringLiteral("--pitch"),
                       QStringLiteral("60"),
                       QStringLiteral("--light-yaw"),
                       QStringLiteral("10"),
                       QStringLiteral("--light-pitch"),
                       QStringLiteral("70"),
                       QStringLiteral("--mesh"),
                       QStringLiteral("sphere"),
                       QStringLiteral("--size"),
                       QStringLiteral("64x48"),
                       QStringLiteral("--out"),
                       q(out)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  core::Result<core::Image> image = core::loadImage(out);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->width(), 64);
}

TEST(Cli, RenderRejectsBadOptionsWithUsageErrors) {
  const std::string out = scratchFolder() + "/x.png";
  const QString preset = q(samplePreset("bricks"));
  const std::vector<std::pair<QStringList, std::string>> cases = {
      {{QStringLiteral("render"), preset}, "--out"},
      {{QStringLiteral("render"), preset, QStringLiteral("--out"), q(out), QStringLiteral("--set"),
        QStringLiteral("nonsense=1")},
       "nonsense"},
      {{QStringLiteral("render"), preset, QStringLiteral("--out"), q(out), QStringLiteral("--set"),
        QStringLiteral("tiling=999")},
       "tiling"},
      {{QStringLiteral("render"), preset, QStringLiteral("--out"), q(out), QStringLiteral("--size"),
        QStringLiteral("big")},
       "--size"},
      {{QStringLiteral("render"), preset, QStringLiteral("--out"), q(out), QStringLiteral("--yaw"),
        QStringLiteral("left")},
       "--yaw"},
      {{QStringLiteral("render"), preset, QStringLiteral("--out"), q(out), QStringLiteral("--mesh"),
        QStringLiteral("teapot")},
       "teapot"},
      {{QStringLiteral("render"), preset, QStringLiteral("--frobnicate")}, "frobnicate"},
      {{QStringLiteral("render"), q(scratchFolder() + "/nope.relief"), QStringLiteral("--out"),
        q(out)},
       "nope.relief"},
      {{QStringLiteral("explode")}, "explode"},
  };
  for (const auto& [arguments, mention] : cases) {
    CliRun run = runCli(arguments);
    EXPECT_FALSE(run.crashed);
    EXPECT_NE(run.exitCode, 0) << arguments.join(QLatin1Char(' ')).toStdString();
    EXPECT_NE(run.err.find(mention), std::string::npos)
        << arguments.join(QLatin1Char(' ')).toStdString() << "\nstderr: " << run.err;
  }
}

TEST(Cli, RenderTakesTechniqueViewMeshAndFormat) {
  const std::string folder = scratchFolder();
  // An OBJ quad: --mesh takes files as well as the primitives' names.
  std::ofstream(folder + "/quad.obj") << "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 1 0\n"
                                         "f 1/1/1 2/2/1 3/3/1 4/4/1\n";
  const std::string steps = folder + "/steps.png";
  CliRun run = runCli({QStringLiteral("render"), q(samplePreset("cobblestones")),
                       QStringLiteral("--technique"), QStringLiteral("relief"),
                       QStringLiteral("--view"), QStringLiteral("steps"), QStringLiteral("--mesh"),
                       q(folder + "/quad.obj"), QStringLiteral("--size"), QStringLiteral("200x120"),
                       QStringLiteral("--out"), q(steps)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(core::loadImage(steps).ok());

  // The float UV: values a PNG could not hold (not multiples of 1/255, beyond 1 with tiling).
  const std::string uv = folder + "/uv.exr";
  run =
      runCli({QStringLiteral("render"), q(samplePreset("cobblestones")), QStringLiteral("--view"),
              QStringLiteral("uv"), QStringLiteral("--format"), QStringLiteral("exr"),
              QStringLiteral("--size"), QStringLiteral("160x100"), QStringLiteral("--out"), q(uv)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  core::Result<core::Image> image = core::loadImage(uv);
  ASSERT_TRUE(image.ok()) << image.error();
  EXPECT_EQ(readImageBits(uv), 32);
  float largest = 0.0f;
  bool offGrid = false;
  for (int y = 0; y < image->height(); ++y) {
    for (int x = 0; x < image->width(); ++x) {
      if (image->at(x, y, 3) <= 0.0f)
        continue;
      const float u = image->at(x, y, 0);
      largest = std::max(largest, u);
      offGrid = offGrid || std::abs(u * 255.0f - std::round(u * 255.0f)) > 0.01f;
    }
  }
  EXPECT_GT(largest, 1.2f);  // the sample tiles twice
  EXPECT_LE(largest, 2.2f);
  EXPECT_TRUE(offGrid);
}

// --farther N looks as from N times farther: the Mip level view (textureQueryLod of the height
// map, as EXR data) reads log2(N) levels further down at every pixel, away from the chain's ends;
// a distance outside 1..64 is a usage error.
TEST(Cli, RenderFartherSamplesLog2NLevelsFurtherDown) {
  const std::string folder = scratchFolder();
  const auto mipLevels = [&](const QString& farther) {
    const std::string out = folder + "/mip" + farther.toStdString() + ".exr";
    CliRun run =
        runCli({QStringLiteral("render"), q(samplePreset("cobblestones")), QStringLiteral("--view"),
                QStringLiteral("mip"), QStringLiteral("--format"), QStringLiteral("exr"),
                QStringLiteral("--size"), QStringLiteral("160x100"), QStringLiteral("--farther"),
                farther, QStringLiteral("--out"), q(out)});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    core::Result<core::Image> image = core::loadImage(out);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  };
  const core::Image near = mipLevels(QStringLiteral("1"));
  const core::Image far = mipLevels(QStringLiteral("8"));
  ASSERT_EQ(near.width(), far.width());
  const int top = core::mipLevelCount(1024, 1024) - 1;
  std::vector<double> differences;
  for (int y = 0; y < near.height(); ++y) {
    for (int x = 0; x < near.width(); ++x) {
      if (near.at(x, y, 3) <= 0.0f || far.at(x, y, 0) >= float(top) - 0.5f)
        continue;
      differences.push_back(double(far.at(x, y, 0)) - near.at(x, y, 0));
    }
  }
  ASSERT_GT(differences.size(), 2000u);
  std::nth_element(differences.begin(),
                   differences.begin() + std::ptrdiff_t(differences.size() / 2), differences.end());
  EXPECT_NEAR(differences[differences.size() / 2], 3.0, 0.1) << "log2(8) levels further";
  for (const char* bad : {"0", "65", "far"}) {
    CliRun run = runCli({QStringLiteral("render"), q(samplePreset("cobblestones")),
                         QStringLiteral("--farther"), QString::fromLatin1(bad),
                         QStringLiteral("--out"), q(folder + "/bad.png")});
    EXPECT_EQ(run.exitCode, 2) << bad;
    EXPECT_NE(run.err.find("--farther"), std::string::npos) << run.err;
  }
}

// The cobblestones sample as a preset in `folder` with its map paths absolute and `colour` (a
// format name, or empty) as the colour map's compression choice, with mipmaps.
std::string cobblestonesWithColourCompression(const std::string& folder, const char* colour) {
  QFile file(q(samplePreset("cobblestones")));
  EXPECT_TRUE(file.open(QIODevice::ReadOnly));
  QJsonObject preset = QJsonDocument::fromJson(file.readAll()).object();
  QJsonObject maps = preset.value(QStringLiteral("maps")).toObject();
  for (const QString& slot : maps.keys()) {
    QJsonObject map = maps.value(slot).toObject();
    map.insert(QStringLiteral("path"),
               q(sourcePath("samples/cobblestones/" + map.value("path").toString().toStdString())));
    if (slot == QStringLiteral("color") && *colour) {
      map.insert(QStringLiteral("compression"),
                 QJsonObject{{QStringLiteral("format"), QString::fromLatin1(colour)},
                             {QStringLiteral("quality"), QStringLiteral("fast")},
                             {QStringLiteral("mipmaps"), true}});
    }
    maps.insert(slot, map);
  }
  preset.insert(QStringLiteral("maps"), maps);
  const std::string path = folder + "/cobbles_" + (*colour ? colour : "none") + ".relief";
  QFile out(q(path));
  EXPECT_TRUE(out.open(QIODevice::WriteOnly));
  out.write(QJsonDocument(preset).toJson());
  return path;
}

// compare --rendered: the material rendered with its maps as they are and as its compression
// choices make them. No choice: identical pictures at every view (PSNR null, FLIP 0, no UV
// shift). A colour map compressed harder (ASTC 8x8, 2 bits a texel, against 4x4, 8 bits) never
// scores better at any view; the colour map moves no parallax. --out or no preset: usage errors.
TEST(Cli, CompareRenderedMeasuresTheMaterialAsDrawn) {
  const std::string folder = scratchFolder();
  const auto views = [&](const char* colour) {
    CliRun run =
        runCli({"compare", "--rendered", q(cobblestonesWithColourCompression(folder, colour)),
                "--size", "160x120", "--json"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out))
        .object()
        .value(QStringLiteral("views"))
        .toArray();
  };
  const QJsonArray same = views("");
  ASSERT_EQ(same.size(), 3);
  for (const QJsonValue& view : same) {
    EXPECT_TRUE(view["psnr"].isNull()) << view["view"].toString().toStdString();
    EXPECT_EQ(view["flip"].toDouble(), 0.0);
    EXPECT_EQ(view["uvShiftTexels"]["mean"].toDouble(), 0.0);
  }
  const QJsonArray fine = views("astc4x4");
  const QJsonArray coarse = views("astc8x8");
  ASSERT_EQ(fine.size(), 3);
  ASSERT_EQ(coarse.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const std::string name = fine[i]["view"].toString().toStdString();
    EXPECT_GT(fine[i]["flip"].toDouble(), 0.0) << name;
    EXPECT_LE(coarse[i]["psnr"].toDouble(), fine[i]["psnr"].toDouble()) << name;
    EXPECT_GE(coarse[i]["flip"].toDouble(), fine[i]["flip"].toDouble()) << name;
    EXPECT_EQ(coarse[i]["uvShiftTexels"]["mean"].toDouble(), 0.0) << name << ": colour only";
  }
  CliRun withOut =
      runCli({"compare", "--rendered", q(cobblestonesWithColourCompression(folder, "")), "--out",
              q(folder + "/x.png")});
  EXPECT_EQ(withOut.exitCode, 2);
  EXPECT_NE(withOut.err.find("drop --out"), std::string::npos) << withOut.err;
  CliRun noPreset =
      runCli({"compare", "--rendered", "--color", q(sourcePath("samples/tiles/tiles_color.png"))});
  EXPECT_EQ(noPreset.exitCode, 2);
  EXPECT_NE(noPreset.err.find("give the preset"), std::string::npos) << noPreset.err;
}

// compare --rendered --slot: each compressed file measured in one slot alone, one row a file. A
// file compressed as the preset's choice would compress it (ASTC 4x4, fast, with mipmaps) gives
// the same views as that choice measured by compare --rendered (the same blocks, frames and
// chains: the two routes agree); a harder format (8x8) never scores better. A file that cannot be
// read, one of another size, an unknown slot or a slot with no files: named, non-zero.
TEST(Cli, CompareRenderedSlotMeasuresEachFileAlone) {
  const std::string folder = scratchFolder();
  const std::string preset = cobblestonesWithColourCompression(folder, "");
  const std::string colour = sourcePath("samples/cobblestones/cobblestones_color.png");
  for (const char* format : {"astc4x4", "astc8x8"}) {
    CliRun run = runCli({"compress", "--in", q(colour), "--format", format, "--quality", "fast",
                         "--mips", "--quiet", "--out", q(folder + "/" + format + ".ktx2")});
    ASSERT_EQ(run.exitCode, 0) << run.err;
  }
  CliRun slot =
      runCli({"compare", "--rendered", q(preset), "--slot", "color", q(folder + "/astc4x4.ktx2"),
              q(folder + "/astc8x8.ktx2"), "--size", "96x72", "--json", "--progress-lines"});
  ASSERT_EQ(slot.exitCode, 0) << slot.err;
  EXPECT_NE(slot.err.find("progress 1.00"), std::string::npos) << slot.err;
  const QJsonArray rows = QJsonDocument::fromJson(QByteArray::fromStdString(slot.out))
                              .object()
                              .value(QStringLiteral("candidates"))
                              .toArray();
  ASSERT_EQ(rows.size(), 2);
  EXPECT_EQ(rows[0]["format"].toString(), QStringLiteral("astc4x4"));
  CliRun choice =
      runCli({"compare", "--rendered", q(cobblestonesWithColourCompression(folder, "astc4x4")),
              "--size", "96x72", "--json"});
  ASSERT_EQ(choice.exitCode, 0) << choice.err;
  const QJsonArray chosenViews = QJsonDocument::fromJson(QByteArray::fromStdString(choice.out))
                                     .object()
                                     .value(QStringLiteral("views"))
                                     .toArray();
  const QJsonArray fine = rows[0]["views"].toArray(), coarse = rows[1]["views"].toArray();
  ASSERT_EQ(chosenViews.size(), 3);
  ASSERT_EQ(fine.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const std::string name = fine[i]["view"].toString().toStdString();
    EXPECT_GT(fine[i]["flip"].toDouble(), 0.0) << name;
    EXPECT_DOUBLE_EQ(fine[i]["flip"].toDouble(), chosenViews[i]["flip"].toDouble()) << name;
    EXPECT_DOUBLE_EQ(fine[i]["psnr"].toDouble(), chosenViews[i]["psnr"].toDouble()) << name;
    EXPECT_GE(coarse[i]["flip"].toDouble(), fine[i]["flip"].toDouble()) << name;
  }
  EXPECT_GE(rows[1]["flip"].toDouble(), rows[0]["flip"].toDouble());

  CliRun missing = runCli({"compare", "--rendered", q(preset), "--slot", "color",
                           q(folder + "/astc4x4.ktx2"), q(folder + "/absent.ktx2")});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("absent.ktx2"), std::string::npos) << missing.err;
  core::Image small(64, 64, 1, core::ColorSpace::Linear);
  std::fill(small.data(), small.data() + small.valueCount(), 0.5f);
  ASSERT_TRUE(core::saveImage(small, folder + "/small.png", core::SampleFormat::UInt8).ok());
  ASSERT_EQ(runCli({"compress", "--in", q(folder + "/small.png"), "--format", "bc4", "--quiet",
                    "--out", q(folder + "/small.ktx2")})
                .exitCode,
            0);
  CliRun otherSize =
      runCli({"compare", "--rendered", q(preset), "--slot", "height", q(folder + "/small.ktx2")});
  EXPECT_EQ(otherSize.exitCode, 1);
  EXPECT_NE(otherSize.err.find("small.ktx2: 64x64 texels"), std::string::npos) << otherSize.err;
  CliRun unknown =
      runCli({"compare", "--rendered", q(preset), "--slot", "colour", q(folder + "/astc4x4.ktx2")});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("colour"), std::string::npos) << unknown.err;
  CliRun noFiles = runCli({"compare", "--rendered", q(preset), "--slot", "color"});
  EXPECT_EQ(noFiles.exitCode, 2);
  EXPECT_NE(noFiles.err.find("FILE.ktx2"), std::string::npos) << noFiles.err;
}

// --shading pbr with --format exr writes the linear radiance, unclamped: the highlight of a
// smooth metal on a sphere is far brighter than 1 (GGX's peak at roughness 0.2 is about 200 per
// steradian). A shading that does not exist is refused with the choices.
// --orm fills the AO, roughness and metallic slots from one file's R, G and B: the render
// equals the one from the three maps given apart (so each channel went to its slot), and
// differs from one with the channels' maps swapped. A grey file is refused, named.
TEST(Cli, OrmRendersAsItsThreeMapsGivenApart) {
  const std::string folder = scratchFolder() + "/cli-orm";
  std::filesystem::create_directories(folder);
  core::Image orm(32, 32, 3), ao(32, 32, 1), roughness(32, 32, 1), metallic(32, 32, 1);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      ao.at(x, y, 0) = orm.at(x, y, 0) = 0.3f + 0.7f * float(x) / 31.0f;
      roughness.at(x, y, 0) = orm.at(x, y, 1) = 0.1f + 0.8f * float(y) / 31.0f;
      metallic.at(x, y, 0) = orm.at(x, y, 2) = float((x / 8 + y / 8) % 2);
    }
  }
  const auto save = [&](const core::Image& image, const std::string& name) {
    // 16-bit: saveImage dithers 8-bit files, differently for an RGB file and a grey one.
    EXPECT_TRUE(core::saveImage(image, folder + "/" + name, core::SampleFormat::UInt16).ok());
    return q(folder + "/" + name);
  };
  const QString ormFile = save(orm, "stone_orm.png"), aoFile = save(ao, "ao.png"),
                roughFile = save(roughness, "rough.png"), metalFile = save(metallic, "metal.png");
  const auto render = [&](const QString& out, const QStringList& maps) {
    CliRun run = runCli(QStringList{QStringLiteral("render"), QStringLiteral("--mesh"),
                                    QStringLiteral("sphere"), QStringLiteral("--size"),
                                    QStringLiteral("96x96"), QStringLiteral("--out"),
                                    q(folder + "/" + out.toStdString())} +
                        maps);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return core::loadImage(folder + "/" + out.toStdString()).value();
  };
  const core::Image packed = render(QStringLiteral("orm.exr"), {QStringLiteral("--orm"), ormFile});
  const core::Image apart = render(QStringLiteral("apart.exr"),
                                   {QStringLiteral("--ao"), aoFile, QStringLiteral("--roughness"),
                                    roughFile, QStringLiteral("--metallic"), metalFile});
  const core::Image swapped =
      render(QStringLiteral("swapped.exr"),
             {QStringLiteral("--ao"), roughFile, QStringLiteral("--roughness"), aoFile,
              QStringLiteral("--metallic"), metalFile});
  EXPECT_TRUE(packed == apart);
  EXPECT_FALSE(packed == swapped);

  core::Image grey(8, 8, 1);
  const QString greyFile = save(grey, "grey_orm.png");
  CliRun refused = runCli({QStringLiteral("render"), QStringLiteral("--orm"), greyFile,
                           QStringLiteral("--out"), q(folder + "/x.png")});
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("grey_orm.png"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("not an ORM texture"), std::string::npos) << refused.err;
}

TEST(Cli, PbrShadingWritesUnclampedLinearRadianceToExr) {
  const std::string folder = scratchFolder();
  const std::string out = folder + "/metal.exr";
  CliRun run =
      runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--mesh"),
              QStringLiteral("sphere"), QStringLiteral("--shading"), QStringLiteral("pbr"),
              QStringLiteral("--set"), QStringLiteral("metallic=1"), QStringLiteral("--set"),
              QStringLiteral("roughness=0.2"), QStringLiteral("--size"), QStringLiteral("128x128"),
              QStringLiteral("--out"), q(out)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  core::Result<core::Image> image = core::loadImage(out);
  ASSERT_TRUE(image.ok()) << image.error();
  float brightest = 0.0f;
  for (int y = 0; y < image->height(); ++y)
    for (int x = 0; x < image->width(); ++x)
      brightest = std::max(brightest, image->at(x, y, 0));
  EXPECT_GT(brightest, 4.0f);

  run = runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--shading"),
                QStringLiteral("glossy"), QStringLiteral("--out"), q(folder + "/x.png")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
  EXPECT_NE(run.err.find("pbr"), std::string::npos) << run.err;
  run = runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--tonemap"),
                QStringLiteral("filmic"), QStringLiteral("--out"), q(folder + "/x.png")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
  EXPECT_NE(run.err.find("neutral"), std::string::npos) << run.err;
  run = runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--exposure"),
                QStringLiteral("12"), QStringLiteral("--out"), q(folder + "/x.png")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
  // Exposure and tone mapping change the PNG, never the EXR (radiance before them).
  const auto renderWith = [&](const QString& target, const QStringList& extra) {
    return runCli(QStringList{QStringLiteral("render"), q(samplePreset("bricks")),
                              QStringLiteral("--size"), QStringLiteral("64x64"),
                              QStringLiteral("--out"), target} +
                  extra);
  };
  const QStringList display = {QStringLiteral("--exposure"), QStringLiteral("1.5"),
                               QStringLiteral("--tonemap"), QStringLiteral("neutral")};
  ASSERT_EQ(renderWith(q(folder + "/plain.png"), {}).exitCode, 0);
  ASSERT_EQ(renderWith(q(folder + "/exposed.png"), display).exitCode, 0);
  ASSERT_EQ(renderWith(q(folder + "/plain.exr"), {}).exitCode, 0);
  ASSERT_EQ(renderWith(q(folder + "/exposed.exr"), display).exitCode, 0);
  const core::Image plainPng = core::loadImage(folder + "/plain.png").value();
  const core::Image exposedPng = core::loadImage(folder + "/exposed.png").value();
  EXPECT_FALSE(plainPng == exposedPng);
  EXPECT_TRUE(core::loadImage(folder + "/plain.exr").value() ==
              core::loadImage(folder + "/exposed.exr").value());
}

// The environment options: image-based light is linear in --environment-intensity (the EXR at
// 0.5 is half the EXR at 1, with the directional light off); --background environment shows the
// overcast sky behind the material (far above the plain gradient's 0.05); a missing or unusable
// file stops the command naming it, bad values are usage errors.
TEST(Cli, EnvironmentOptionsLightAndShowTheEnvironment) {
  const std::string folder = scratchFolder();
  const auto render = [&](const std::string& out, const QStringList& extra) {
    return runCli(QStringList{QStringLiteral("render"), q(samplePreset("bricks")),
                              QStringLiteral("--mesh"), QStringLiteral("sphere"),
                              QStringLiteral("--shading"), QStringLiteral("pbr"),
                              QStringLiteral("--size"), QStringLiteral("64x64"),
                              QStringLiteral("--out"), q(out)} +
                  extra);
  };
  const QStringList sky = {QStringLiteral("--environment"), QStringLiteral("sky"),
                           QStringLiteral("--light-intensity"), QStringLiteral("0")};
  ASSERT_EQ(render(folder + "/full.exr", sky).exitCode, 0);
  ASSERT_EQ(
      render(folder + "/half.exr",
             sky + QStringList{QStringLiteral("--environment-intensity"), QStringLiteral("0.5")})
          .exitCode,
      0);
  const core::Image full = core::loadImage(folder + "/full.exr").value();
  const core::Image half = core::loadImage(folder + "/half.exr").value();
  float brightest = 0.0f, worst = 0.0f;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      brightest = std::max(brightest, full.at(x, y, 1));
      worst = std::max(worst, std::abs(half.at(x, y, 1) - 0.5f * full.at(x, y, 1)));
    }
  }
  EXPECT_GT(brightest, 0.1f);
  EXPECT_LT(worst, 1e-3f * brightest);

  // Level, the top of the picture looks 20 degrees up: the sky there is (1 + 2 sin 20) / 3 of
  // the zenith's radiance, 0.56, sRGB 0.77.
  const QStringList level = sky + QStringList{QStringLiteral("--pitch"), QStringLiteral("0")};
  ASSERT_EQ(render(folder + "/plain.png", level).exitCode, 0);
  ASSERT_EQ(render(folder + "/sky.png", level + QStringList{QStringLiteral("--background"),
                                                            QStringLiteral("environment")})
                .exitCode,
            0);
  EXPECT_LT(core::loadImage(folder + "/plain.png").value().at(1, 1, 1), 0.3f);
  EXPECT_GT(core::loadImage(folder + "/sky.png").value().at(1, 1, 1), 0.6f);

  const std::string missing = folder + "/nowhere.exr";
  CliRun run = render(folder + "/x.png", {QStringLiteral("--environment"), q(missing)});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
  const std::string square = folder + "/square.exr";
  ASSERT_TRUE(core::saveImage(core::Image(8, 8, 3), square, core::SampleFormat::Half).ok());
  run = render(folder + "/x.png", {QStringLiteral("--environment"), q(square)});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find(square), std::string::npos) << run.err;
  run =
      render(folder + "/x.png", {QStringLiteral("--environment-intensity"), QStringLiteral("20")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
  run = render(folder + "/x.png", {QStringLiteral("--background"), QStringLiteral("starfield")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
  EXPECT_NE(run.err.find("blurred"), std::string::npos) << run.err;
  run = render(folder + "/x.png", {QStringLiteral("--light-intensity"), QStringLiteral("-1")});
  EXPECT_EQ(run.exitCode, 2) << run.err;
}

TEST(Cli, ErrorViewPrintsTheErrorAgainstTheExactTrace) {
  // Tiled a tenth of a time, the 1024-texel map is magnified on this small frame and compared.
  const std::string out = scratchFolder() + "/error.png";
  CliRun run = runCli({QStringLiteral("render"), q(samplePreset("tiles")), QStringLiteral("--view"),
                       QStringLiteral("error"), QStringLiteral("--size"), QStringLiteral("160x100"),
                       QStringLiteral("--set"), QStringLiteral("tiling=0.1"),
                       QStringLiteral("--out"), q(out)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("UV error against the exact trace: mean"), std::string::npos) << run.out;
  EXPECT_TRUE(core::loadImage(out).ok());
  // As the preset tiles it, every pixel reads the map minified: nothing to compare, and the
  // summary says why instead of printing an error of the mip chain.
  run = runCli({QStringLiteral("render"), q(samplePreset("tiles")), QStringLiteral("--view"),
                QStringLiteral("error"), QStringLiteral("--size"), QStringLiteral("160x100"),
                QStringLiteral("--out"), q(out)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("reads the height map minified (mip level 1 or more)"), std::string::npos)
      << run.out;
}

TEST(Cli, RenderRefusesBadTechniquesViewsAndMeshes) {
  const std::string folder = scratchFolder();
  std::ofstream(folder + "/nouv.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const QString preset = q(samplePreset("bricks"));
  const QString out = q(folder + "/x.png");
  const std::vector<std::pair<QStringList, std::string>> cases = {
      {{QStringLiteral("--technique"), QStringLiteral("warp")}, "pom"},
      {{QStringLiteral("--view"), QStringLiteral("xray")}, "steps"},
      {{QStringLiteral("--mesh"), q(folder + "/nouv.obj")}, "texture coordinates"},
      {{QStringLiteral("--format"), QStringLiteral("exr")}, ".exr"},
  };
  for (const auto& [options, mention] : cases) {
    CliRun run = runCli(
        QStringList{QStringLiteral("render"), preset, QStringLiteral("--out"), out} + options);
    EXPECT_FALSE(run.crashed);
    EXPECT_NE(run.exitCode, 0) << options.join(QLatin1Char(' ')).toStdString();
    EXPECT_NE(run.err.find(mention), std::string::npos)
        << options.join(QLatin1Char(' ')).toStdString() << "\nstderr: " << run.err;
  }
}

TEST(Cli, GenerateMakesEveryMapAtFullPrecision) {
  const std::string folder = scratchFolder();
  const QString height = q(sourcePath("samples/tiles/tiles_height.png"));
  const QString normal = q(sourcePath("samples/tiles/tiles_normal.png"));
  const QString color = q(sourcePath("samples/tiles/tiles_color.png"));
  const struct {
    QStringList arguments;
    std::string out;
    int bits;
    int channels;
  } cases[] = {
      {{"normal", "--in", height, "--kernel", "scharr", "--strength", "15", "--convention",
        "directx", "--edge", "wrap"},
       "n.png",
       16,
       3},
      {{"height", "--in", normal}, "h.exr", 32, 1},
      {{"height-from-color", "--in", color, "--radius", "32", "--invert", "true"}, "hc.tif", 16, 1},
      {{"ao", "--in", height, "--radius", "8", "--directions", "8"}, "ao.jpg", 8, 1},
      {{"curvature", "--in", normal, "--from", "normal"}, "c.png", 16, 1},
      {{"pack", "--normal", normal, "--height", height}, "nh.png", 16, 4},
  };
  for (const auto& c : cases) {
    const std::string out = folder + "/" + c.out;
    CliRun run = runCli(QStringList{QStringLiteral("generate")} + c.arguments +
                        QStringList{QStringLiteral("--out"), q(out)});
    ASSERT_EQ(run.exitCode, 0) << c.out << ": " << run.err;
    core::Result<core::ImageFileInfo> info = core::readImageInfo(out);
    ASSERT_TRUE(info.ok()) << info.error();
    EXPECT_EQ(info->bitsPerChannel, c.bits) << c.out;
    EXPECT_EQ(info->channels, c.channels) << c.out;
    EXPECT_EQ(info->width, 1024) << c.out;
  }
  // Height from normal reports the relief's depth.
  CliRun depth =
      runCli({QStringLiteral("generate"), QStringLiteral("height"), QStringLiteral("--in"), normal,
              QStringLiteral("--out"), q(folder + "/depth.png")});
  EXPECT_NE(depth.out.find("relief depth"), std::string::npos) << depth.out;
}

// compress --mip-filter kaiser: the chain is written (the same size as the box's), and a name
// that is no filter is refused before anything is written.
TEST(Cli, CompressTakesTheKaiserMipFilter) {
  const std::string folder = scratchFolder();
  const QString colour = q(sourcePath("samples/tiles/tiles_color.png"));
  CliRun kaiser = runCli({"compress", "--in", colour, "--format", "bc1", "--mips", "--mip-filter",
                          "kaiser", "--out", q(folder + "/k.dds")});
  ASSERT_EQ(kaiser.exitCode, 0) << kaiser.err;
  CliRun box = runCli(
      {"compress", "--in", colour, "--format", "bc1", "--mips", "--out", q(folder + "/b.dds")});
  ASSERT_EQ(box.exitCode, 0) << box.err;
  EXPECT_EQ(std::filesystem::file_size(folder + "/k.dds"),
            std::filesystem::file_size(folder + "/b.dds"));
  EXPECT_NE(readBytes(folder + "/k.dds"), readBytes(folder + "/b.dds"));
  CliRun bad = runCli({"compress", "--in", colour, "--format", "bc1", "--mips", "--mip-filter",
                       "lanczos", "--out", q(folder + "/x.dds")});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("not box or kaiser"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/x.dds"));
}

// compress --roughness-from-normals: a roughness map's mips widened by the normal map's spread
// are rougher than the plain chain's far down (the cobblestones' bumps), level 0 is the map as it
// is; without --mips it is a usage error, and a normal map of another size is refused by name.
TEST(Cli, CompressFoldsTheNormalsSpreadIntoRoughness) {
  const std::string folder = scratchFolder();
  core::Image flat(1024, 1024, 1);
  for (std::size_t i = 0; i < flat.valueCount(); ++i)
    flat.data()[i] = 0.25f;
  ASSERT_TRUE(core::saveImage(flat, folder + "/rough.png"));
  const QString rough = q(folder + "/rough.png");
  const QString normals = q(sourcePath("samples/cobblestones/cobblestones_normal.png"));
  CliRun folded = runCli({"compress", "--in", rough, "--format", "bc4", "--mips",
                          "--roughness-from-normals", normals, "--out", q(folder + "/f.ktx2")});
  ASSERT_EQ(folded.exitCode, 0) << folded.err;
  CliRun plain = runCli(
      {"compress", "--in", rough, "--format", "bc4", "--mips", "--out", q(folder + "/p.ktx2")});
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  const auto levelMean = [](const std::string& path, int level) {
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path);
    EXPECT_TRUE(texture.ok()) << texture.error();
    const core::Image decoded = core::decodeAsMap(texture.value(), level).value();
    double sum = 0.0;
    for (std::size_t i = 0; i < decoded.valueCount(); ++i)
      sum += decoded.data()[i];
    return sum / double(decoded.valueCount());
  };
  EXPECT_NEAR(levelMean(folder + "/f.ktx2", 0), 0.25, 1.0 / 255.0);
  EXPECT_NEAR(levelMean(folder + "/p.ktx2", 4), 0.25, 1.0 / 255.0);
  EXPECT_GT(levelMean(folder + "/f.ktx2", 4), 0.35) << "64 texels a level-4 texel: bumps fold in";
  CliRun noMips = runCli({"compress", "--in", rough, "--format", "bc4", "--roughness-from-normals",
                          normals, "--out", q(folder + "/x.ktx2")});
  EXPECT_EQ(noMips.exitCode, 2);
  EXPECT_NE(noMips.err.find("--mips"), std::string::npos) << noMips.err;
  core::Image small(512, 512, 1);
  ASSERT_TRUE(core::saveImage(small, folder + "/small.png"));
  CliRun mismatch =
      runCli({"compress", "--in", q(folder + "/small.png"), "--format", "bc4", "--mips",
              "--roughness-from-normals", normals, "--out", q(folder + "/y.ktx2")});
  EXPECT_EQ(mismatch.exitCode, 1);
  EXPECT_NE(mismatch.err.find("small.png"), std::string::npos) << mismatch.err;
  EXPECT_NE(mismatch.err.find("512x512"), std::string::npos) << mismatch.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/y.ktx2"));
}

// compress --alpha-coverage: the cut-out's coverage of the cutoff survives down the chain (level
// 3, 64x64, within 1% of the texels) where the plain chain thins it; without --mips, outside
// 0..1 or on a map without alpha it is a usage error.
// --rdo: the file after Zstandard shrinks as lambda rises and decodes to a close picture; 0 is
// the plain file byte for byte; a negative lambda, one above the limit, or a format without RDO
// are command-line errors.
TEST(Cli, CompressRdoTradesQualityForSize) {
  const std::string folder = scratchFolder();
  // A 256x256 corner of the tiles: enough blocks to repeat, quick under the sanitizers.
  core::Result<core::Image> tiles = core::loadImage(sourcePath("samples/tiles/tiles_color.png"));
  ASSERT_TRUE(tiles.ok()) << tiles.error();
  core::Image corner(256, 256, 3, tiles->colorSpace());
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      for (int c = 0; c < 3; ++c)
        corner.at(x, y, c) = tiles->at(x, y, c);
    }
  }
  ASSERT_TRUE(core::saveImage(corner, folder + "/tiles_corner.png"));
  const QString in = q(folder + "/tiles_corner.png");
  const auto compress = [&](const char* lambda) {
    const std::string out = folder + "/rdo_" + lambda + ".ktx2";
    CliRun run = runCli({"compress", "--in", in, "--format", "bc1", "--zstd", "19", "--rdo", lambda,
                         "--out", q(out)});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return out;
  };
  const std::string off = compress("0"), mild = compress("4"), strong = compress("64");
  CliRun plain = runCli({"compress", "--in", in, "--format", "bc1", "--zstd", "19", "--out",
                         q(folder + "/plain.ktx2")});
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(readBytes(off), readBytes(folder + "/plain.ktx2"));
  EXPECT_LT(std::filesystem::file_size(mild), std::filesystem::file_size(off));
  EXPECT_LT(std::filesystem::file_size(strong), std::filesystem::file_size(mild));
  const auto psnr = [&](const std::string& file) {
    CliRun run = runCli({"compare", in, q(file), "--json"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out))
        .object()
        .value(QStringLiteral("psnr"))
        .toDouble();
  };
  EXPECT_GT(psnr(mild), psnr(off) - 0.5);
  EXPECT_LT(psnr(strong), psnr(off));
  for (const QStringList& bad : {QStringList{"--format", "bc1", "--rdo", "-1"},
                                 QStringList{"--format", "bc1", "--rdo", "5000"},
                                 QStringList{"--format", "etc2", "--rdo", "4"}}) {
    CliRun run =
        runCli(QStringList{"compress", "--in", in, "--out", q(folder + "/bad.ktx2")} << bad);
    EXPECT_EQ(run.exitCode, 2) << bad.join(' ').toStdString();
    EXPECT_NE(run.err.find("--rdo"), std::string::npos) << run.err;
  }
}

// BC6H from an EXR: the studio environment (13 stops) written as a float EXR, compressed into
// KTX2 and DDS; the metrics judge it in float (exposure PSNR, log2 error) and the files decode
// as BC6H. A NaN in the input is clamped with a warning naming the file. An 8-bit map is refused
// with exit 2 and nothing written unless --allow-8bit; --rdo with BC6H is refused too.
TEST(Cli, CompressBc6hFromExr) {
  const std::string folder = scratchFolder();
  core::Image studio = core::makeBuiltInEnvironment(core::BuiltInEnvironment::Studio, 64);
  studio.at(3, 3, 0) = std::numeric_limits<float>::quiet_NaN();
  studio.setSourceBitsPerChannel(32);
  ASSERT_TRUE(core::saveImage(studio, folder + "/studio.exr"));
  const QString in = q(folder + "/studio.exr");
  CliRun run = runCli({"compress", "--in", in, "--format", "bc6h", "--zstd", "19", "--mips",
                       "--out", q(folder + "/studio.ktx2"), "--metrics", "json"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("studio.exr"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("not numbers"), std::string::npos) << run.err;
  const QJsonObject hdr = QJsonDocument::fromJson(QByteArray::fromStdString(run.out))
                              .object()
                              .value(QStringLiteral("hdr"))
                              .toObject();
  EXPECT_GT(hdr.value(QStringLiteral("exposurePsnr")).toDouble(), 40.0) << run.out;
  EXPECT_LT(hdr.value(QStringLiteral("meanLog2Error")).toDouble(), 0.05) << run.out;
  for (const char* file : {"/studio.ktx2", "/studio.dds"}) {
    if (std::string(file) == "/studio.dds") {
      CliRun dds =
          runCli({"compress", "--in", in, "--format", "bc6h-signed", "--out", q(folder + file)});
      ASSERT_EQ(dds.exitCode, 0) << dds.err;
    }
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(folder + file);
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_TRUE(core::isHalfFloatFormat(texture->format)) << file;
  }

  core::Image grey(16, 16, 1);
  ASSERT_TRUE(core::saveImage(grey, folder + "/grey.png"));
  CliRun eightBit = runCli({"compress", "--in", q(folder + "/grey.png"), "--format", "bc6h",
                            "--height", "--out", q(folder + "/grey.ktx2")});
  EXPECT_EQ(eightBit.exitCode, 2) << eightBit.err;
  EXPECT_NE(eightBit.err.find("grey.png"), std::string::npos) << eightBit.err;
  EXPECT_NE(eightBit.err.find("8-bit"), std::string::npos) << eightBit.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/grey.ktx2"));
  CliRun allowed = runCli({"compress", "--in", q(folder + "/grey.png"), "--format", "bc6h",
                           "--height", "--allow-8bit", "--out", q(folder + "/grey.ktx2")});
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
  CliRun rdo = runCli({"compress", "--in", in, "--format", "bc6h", "--zstd", "19", "--rdo", "8",
                       "--out", q(folder + "/rdo.ktx2")});
  EXPECT_EQ(rdo.exitCode, 2) << rdo.err;
  EXPECT_NE(rdo.err.find("--rdo"), std::string::npos) << rdo.err;
}

TEST(Cli, CompressKeepsAlphaCoverage) {
  const std::string folder = scratchFolder();
  core::Image leaves(512, 512, 4);
  for (int y = 0; y < 512; ++y) {
    for (int x = 0; x < 512; ++x) {
      const double stroke = std::abs(std::sin(x / 9.0 + 3.0 * std::sin(y / 13.0)));
      for (int c = 0; c < 3; ++c)
        leaves.at(x, y, c) = 0.3f;
      leaves.at(x, y, 3) = float(std::max(0.0, 1.0 - 4.0 * stroke));
    }
  }
  ASSERT_TRUE(core::saveImage(leaves, folder + "/leaves.png"));
  const QString in = q(folder + "/leaves.png");
  const double coverage = core::alphaCoverage(leaves, 0.5f);
  const auto levelCoverage = [&](const std::string& path) {
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path);
    EXPECT_TRUE(texture.ok()) << texture.error();
    return core::alphaCoverage(core::decodeLevel(texture.value(), 3).value(), 0.5f);
  };
  CliRun kept = runCli({"compress", "--in", in, "--format", "bc7", "--mips", "--alpha-coverage",
                        "0.5", "--out", q(folder + "/kept.ktx2")});
  ASSERT_EQ(kept.exitCode, 0) << kept.err;
  CliRun plain =
      runCli({"compress", "--in", in, "--format", "bc7", "--mips", "--out", q(folder + "/p.ktx2")});
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_NEAR(levelCoverage(folder + "/kept.ktx2"), coverage, 0.01);
  EXPECT_LT(levelCoverage(folder + "/p.ktx2"), coverage - 0.02) << "the plain chain thins it";
  const QString rgb = q(sourcePath("samples/tiles/tiles_color.png"));
  for (const QStringList& bad : {QStringList{"--in", in, "--alpha-coverage", "0.5"},
                                 QStringList{"--in", in, "--mips", "--alpha-coverage", "1.5"},
                                 QStringList{"--in", rgb, "--mips", "--alpha-coverage", "0.5"}}) {
    CliRun run =
        runCli(QStringList{"compress", "--format", "bc7", "--out", q(folder + "/x.ktx2")} + bad);
    EXPECT_EQ(run.exitCode, 2) << bad.join(' ').toStdString();
    EXPECT_NE(run.err.find("alpha"), std::string::npos) << run.err;
  }
}

// generate tileable: a crop of a sample set (which no longer tiles) comes out as tiles under the
// same names, at the inputs' bit depths, with the seams' numbers; an --out-dir that would write
// over the inputs, and maps of different sizes, are refused with the files named and nothing
// written.
TEST(Cli, TileableMakesASetTileUnderItsOwnNames) {
  const std::string folder = scratchFolder();
  const auto crop = [&](const std::string& sample, const std::string& name, int size) {
    core::Result<core::Image> full = core::loadImage(sourcePath(sample));
    EXPECT_TRUE(full) << full.error();
    core::Image part(size, size, full->channels(), full->colorSpace());
    part.setSourceBitsPerChannel(full->sourceBitsPerChannel());
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        for (int c = 0; c < full->channels(); ++c)
          part.at(x, y, c) = full->at(x + 137, y + 211, c);
    EXPECT_TRUE(core::saveImage(part, folder + "/" + name));
    return q(folder + "/" + name);
  };
  const QString color = crop("samples/cobblestones/cobblestones_color.png", "stones.png", 320);
  const QString height = crop("samples/cobblestones/cobblestones_height.png", "stones_h.png", 320);
  const QString out = q(folder + "/tiles");
  CliRun run =
      runCli({"generate", "tileable", "--in", color, "--also", height, "--out-dir", out, "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const QJsonObject report = QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
  for (const char* axis : {"horizontal", "vertical"}) {
    const QJsonObject numbers = report.value(QLatin1String(axis)).toObject();
    EXPECT_FALSE(numbers.value("alreadyTiled").toBool()) << axis;
    EXPECT_GT(numbers.value("seamBefore").toDouble(), 1.5) << axis;
    EXPECT_LE(numbers.value("seamAfter").toDouble(), 1.2) << axis;
  }
  EXPECT_EQ(readImageBits(folder + "/tiles/stones.png"), 8);
  EXPECT_EQ(readImageBits(folder + "/tiles/stones_h.png"), 16);

  // Into the inputs' own folder: refused, the inputs untouched.
  const std::string before = readBytes(color.toStdString());
  CliRun over = runCli({"generate", "tileable", "--in", color, "--out-dir", q(folder)});
  EXPECT_EQ(over.exitCode, 2);
  EXPECT_NE(over.err.find("over itself"), std::string::npos) << over.err;
  EXPECT_EQ(readBytes(color.toStdString()), before);

  // Maps of different sizes: the message says so and names the files; no folder made.
  const QString small = crop("samples/cobblestones/cobblestones_height.png", "small.png", 200);
  CliRun mismatch = runCli(
      {"generate", "tileable", "--in", color, "--also", small, "--out-dir", q(folder + "/never")});
  EXPECT_EQ(mismatch.exitCode, 1);
  EXPECT_NE(mismatch.err.find("differ in size"), std::string::npos) << mismatch.err;
  EXPECT_NE(mismatch.err.find("small.png"), std::string::npos) << mismatch.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/never"));
}

// generate pack --layout: the Unity HDRP mask map from an AO and a roughness file, read back
// texel by texel (16-bit PNG: within half a step); a channel term overrides the layout's.
TEST(Cli, PackLayoutsPutEachMapInItsChannel) {
  const std::string folder = scratchFolder();
  core::Image ao(16, 8, 1), roughness(16, 8, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      ao.at(x, y, 0) = float(x) / 15.0f;
      roughness.at(x, y, 0) = float(y) / 7.0f;
    }
  }
  ASSERT_TRUE(core::saveImage(ao, folder + "/ao.png", core::SampleFormat::UInt16).ok());
  ASSERT_TRUE(core::saveImage(roughness, folder + "/rough.png", core::SampleFormat::UInt16).ok());
  const std::string out = folder + "/mask.png";
  CliRun run =
      runCli({QStringLiteral("generate"), QStringLiteral("pack"), QStringLiteral("--layout"),
              QStringLiteral("unity-mask"), QStringLiteral("--ao"), q(folder + "/ao.png"),
              QStringLiteral("--roughness"), q(folder + "/rough.png"), QStringLiteral("--b"),
              QStringLiteral("0.5"), QStringLiteral("--out"), q(out)});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("no metallic map: its neutral value 0 was used"), std::string::npos)
      << run.out;
  core::Result<core::Image> mask = core::loadImage(out);
  ASSERT_TRUE(mask.ok()) << mask.error();
  ASSERT_EQ(mask->channels(), 4);
  const float step = 0.5f / 65535.0f + 1e-6f;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      EXPECT_NEAR(mask->at(x, y, 0), 0.0f, step);                          // metallic
      EXPECT_NEAR(mask->at(x, y, 1), ao.at(x, y, 0), step);                // occlusion
      EXPECT_NEAR(mask->at(x, y, 2), 0.5f, step);                          // --b
      EXPECT_NEAR(mask->at(x, y, 3), 1.0f - roughness.at(x, y, 0), step);  // smoothness
    }
  }
  CliRun bad = runCli({QStringLiteral("generate"), QStringLiteral("pack"), QStringLiteral("--r"),
                       QStringLiteral("metal.r"), QStringLiteral("--ao"), q(folder + "/ao.png"),
                       QStringLiteral("--out"), q(folder + "/bad.png")});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("no map called 'metal'"), std::string::npos) << bad.err;
}

// Scriptable output: piped, a long command prints its result line and no progress; --quiet
// (anywhere on the line) drops the informational lines but not the results asked for (JSON
// metrics) nor errors; on a terminal (util-linux's script gives one) the progress line is drawn
// on standard error and erased before the result.
TEST(Cli, ProgressOnlyOnATerminalAndQuietOnlyResults) {
  const std::string folder = scratchFolder();
  const QString colour = q(sourcePath("samples/bricks/bricks_color.png"));
  const QStringList compress = {
      QStringLiteral("compress"), QStringLiteral("--in"), colour,
      QStringLiteral("--format"), QStringLiteral("bc1"),  QStringLiteral("--out"),
      q(folder + "/c.dds")};
  CliRun piped = runCli(compress);
  ASSERT_EQ(piped.exitCode, 0) << piped.err;
  EXPECT_NE(piped.out.find("c.dds: BC1"), std::string::npos) << piped.out;
  EXPECT_EQ(piped.err.find('\r'), std::string::npos) << piped.err;
  EXPECT_EQ(piped.err.find('%'), std::string::npos) << piped.err;

  CliRun quiet = runCli(QStringList{QStringLiteral("--quiet")} + compress);
  EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.out, "");
  CliRun quietJson =
      runCli(compress + QStringList{QStringLiteral("-q"), QStringLiteral("--metrics"),
                                    QStringLiteral("json")});
  EXPECT_EQ(quietJson.exitCode, 0) << quietJson.err;
  EXPECT_TRUE(QJsonDocument::fromJson(QByteArray::fromStdString(quietJson.out)).isObject())
      << quietJson.out;
  CliRun quietError =
      runCli({QStringLiteral("-q"), QStringLiteral("compress"), QStringLiteral("--in"),
              q(folder + "/missing.png"), QStringLiteral("--format"), QStringLiteral("bc1"),
              QStringLiteral("--out"), q(folder + "/m.dds")});
  EXPECT_EQ(quietError.exitCode, 1);
  EXPECT_NE(quietError.err.find("missing.png"), std::string::npos) << quietError.err;

  // A terminal: `script -qec COMMAND /dev/null` runs COMMAND on a pseudo-terminal and copies
  // what it prints (stdout and stderr alike) to its own standard output.
  QProcess script;
  QStringList command = {QStringLiteral(RELIEF_CLI_PATH)};
  command += compress;
  script.start(QStringLiteral("script"), {QStringLiteral("-qec"), command.join(QLatin1Char(' ')),
                                          QStringLiteral("/dev/null")});
  if (!script.waitForStarted(10000))
    GTEST_SKIP() << "util-linux's script is not installed: no pseudo-terminal to test with";
  ASSERT_TRUE(script.waitForFinished(120000));
  EXPECT_EQ(script.exitCode(), 0);
  const std::string terminal = script.readAllStandardOutput().toStdString();
  EXPECT_NE(terminal.find("compress bricks_color.png ["), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("100%"), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("\r\033[K"), std::string::npos) << terminal;  // erased
  EXPECT_NE(terminal.find("c.dds: BC1"), std::string::npos) << terminal;
}

// --json on every command that reports something: one object on stdout that parses, with the
// command's facts (the output's size, the relief depth, the export's main file, the error view's
// statistics) and nothing else printed there.
TEST(Cli, ReportingCommandsPrintOneJsonObject) {
  const std::string folder = scratchFolder();
  const auto object = [](const CliRun& run) {
    EXPECT_EQ(run.exitCode, 0) << run.err;
    QJsonParseError error{};
    const QJsonDocument document =
        QJsonDocument::fromJson(QByteArray::fromStdString(run.out), &error);
    EXPECT_EQ(error.error, QJsonParseError::NoError) << run.out;
    return document.object();
  };
  const QJsonObject height =
      object(runCli({QStringLiteral("generate"), QStringLiteral("height"), QStringLiteral("--in"),
                     q(sourcePath("samples/bricks/bricks_normal.png")), QStringLiteral("--out"),
                     q(folder + "/h.png"), QStringLiteral("--json")}));
  EXPECT_EQ(height.value(QStringLiteral("width")).toInt(), 1024);
  EXPECT_GT(height.value(QStringLiteral("depthTexels")).toDouble(), 1.0);
  const QJsonObject exported =
      object(runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
                     QStringLiteral("--to"), QStringLiteral("godot"), QStringLiteral("--out"),
                     q(folder + "/godot"), QStringLiteral("--json")}));
  EXPECT_TRUE(
      exported.value(QStringLiteral("written")).toString().endsWith(QStringLiteral(".tres")));
  const QJsonObject error =
      object(runCli({QStringLiteral("render"), q(samplePreset("tiles")), QStringLiteral("--view"),
                     QStringLiteral("error"), QStringLiteral("--size"), QStringLiteral("96x64"),
                     QStringLiteral("--set"), QStringLiteral("tiling=0.1"),  // magnified: compared
                     QStringLiteral("--out"), q(folder + "/e.png"), QStringLiteral("--json")}));
  const QJsonObject preset = object(runCli({QStringLiteral("preset"), QStringLiteral("validate"),
                                            q(samplePreset("tiles")), QStringLiteral("--json")}));
  EXPECT_TRUE(preset.value(QStringLiteral("valid")).toBool());
  EXPECT_EQ(preset.value(QStringLiteral("maps"))
                .toObject()
                .value(QStringLiteral("height"))
                .toObject()
                .value(QStringLiteral("width"))
                .toInt(),
            1024);
  EXPECT_TRUE(preset.value(QStringLiteral("parameters"))
                  .toObject()
                  .contains(QStringLiteral("heightScale")));
  const QJsonObject stats = error.value(QStringLiteral("uvErrorTexels")).toObject();
  EXPECT_GT(stats.value(QStringLiteral("pixels")).toDouble(), 0.0);
  EXPECT_TRUE(stats.contains(QStringLiteral("minifiedPixels")));
  EXPECT_LE(stats.value(QStringLiteral("mean")).toDouble(),
            stats.value(QStringLiteral("p95")).toDouble() + 1e-9);
  EXPECT_LE(stats.value(QStringLiteral("p95")).toDouble(),
            stats.value(QStringLiteral("max")).toDouble() + 1e-9);
}

TEST(Cli, GenerateExplainsWhatIsWrong) {
  const std::string folder = scratchFolder();
  const QString height = q(sourcePath("samples/tiles/tiles_height.png"));
  const QString out = q(folder + "/x.png");
  const std::vector<std::pair<QStringList, std::string>> usage = {
      {{"generate", "emboss", "--in", height, "--out", out}, "emboss"},
      {{"generate", "normal", "--out", out}, "--in"},
      {{"generate", "normal", "--in", height}, "--out"},
      {{"generate", "normal", "--in", height, "--out", out, "--kernel", "prewitt"}, "kernel"},
      {{"generate", "normal", "--in", height, "--out", out, "--strength", "-3"}, "strength"},
      {{"generate", "pack", "--normal", height, "--height", height, "--out", out, "--swizzle",
        "n.r z.g"},
       "swizzle"},
  };
  for (const auto& [arguments, mention] : usage) {
    CliRun run = runCli(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments.join(QLatin1Char(' ')).toStdString();
    EXPECT_NE(run.err.find(mention), std::string::npos) << run.err;
  }
  CliRun missing = runCli({"generate", "ao", "--in", q(folder + "/nothing.png"), "--out", out});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("nothing.png"), std::string::npos);
  writeBytes(folder + "/zero.png", "");
  CliRun zero = runCli({"generate", "normal", "--in", q(folder + "/zero.png"), "--out", out});
  EXPECT_EQ(zero.exitCode, 1);
  EXPECT_NE(zero.err.find("zero.png: the file is empty"), std::string::npos) << zero.err;
  // A photograph given as a normal map: a warning naming it, and the work still done.
  CliRun photo =
      runCli({"generate", "height", "--in", q(sourcePath("samples/tiles/tiles_color.png")), "--out",
              q(folder + "/photo.png")});
  EXPECT_EQ(photo.exitCode, 0) << photo.err;
  EXPECT_NE(photo.err.find("warning: "), std::string::npos);
  EXPECT_NE(photo.err.find("tiles_color.png"), std::string::npos);
}

TEST(Cli, RenderWithoutADisplaySaysSo) {
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.remove(QStringLiteral("DISPLAY"));
  environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
  const std::string out = scratchFolder() + "/nodisplay.png";
  CliRun run =
      runCli({QStringLiteral("render"), q(samplePreset("bricks")), QStringLiteral("--out"), q(out)},
             environment);
  EXPECT_FALSE(run.crashed);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.err.find("xvfb-run"), std::string::npos) << run.err;
}

TEST(Cli, EditorWithoutADisplaySaysSoInsteadOfCrashing) {
  // Qt aborts when xcb cannot connect and crashes when a QOpenGLWidget gets no context; the
  // editor must check first and explain.
  for (const char* platform : {"", "offscreen"}) {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("DISPLAY"));
    environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QString::fromLatin1(platform));
    if (!*platform)
      environment.remove(QStringLiteral("QT_QPA_PLATFORM"));
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(RELIEF_GUI_PATH), {});
    ASSERT_TRUE(process.waitForFinished(60000));
    EXPECT_EQ(process.exitStatus(), QProcess::NormalExit) << platform;
    EXPECT_NE(process.exitCode(), 0) << platform;
    EXPECT_NE(process.readAllStandardError().indexOf("xvfb-run"), -1) << platform;
  }
}

TEST(Cli, PresetValidateAcceptsTheSamples) {
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    CliRun run =
        runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(samplePreset(name))});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("valid"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("height 1024x1024"), std::string::npos) << run.out;
  }
}

TEST(Cli, PresetValidateNamesTheFileAndEveryProblem) {
  const std::string folder = scratchFolder() + "/validate";
  std::filesystem::create_directories(folder);
  const struct {
    const char* file;
    std::string text;
    const char* problem;
  } cases[] = {
      {"notjson.relief", "this is not json", "not a valid preset"},
      {"truncated.relief", "{\"format\": \"relief-material\", \"version\": 2, \"maps\": {",
       "not a valid preset"},
      {"future.relief", "{\"format\": \"relief-material\", \"version\": 99}", "newer Relief"},
      {"missingmap.relief",
       "{\"format\": \"relief-material\", \"version\": 2,"
       " \"maps\": {\"height\": {\"path\": \"gone_height.png\"}}}",
       "gone_height.png"},
      {"wrongtype.relief",
       "{\"format\": \"relief-material\", \"version\": 2,"
       " \"parameters\": {\"heightScale\": \"deep\"}}",
       "heightScale"},
      {"range.relief",
       "{\"format\": \"relief-material\", \"version\": 2, \"parameters\": {\"tiling\": 1e300}}",
       "tiling"},
  };
  for (const auto& c : cases) {
    const std::string path = folder + "/" + c.file;
    writeBytes(path, c.text);
    CliRun run = runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(path)});
    expectCleanFailure(run, path, c.problem);
    EXPECT_EQ(run.exitCode, 1) << c.file;
  }
}

TEST(Cli, PresetInfoPrintsParametersMapsAndView) {
  CliRun run = runCli({QStringLiteral("preset"), QStringLiteral("info"), q(samplePreset("tiles"))});
  EXPECT_EQ(run.exitCode, 0) << run.err;
  for (const char* expected :
       {"technique: pom", "heightScale", "tiling", "tiles_height.png", "16 bit", "srgb"}) {
    EXPECT_NE(run.out.find(expected), std::string::npos) << expected << " in\n" << run.out;
  }
  CliRun bad =
      runCli({QStringLiteral("preset"), QStringLiteral("explain"), q(samplePreset("tiles"))});
  EXPECT_EQ(bad.exitCode, 2);
}

TEST(Cli, ExportWritesEachKindFromASample) {
  const std::string folder = scratchFolder() + "/export";
  CliRun package =
      runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
              QStringLiteral("--to"), QStringLiteral("package"), QStringLiteral("--out"),
              q(folder + "/package"), QStringLiteral("--maps"), QStringLiteral("exr")});
  EXPECT_EQ(package.exitCode, 0) << package.err;
  // The package's preset is itself valid and points at the copied maps.
  CliRun check = runCli(
      {QStringLiteral("preset"), QStringLiteral("validate"), q(folder + "/package/tiles.relief")});
  EXPECT_EQ(check.exitCode, 0) << check.err;
  EXPECT_TRUE(std::filesystem::exists(folder + "/package/tiles_height.exr"));

  CliRun gltf =
      runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
              QStringLiteral("--to"), QStringLiteral("gltf"), QStringLiteral("--out"),
              q(folder + "/gltf"), QStringLiteral("--mesh"), QStringLiteral("cube")});
  EXPECT_EQ(gltf.exitCode, 0) << gltf.err;
  EXPECT_TRUE(std::filesystem::exists(folder + "/gltf/tiles.gltf"));
  EXPECT_TRUE(std::filesystem::exists(folder + "/gltf/tiles.bin"));

  CliRun godot = runCli({QStringLiteral("export"), QStringLiteral("--preset"),
                         q(samplePreset("tiles")), QStringLiteral("--to"), QStringLiteral("godot"),
                         QStringLiteral("--out"), q(folder + "/godot")});
  EXPECT_EQ(godot.exitCode, 0) << godot.err;
  EXPECT_NE(readBytes(folder + "/godot/tiles.tres").find("heightmap_scale = 1.5"),
            std::string::npos);  // tiles: heightScale 0.015

  // The engine kinds report their main file and notes as JSON too.
  for (const char* kind : {"unreal", "unity", "unity-hdrp"}) {
    CliRun engine =
        runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
                QStringLiteral("--to"), QString::fromLatin1(kind), QStringLiteral("--out"),
                q(folder + "/" + kind), QStringLiteral("--json")});
    EXPECT_EQ(engine.exitCode, 0) << kind << ": " << engine.err;
    const QJsonObject result =
        QJsonDocument::fromJson(QByteArray::fromStdString(engine.out)).object();
    EXPECT_EQ(result.value(QStringLiteral("kind")).toString(), QString::fromLatin1(kind));
    EXPECT_TRUE(
        std::filesystem::exists(result.value(QStringLiteral("written")).toString().toStdString()))
        << kind;
  }
  EXPECT_NE(readBytes(folder + "/unity-hdrp/tiles.mat").find("_HeightPoMAmplitude: 1.5"),
            std::string::npos);  // 0.015 texture widths of a 1 m primitive: 1.5 cm
}

TEST(Cli, ExportRefusesBadRequests) {
  const std::string folder = scratchFolder() + "/export-bad";
  CliRun noKind = runCli({QStringLiteral("export"), QStringLiteral("--preset"),
                          q(samplePreset("tiles")), QStringLiteral("--out"), q(folder)});
  EXPECT_EQ(noKind.exitCode, 2);
  EXPECT_NE(noKind.err.find("--to"), std::string::npos) << noKind.err;
  CliRun badKind =
      runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
              QStringLiteral("--to"), QStringLiteral("fbx"), QStringLiteral("--out"), q(folder)});
  EXPECT_EQ(badKind.exitCode, 2);
  CliRun badTextures =
      runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(samplePreset("tiles")),
              QStringLiteral("--to"), QStringLiteral("package"), QStringLiteral("--textures"),
              QStringLiteral("pvr"), QStringLiteral("--out"), q(folder)});
  EXPECT_EQ(badTextures.exitCode, 2);
  EXPECT_NE(badTextures.err.find("--textures pvr"), std::string::npos) << badTextures.err;
  const std::string missing = folder + "/absent.relief";
  CliRun noPreset =
      runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(missing),
              QStringLiteral("--to"), QStringLiteral("godot"), QStringLiteral("--out"), q(folder)});
  expectCleanFailure(noPreset, missing, "absent.relief");
  // --strict refuses a preset with a missing map; without it the rest is exported.
  std::filesystem::create_directories(folder);
  const std::string partial = folder + "/partial.relief";
  writeBytes(partial,
             "{\"format\": \"relief-material\", \"version\": 2, \"maps\": {\"color\": "
             "{\"path\": \"" +
                 sourcePath("samples/tiles/tiles_color.png") +
                 "\"}, \"height\": {\"path\": \"gone.png\"}}}");
  CliRun strict = runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(partial),
                          QStringLiteral("--to"), QStringLiteral("godot"), QStringLiteral("--out"),
                          q(folder + "/strict"), QStringLiteral("--strict")});
  expectCleanFailure(strict, partial, "gone.png");
  CliRun lenient = runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(partial),
                           QStringLiteral("--to"), QStringLiteral("godot"), QStringLiteral("--out"),
                           q(folder + "/lenient")});
  EXPECT_EQ(lenient.exitCode, 0) << lenient.err;
  EXPECT_NE(lenient.err.find("warning"), std::string::npos) << lenient.err;
}

// A 256x256 crop of a sample map, so that compression under the sanitizers stays quick.
std::string croppedSample(const std::string& file) {
  const core::Image full = core::loadImage(sourcePath("samples/" + file)).value();
  core::Image crop(256, 256, full.channels(), full.colorSpace());
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x)
      std::copy_n(full.pixel(x + 300, y + 300), full.channels(), crop.pixel(x, y));
  }
  const std::string path = scratchFolder() + "/crop-" + file.substr(file.find('/') + 1);
  EXPECT_TRUE(core::saveImage(crop, path).ok());
  return path;
}

QJsonObject jsonOf(const CliRun& run) {
  QJsonParseError error;
  const QJsonDocument document =
      QJsonDocument::fromJson(QByteArray::fromStdString(run.out), &error);
  EXPECT_EQ(error.error, QJsonParseError::NoError) << run.out;
  return document.object();
}

TEST(Cli, CompressWritesDdsAndKtx2WithMetrics) {
  const std::string folder = scratchFolder();
  const std::string colour = croppedSample("tiles/tiles_color.png");
  CliRun bc1 = runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(colour),
                       QStringLiteral("--format"), QStringLiteral("bc1"), QStringLiteral("--mips"),
                       QStringLiteral("--out"), q(folder + "/c.dds"), QStringLiteral("--metrics"),
                       QStringLiteral("json")});
  ASSERT_EQ(bc1.exitCode, 0) << bc1.err;
  const QJsonObject metrics = jsonOf(bc1);
  EXPECT_EQ(metrics["format"].toString(), QStringLiteral("bc1"));
  EXPECT_DOUBLE_EQ(metrics["bitsPerPixel"].toDouble(), 4.0);
  EXPECT_DOUBLE_EQ(metrics["ratioToSource"].toDouble(), 6.0);  // reference 003's 6:1
  EXPECT_GT(metrics["psnr"].toDouble(), 35.0);
  EXPECT_EQ(metrics["channels"].toArray().size(), 3);
  // 256x256 with 9 levels: 64^2 + 32^2 + 16^2 + 8^2 + 4^2 + 2^2 + 1 + 1 + 1 = 5463 blocks of
  // 8 bytes, after the 128-byte header.
  EXPECT_EQ(std::filesystem::file_size(folder + "/c.dds"), 128u + 8u * 5463u);

  // decode gives back the same texels compare measures: the PSNR printed for the DDS file and
  // for its decoded PNG agree (the PNG stores 16 bits, far finer than the error).
  CliRun decode = runCli({QStringLiteral("decode"), q(folder + "/c.dds"), QStringLiteral("--out"),
                          q(folder + "/c.png")});
  ASSERT_EQ(decode.exitCode, 0) << decode.err;
  CliRun viaTexture = runCli(
      {QStringLiteral("compare"), q(colour), q(folder + "/c.dds"), QStringLiteral("--json")});
  CliRun viaImage = runCli(
      {QStringLiteral("compare"), q(colour), q(folder + "/c.png"), QStringLiteral("--json")});
  ASSERT_EQ(viaTexture.exitCode, 0) << viaTexture.err;
  ASSERT_EQ(viaImage.exitCode, 0) << viaImage.err;
  EXPECT_NEAR(jsonOf(viaTexture)["psnr"].toDouble(), metrics["psnr"].toDouble(), 1e-6);
  EXPECT_NEAR(jsonOf(viaImage)["psnr"].toDouble(), metrics["psnr"].toDouble(), 0.05);
  EXPECT_FALSE(jsonOf(viaImage).contains("bitsPerPixel"));
  // FLIP beside PSNR (core/compression/Flip.h): above 0 for BC1, a small fraction of its 0..1
  // range; 0 against itself; --flip-map writes the heat map at the map's size.
  const double flip = jsonOf(viaTexture)["flip"].toObject()["mean"].toDouble();
  EXPECT_GT(flip, 0.0);
  EXPECT_LT(flip, 0.2);
  CliRun self = runCli({QStringLiteral("compare"), q(colour), q(colour), QStringLiteral("--json"),
                        QStringLiteral("--flip-map"), q(folder + "/flip.png")});
  ASSERT_EQ(self.exitCode, 0) << self.err;
  EXPECT_EQ(jsonOf(self)["flip"].toObject()["mean"].toDouble(), 0.0);
  core::Result<core::ImageFileInfo> flipMap = core::readImageInfo(folder + "/flip.png");
  ASSERT_TRUE(flipMap.ok()) << flipMap.error();
  EXPECT_EQ(flipMap->width, 256);
  EXPECT_EQ(flipMap->channels, 3);

  // A normal map in BC5 inside KTX2: the angular error is reported, and the slot travels in the
  // file, so compare measures angles without --normal.
  const std::string normal = croppedSample("tiles/tiles_normal.png");
  CliRun bc5 = runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(normal),
                       QStringLiteral("--format"), QStringLiteral("bc5"),
                       QStringLiteral("--normal"), QStringLiteral("--out"), q(folder + "/n.ktx2")});
  ASSERT_EQ(bc5.exitCode, 0) << bc5.err;
  CliRun angles = runCli({QStringLiteral("compare"), q(normal), q(folder + "/n.ktx2")});
  ASSERT_EQ(angles.exitCode, 0) << angles.err;
  EXPECT_NE(angles.out.find("angular error: mean"), std::string::npos) << angles.out;

  // A mip level of an ASTC KTX2 decodes at its own size.
  CliRun astc = runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(colour),
                        QStringLiteral("--format"), QStringLiteral("astc6x6"),
                        QStringLiteral("--quality"), QStringLiteral("fast"),
                        QStringLiteral("--mips"), QStringLiteral("--out"), q(folder + "/a.ktx2")});
  ASSERT_EQ(astc.exitCode, 0) << astc.err;
  CliRun level = runCli({QStringLiteral("decode"), q(folder + "/a.ktx2"), QStringLiteral("--level"),
                         QStringLiteral("2"), QStringLiteral("--out"), q(folder + "/a2.png")});
  ASSERT_EQ(level.exitCode, 0) << level.err;
  const core::Image decoded = core::loadImage(folder + "/a2.png").value();
  EXPECT_EQ(decoded.width(), 64);
}

// BC7 from the CLI: a DDS with the DX10 header (148-byte header, 16 bytes per block), far above
// BC1 on the same map, and `info` names the format; the same blocks in KTX2. BC1 with
// --perceptual.
TEST(Cli, CompressWritesBc7) {
  const std::string folder = scratchFolder();
  const std::string colour = croppedSample("tiles/tiles_color.png");
  const auto compress = [&](const char* format, const std::string& out) {
    return runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(colour),
                   QStringLiteral("--format"), QString::fromLatin1(format), QStringLiteral("--out"),
                   q(out), QStringLiteral("--metrics"), QStringLiteral("json")});
  };
  const CliRun bc7 = compress("bc7", folder + "/c7.dds");
  const CliRun bc1 = compress("bc1", folder + "/c1.dds");
  ASSERT_EQ(bc7.exitCode, 0) << bc7.err;
  ASSERT_EQ(bc1.exitCode, 0) << bc1.err;
  EXPECT_DOUBLE_EQ(jsonOf(bc7)["bitsPerPixel"].toDouble(), 8.0);
  EXPECT_GT(jsonOf(bc7)["psnr"].toDouble(), jsonOf(bc1)["psnr"].toDouble() + 5.0);
  EXPECT_EQ(std::filesystem::file_size(folder + "/c7.dds"), 148u + 16u * 64u * 64u);
  const CliRun info = runCli({QStringLiteral("info"), q(folder + "/c7.dds")});
  EXPECT_NE(info.out.find("BC7"), std::string::npos) << info.out;
  // --perceptual weighs BC1's colour error by luminance: green (70% of the weight) gains, the
  // uniform PSNR falls.
  const CliRun perceptual = runCli(
      {QStringLiteral("compress"), QStringLiteral("--in"), q(colour), QStringLiteral("--format"),
       QStringLiteral("bc1"), QStringLiteral("--perceptual"), QStringLiteral("--out"),
       q(folder + "/p1.dds"), QStringLiteral("--metrics"), QStringLiteral("json")});
  ASSERT_EQ(perceptual.exitCode, 0) << perceptual.err;
  EXPECT_LT(jsonOf(perceptual)["psnr"].toDouble(), jsonOf(bc1)["psnr"].toDouble());
  const auto greenPsnr = [](const CliRun& run) {
    return jsonOf(run)["channels"].toArray()[1].toObject()["psnr"].toDouble();
  };
  EXPECT_GT(greenPsnr(perceptual), greenPsnr(bc1));
  const CliRun ktx2 = compress("bc7", folder + "/c7.ktx2");
  ASSERT_EQ(ktx2.exitCode, 0) << ktx2.err;
  EXPECT_EQ(core::loadCompressedTexture(folder + "/c7.ktx2")->levels[0].data,
            core::loadCompressedTexture(folder + "/c7.dds")->levels[0].data);
}

// --zstd: the same blocks in a smaller KTX2 (lossless), the size on disk reported; refused for
// DDS and outside 0..22.
TEST(Cli, CompressSupercompressesKtx2WithZstandard) {
  const std::string folder = scratchFolder();
  const std::string normal = croppedSample("bricks/bricks_normal.png");
  const auto compress = [&](const QString& level, const std::string& out) {
    return runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(normal),
                   QStringLiteral("--normal"), QStringLiteral("--format"), QStringLiteral("bc5"),
                   QStringLiteral("--mips"), QStringLiteral("--zstd"), level,
                   QStringLiteral("--out"), q(out), QStringLiteral("--metrics"),
                   QStringLiteral("json")});
  };
  const CliRun plain = compress(QStringLiteral("0"), folder + "/plain.ktx2");
  const CliRun packed = compress(QStringLiteral("19"), folder + "/packed.ktx2");
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  ASSERT_EQ(packed.exitCode, 0) << packed.err;
  const auto plainBytes = std::filesystem::file_size(folder + "/plain.ktx2");
  const auto packedBytes = std::filesystem::file_size(folder + "/packed.ktx2");
  EXPECT_LT(packedBytes, plainBytes);
  // The metrics report what ships: the KTX2 file's size, as it is on disk.
  EXPECT_EQ(jsonOf(packed)["ktx2Bytes"].toDouble(), double(packedBytes));
  EXPECT_EQ(jsonOf(packed)["zstdLevel"].toInt(), 19);
  EXPECT_EQ(jsonOf(plain)["ktx2Bytes"].toDouble(), double(plainBytes));
  // Lossless: both decode to the same texels.
  for (const char* name : {"plain", "packed"}) {
    const CliRun decoded =
        runCli({QStringLiteral("decode"), q(folder + "/" + name + ".ktx2"), QStringLiteral("--raw"),
                QStringLiteral("--out"), q(folder + "/" + name + ".png")});
    ASSERT_EQ(decoded.exitCode, 0) << decoded.err;
  }
  EXPECT_TRUE(core::loadImage(folder + "/plain.png").value() ==
              core::loadImage(folder + "/packed.png").value());
  const CliRun info = runCli({QStringLiteral("info"), q(folder + "/packed.ktx2")});
  EXPECT_NE(info.out.find("on disk: " + std::to_string(packedBytes) +
                          " bytes (Zstandard supercompression)"),
            std::string::npos)
      << info.out;
  const CliRun dds = compress(QStringLiteral("3"), folder + "/n.dds");
  EXPECT_EQ(dds.exitCode, 2);
  EXPECT_NE(dds.err.find("KTX2 feature"), std::string::npos) << dds.err;
  EXPECT_FALSE(std::filesystem::exists(folder + "/n.dds"));
  const CliRun tooHigh = compress(QStringLiteral("23"), folder + "/high.ktx2");
  EXPECT_EQ(tooHigh.exitCode, 2);
  EXPECT_NE(tooHigh.err.find("--zstd"), std::string::npos) << tooHigh.err;
}

TEST(Cli, CompressWarnsWhenAFloatMapIsClamped) {
  // An EXR height from 0 to 2: half its values cannot be stored by any GPU format here.
  core::Image height(64, 64, 1);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x)
      height.at(x, y, 0) = 2.0f * float(x) / 63.0f;
  }
  const std::string folder = scratchFolder();
  ASSERT_TRUE(core::saveImage(height, folder + "/tall.exr", core::SampleFormat::Float).ok());
  CliRun run = runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(folder + "/tall.exr"),
                       QStringLiteral("--format"), QStringLiteral("bc4"), QStringLiteral("--out"),
                       q(folder + "/tall.ktx2")});
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("tall.exr: 50% of the values lie outside 0..1"), std::string::npos)
      << run.err;
}

TEST(Cli, CompressDecodeAndCompareRefuseBadInput) {
  const std::string folder = scratchFolder();
  const std::string colour = croppedSample("tiles/tiles_color.png");
  const auto compress = [&](const QString& format, const std::string& out) {
    return runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(colour),
                   QStringLiteral("--format"), format, QStringLiteral("--out"), q(out)});
  };
  CliRun unknown = compress(QStringLiteral("bc9"), folder + "/x.dds");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("bc9"), std::string::npos);
  CliRun eightBitHdr = compress(QStringLiteral("bc6h"), folder + "/x.dds");
  EXPECT_EQ(eightBitHdr.exitCode, 2);
  EXPECT_NE(eightBitHdr.err.find("8-bit"), std::string::npos) << eightBitHdr.err;
  CliRun etcInDds = compress(QStringLiteral("etc2"), folder + "/x.dds");
  EXPECT_EQ(etcInDds.exitCode, 2);
  EXPECT_NE(etcInDds.err.find(".ktx2"), std::string::npos) << etcInDds.err;
  CliRun colourInBc5 = compress(QStringLiteral("bc5"), folder + "/x.dds");
  EXPECT_EQ(colourInBc5.exitCode, 2);
  EXPECT_NE(colourInBc5.err.find("--normal"), std::string::npos) << colourInBc5.err;
  CliRun missing = runCli({QStringLiteral("compress"), QStringLiteral("--in"),
                           q(folder + "/absent.png"), QStringLiteral("--format"),
                           QStringLiteral("bc1"), QStringLiteral("--out"), q(folder + "/x.dds")});
  expectCleanFailure(missing, folder + "/absent.png", "not found");

  // A truncated DDS: decode and compare name the file and fail.
  ASSERT_EQ(compress(QStringLiteral("bc3"), folder + "/whole.dds").exitCode, 0);
  const std::string whole = readBytes(folder + "/whole.dds");
  writeBytes(folder + "/cut.dds", whole.substr(0, whole.size() / 2));
  expectCleanFailure(runCli({QStringLiteral("decode"), q(folder + "/cut.dds"),
                             QStringLiteral("--out"), q(folder + "/cut.png")}),
                     folder + "/cut.dds", "ends inside");
  EXPECT_FALSE(std::filesystem::exists(folder + "/cut.png"));
  expectCleanFailure(runCli({QStringLiteral("compare"), q(colour), q(folder + "/cut.dds")}),
                     folder + "/cut.dds", "ends inside");
  // Different sizes.
  CliRun sizes = runCli(
      {QStringLiteral("compare"), q(colour), q(sourcePath("samples/tiles/tiles_color.png"))});
  EXPECT_EQ(sizes.exitCode, 1);
  EXPECT_NE(sizes.err.find("same size"), std::string::npos) << sizes.err;
}

TEST(Cli, EveryCommandHasHelp) {
  for (const QString& command :
       {QStringLiteral("render"), QStringLiteral("info"), QStringLiteral("export"),
        QStringLiteral("compress"), QStringLiteral("decode"), QStringLiteral("compare")}) {
    CliRun run = runCli({command, QStringLiteral("--help")});
    EXPECT_EQ(run.exitCode, 0) << command.toStdString();
    EXPECT_NE(run.out.find("Usage: relief-cli " + command.toStdString()), std::string::npos)
        << run.out;
  }
  CliRun top = runCli({QStringLiteral("--help")});
  EXPECT_EQ(top.exitCode, 0);
  EXPECT_NE(top.out.find("render"), std::string::npos);
  // The parameter list in render --help comes from core's table.
  CliRun render = runCli({QStringLiteral("render"), QStringLiteral("--help")});
  EXPECT_NE(render.out.find("normalYDown"), std::string::npos);
}

// ---- Hostile and unusual files (issue: nothing crashes, hangs or lies) ----

// A legacy DDS header (128 bytes) with the fields the readers check; no texel data follows.
std::string ddsHeader(std::uint32_t width, std::uint32_t height, std::uint32_t mipCount,
                      std::uint32_t pixelFlags, const char* fourCC, std::uint32_t caps2 = 0,
                      std::uint32_t depth = 0) {
  std::string bytes(128, '\0');
  const auto put = [&bytes](std::size_t offset, std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
      bytes[offset + std::size_t(i)] = char((value >> (8 * i)) & 0xFF);
  };
  bytes.replace(0, 4, "DDS ");
  put(4, 124);
  put(8, 0x1007);
  put(12, height);
  put(16, width);
  put(24, depth);
  put(28, mipCount);
  put(76, 32);  // pixel format size
  put(80, pixelFlags);
  if (fourCC)
    bytes.replace(84, 4, fourCC);
  put(108, 0x1000);  // caps: texture
  put(112, caps2);
  return bytes;
}

TEST(Cli, HostileTexturesAreRefusedByRelief_sOwnReader) {
  const std::string folder = scratchFolder() + "/hostile-dds";
  std::filesystem::create_directories(folder);
  struct Case {
    std::string name;
    std::string bytes;
    std::string problem;
  };
  const std::uint32_t kFourCC = 0x4;
  const std::vector<Case> cases = {
      // Uncompressed (flags without FourCC, bit count 0): OpenImageIO's reader spun forever.
      {"uncompressed.dds", ddsHeader(64, 64, 1, 0x40, nullptr) + std::string(64 * 64 * 4, 'x'),
       "uncompressed"},
      {"cube.dds", ddsHeader(64, 64, 1, kFourCC, "DXT1", 0xFE00) + std::string(6 * 2048, 'x'),
       "cube map"},
      {"volume.dds", ddsHeader(64, 64, 1, kFourCC, "DXT1", 0x200000, 4) + std::string(8192, 'x'),
       "volume"},
      // Legal for DDS, but beyond the images Relief decodes into (it aborted on allocation).
      {"huge.dds", ddsHeader(32768, 32768, 1, kFourCC, "DXT1"), "outside 1..16384"},
      {"mips.dds", ddsHeader(64, 64, 0xFFFFFFFFu, kFourCC, "DXT1") + std::string(2048, 'x'),
       "4294967295 mip levels"},
  };
  for (const Case& c : cases) {
    const std::string path = folder + "/" + c.name;
    writeBytes(path, c.bytes);
    expectCleanFailure(runCli({QStringLiteral("info"), q(path)}), path, c.problem);
    expectCleanFailure(runCli({QStringLiteral("compress"), QStringLiteral("--in"), q(path),
                               QStringLiteral("--format"), QStringLiteral("bc1"),
                               QStringLiteral("--out"), q(folder + "/out.dds")}),
                       path, c.problem);
  }
  // Whole-number options are whole numbers: "0.5" used to be read as level 0.
  const CliRun half =
      runCli({QStringLiteral("decode"), q(folder + "/mips.dds"), QStringLiteral("--out"),
              q(folder + "/level.png"), QStringLiteral("--level"), QStringLiteral("0.5")});
  EXPECT_EQ(half.exitCode, 2);
  EXPECT_NE(half.err.find("'0.5' is not a whole number"), std::string::npos) << half.err;
  // A DDS renamed to .png is still not handed to OpenImageIO.
  writeBytes(folder + "/disguised.png", cases.front().bytes);
  expectCleanFailure(runCli({QStringLiteral("info"), q(folder + "/disguised.png")}),
                     folder + "/disguised.png", "compressed texture");
}

TEST(Cli, PresetsThatAreNotFilesOrAreHugeAreRefusedAtOnce) {
  const std::string folder = scratchFolder() + "/hostile-presets";
  std::filesystem::create_directories(folder);
  const std::string fifo = folder + "/fifo.relief";
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectCleanFailure(runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(fifo)}), fifo,
                     "not a regular file");
  const std::string zero = folder + "/zero.relief";
  std::filesystem::remove(zero);
  std::filesystem::create_symlink("/dev/zero", zero);
  expectCleanFailure(runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(zero)}), zero,
                     "not a regular file");
  const std::string big = folder + "/big.relief";
  writeBytes(big, "{");
  std::filesystem::resize_file(big, std::uintmax_t(20) << 20);  // sparse: no disk used
  expectCleanFailure(runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(big)}), big,
                     "larger than any preset");
  // A version past what an int holds is reported as written.
  const std::string future = folder + "/future.relief";
  writeBytes(future, R"({"format": "relief-material", "version": 9223372036854775808})");
  expectCleanFailure(runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(future)}),
                     future, "version 9223372036854775808");
}

// A bad file a preset points at is named with the preset and the field that named it, so the
// user knows which preset to fix and where: "m.relief: view.mesh: …/adir.obj: a folder, …".
TEST(Cli, FilesAPresetNamesAreReportedWithThePresetAndTheField) {
  const std::string folder = scratchFolder() + "/preset-names";
  std::filesystem::create_directories(folder + "/adir.obj");
  std::filesystem::create_directories(folder + "/adir.exr");
  std::filesystem::create_directories(folder + "/adir.png");
  const std::string preset = folder + "/m.relief";
  const auto expectNamed = [&](const CliRun& run, const std::string& field,
                               const std::string& file) {
    EXPECT_FALSE(run.crashed);
    EXPECT_NE(run.exitCode, 0) << run.err;
    const std::string said = preset + ": " + field;
    EXPECT_NE(run.err.find(said), std::string::npos) << "expected '" << said << "' in: " << run.err;
    EXPECT_NE(run.err.find(file + ": a folder, not a regular file"), std::string::npos) << run.err;
  };

  writeBytes(preset,
             R"({"format": "relief-material", "version": 2, "view": {"mesh": "adir.obj"}})");
  const QString out = q(folder + "/out.png");
  expectNamed(runCli({QStringLiteral("render"), q(preset), QStringLiteral("--size"),
                      QStringLiteral("16x16"), QStringLiteral("--out"), out}),
              "view.mesh", "adir.obj");
  expectNamed(runCli({QStringLiteral("export"), QStringLiteral("--preset"), q(preset),
                      QStringLiteral("--to"), QStringLiteral("gltf"), QStringLiteral("--out"),
                      q(folder + "/export/")}),
              "view.mesh", "adir.obj");
  // --mesh given on the command line: the file alone, as the user typed it.
  const CliRun typed = runCli({QStringLiteral("render"), q(preset), QStringLiteral("--mesh"),
                               q(folder + "/adir.obj"), QStringLiteral("--size"),
                               QStringLiteral("16x16"), QStringLiteral("--out"), out});
  EXPECT_NE(typed.exitCode, 0);
  EXPECT_EQ(typed.err.find("view.mesh"), std::string::npos) << typed.err;

  writeBytes(preset, R"({"format": "relief-material", "version": 2,
                         "view": {"environment": {"source": "adir.exr"}}})");
  expectNamed(runCli({QStringLiteral("render"), q(preset), QStringLiteral("--size"),
                      QStringLiteral("16x16"), QStringLiteral("--out"), out}),
              "view.environment.source", "adir.exr");

  // Maps were already named by their slot: "m.relief: height map not loaded: …".
  writeBytes(
      preset,
      R"({"format": "relief-material", "version": 2, "maps": {"height": {"path": "adir.png"}}})");
  expectNamed(runCli({QStringLiteral("preset"), QStringLiteral("validate"), q(preset)}),
              "height map not loaded", "adir.png");
}

TEST(Cli, HostileMeshesAreRefusedBeforeAssimpReadsThem) {
  const std::string folder = scratchFolder() + "/hostile-meshes";
  std::filesystem::create_directories(folder);
  const auto render = [&folder](const std::string& mesh) {
    return runCli({q(std::string("render")), QStringLiteral("--color"),
                   q(sourcePath("samples/tiles/tiles_color.png")), QStringLiteral("--mesh"),
                   q(mesh), QStringLiteral("--size"), QStringLiteral("64x64"),
                   QStringLiteral("--out"), q(folder + "/out.png")});
  };
  // 20,000 nested nodes overflowed Assimp's recursion (SIGSEGV).
  std::string nodes;
  for (int i = 0; i < 20000; ++i)
    nodes += (i ? "," : "") +
             (i + 1 < 20000 ? "{\"children\":[" + std::to_string(i + 1) + "]}" : std::string("{}"));
  const std::string deep = folder + "/deep.gltf";
  writeBytes(deep,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
             "\"nodes\":[" +
                 nodes + "]}");
  expectCleanFailure(render(deep), deep, "nested more than 256");
  // A buffer outside the mesh's folder is not read as vertex data.
  const std::string escaping = folder + "/escaping.gltf";
  writeBytes(
      escaping,
      R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../../etc/passwd","byteLength":10}]})");
  expectCleanFailure(render(escaping), escaping, "outside the file's folder");
  // A glb whose header claims 4 GB is refused from its first 12 bytes.
  std::string glb = "glTF";
  const std::uint32_t version = 2, length = 0xFFFFFFF0u;
  glb.append(reinterpret_cast<const char*>(&version), 4);
  glb.append(reinterpret_cast<const char*>(&length), 4);
  glb += std::string(64, '\0');
  const std::string claims = folder + "/claims.glb";
  writeBytes(claims, glb);
  expectCleanFailure(render(claims), claims, "bytes but the file has");
  // NaN positions used to render nothing with exit 0.
  const std::string nan = folder + "/nan.obj";
  writeBytes(nan, "v 0 0 0\nv 1 0 0\nv nan 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  expectCleanFailure(render(nan), nan, "non-finite");
}

// Tiled TIFF and tiled, mip-mapped EXR (what VFX pipelines hand artists) crashed `info` with
// SIGFPE. oiiotool (OpenImageIO's own tool, a Debian package Relief installs) writes them.
TEST(Cli, InfoReadsTiledTiffAndMipMappedExr) {
  const std::string folder = scratchFolder() + "/tiled";
  std::filesystem::create_directories(folder);
  const std::vector<QStringList> writes = {
      {QStringLiteral("--pattern"), QStringLiteral("checker"), QStringLiteral("250x130"),
       QStringLiteral("3"), QStringLiteral("--tile"), QStringLiteral("64"), QStringLiteral("64"),
       QStringLiteral("-o"), q(folder + "/tiled.tif")},
      {QStringLiteral("--pattern"), QStringLiteral("checker"), QStringLiteral("250x130"),
       QStringLiteral("3"), QStringLiteral("-d"), QStringLiteral("half"), QStringLiteral("-otex"),
       q(folder + "/mip.exr")},
      // Two parts, as a compositor writes passes: Relief reads the first and says so.
      {QStringLiteral("--pattern"), QStringLiteral("constant:color=0.5"), QStringLiteral("250x130"),
       QStringLiteral("1"), QStringLiteral("--attrib"), QStringLiteral("oiio:subimagename"),
       QStringLiteral("height"), QStringLiteral("--pattern"), QStringLiteral("checker"),
       QStringLiteral("250x130"), QStringLiteral("3"), QStringLiteral("--siappend"),
       QStringLiteral("-d"), QStringLiteral("half"), QStringLiteral("-o"),
       q(folder + "/parts.exr")},
  };
  for (const QStringList& arguments : writes) {
    QProcess oiiotool;
    oiiotool.start(QStringLiteral("oiiotool"), arguments);
    ASSERT_TRUE(oiiotool.waitForFinished(60000));
    ASSERT_EQ(oiiotool.exitCode(), 0) << oiiotool.readAllStandardError().toStdString();
  }
  for (const char* name : {"tiled.tif", "mip.exr", "parts.exr"}) {
    const CliRun run = runCli({QStringLiteral("info"), q(folder + "/" + name)});
    EXPECT_FALSE(run.crashed) << name;
    EXPECT_EQ(run.exitCode, 0) << name << ": " << run.err;
    EXPECT_NE(run.out.find("size: 250x130"), std::string::npos) << run.out;
    // Only a file of several parts gets the note.
    EXPECT_EQ(run.out.find("note: the file holds 2 images") != std::string::npos,
              std::string(name) == "parts.exr")
        << run.out;
  }
  const CliRun parts = runCli({QStringLiteral("info"), q(folder + "/parts.exr")});
  EXPECT_NE(parts.out.find("channels: 1\n"), std::string::npos) << parts.out;
  EXPECT_NE(parts.out.find("reads the first (\"height\") alone"), std::string::npos) << parts.out;
  const CliRun json =
      runCli({QStringLiteral("info"), q(folder + "/parts.exr"), QStringLiteral("--json")});
  EXPECT_NE(json.out.find("\"subimages\":2"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"subimageRead\":\"height\""), std::string::npos) << json.out;
}

TEST(Cli, SavingOverAFolderSaysSoAndKeepsIt) {
  const std::string folder = scratchFolder() + "/out-is-folder";
  const std::string target = folder + "/normal.png";
  std::filesystem::create_directories(target);
  const CliRun run =
      runCli({QStringLiteral("generate"), QStringLiteral("normal"), QStringLiteral("--in"),
              q(sourcePath("samples/tiles/tiles_height.png")), QStringLiteral("--out"), q(target)});
  expectCleanFailure(run, target, "is a folder");
  EXPECT_EQ(run.err.find("Success"), std::string::npos) << run.err;
  EXPECT_TRUE(std::filesystem::is_directory(target));
}

// A private Xvfb for one test (its own display number); stopped when the object goes.
class PrivateXServer {
 public:
  PrivateXServer() {
    m_display = 400 + int(::getpid() % 400);
    while (std::filesystem::exists(socket()))
      ++m_display;
    m_server.start(QStringLiteral("Xvfb"),
                   QStringList{QStringLiteral(":%1").arg(m_display), QStringLiteral("-screen"),
                               QStringLiteral("0"), QStringLiteral("640x480x24"),
                               QStringLiteral("-nolisten"), QStringLiteral("tcp")});
    for (int i = 0; i < 200 && !std::filesystem::exists(socket()); ++i)
      QThread::msleep(50);
  }
  ~PrivateXServer() {
    m_server.terminate();
    m_server.waitForFinished(5000);
  }
  bool running() const { return std::filesystem::exists(socket()); }
  QProcessEnvironment environment() const {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("DISPLAY"), QStringLiteral(":%1").arg(m_display));
    return environment;
  }

 private:
  std::string socket() const { return "/tmp/.X11-unix/X" + std::to_string(m_display); }
  int m_display = 0;
  QProcess m_server;
};

QStringList smallRender(const std::string& out) {
  return {QStringLiteral("render"), q(samplePreset("tiles")), QStringLiteral("--size"),
          QStringLiteral("96x64"),  QStringLiteral("--out"),  q(out)};
}

// Render farms run renders in parallel: rounds of four at once on one private Xvfb (which resets
// whenever its last client leaves, the case where the display probe's early disconnect let Qt's
// connection land in a reset and abort), none may fail.
TEST(Cli, ParallelRendersOnOneXServerAllSucceed) {
  PrivateXServer server;
  ASSERT_TRUE(server.running()) << "Xvfb did not start";
  const std::string folder = scratchFolder() + "/parallel";
  std::filesystem::create_directories(folder);
  int failures = 0;
  std::string firstError;
  for (int round = 0; round < 3; ++round) {
    std::vector<std::unique_ptr<QProcess>> renders;
    for (int i = 0; i < 4; ++i) {
      auto render = std::make_unique<QProcess>();
      render->setProcessEnvironment(server.environment());
      render->start(QStringLiteral(RELIEF_CLI_PATH),
                    smallRender(folder + "/r" + std::to_string(round * 4 + i) + ".png"));
      renders.push_back(std::move(render));
    }
    for (auto& render : renders) {
      const bool finished = render->waitForFinished(120000);
      if (!finished || render->exitStatus() != QProcess::NormalExit || render->exitCode() != 0) {
        ++failures;
        if (firstError.empty())
          firstError = render->readAllStandardError().toStdString();
      }
    }
  }
  EXPECT_EQ(failures, 0) << "first failure: " << firstError;
}

}  // namespace
}  // namespace relief::test
