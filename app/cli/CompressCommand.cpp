// CompressCommand; see CompressCommand.h.
#include "CompressCommand.h"

#include "app/cli/CliOptionNames.h"

#include "ChooseOptions.h"
#include "CliCommon.h"
#include "TerminalProgress.h"
#include "core/compression/BlockRdo.h"
#include "core/compression/CompressionJob.h"
#include "core/compression/Flip.h"
#include "core/compression/MapFile.h"
#include "core/compression/TextureFile.h"
#include "core/image/Heatmap.h"
#include "core/image/ImageIO.h"

#include <QFileInfo>
#include <QJsonDocument>

#include <limits>

namespace relief::cli {
namespace {

QString formatNames() {
  std::vector<core::TextureFormat> formats;
  for (const core::TextureFormatInfo& info : core::allTextureFormats())
    formats.push_back(info.format);
  return enumNames<core::TextureFormat>(
      formats, [](core::TextureFormat f) { return core::textureFormatInfo(f).name; });
}

// The parallax height scale the height metrics assume when none is given: the material's.
const double kDefaultHeightScale = core::parameterDefault(core::ParamId::HeightScale);

// A candidate: an ordinary image, or a compressed texture decoded as the map it holds.
struct Candidate {
  core::Image image;
  std::optional<core::CompressedTexture> texture;
};

core::Result<Candidate> loadCandidate(const std::string& path) {
  if (core::containerForPath(path)) {
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path);
    if (!texture)
      return core::makeError(texture.error());
    core::Result<core::Image> image = core::decodeAsMap(texture.value());
    if (!image)
      return core::makeError(path + ": " + image.error());
    return Candidate{std::move(image).value(), std::move(texture).value()};
  }
  core::Result<core::Image> image = core::loadImage(path);
  if (!image)
    return core::makeError(image.error());
  return Candidate{std::move(image).value(), std::nullopt};
}

CliOptions slotOptions() {
  return {
      {option::kNormal,
       {},
       QStringLiteral("The map is a normal map (tangent space, 0.5 + 0.5 n): angular error is "
                      "measured."),
       {}},
      {option::kHeight,
       {},
       QStringLiteral("The map is a height map: the error is also given as parallax shift."),
       {}},
      {option::kHeightScale, QStringLiteral("scale"),
       QStringLiteral("Parallax height scale for the shift."),
       QString::number(kDefaultHeightScale)},
  };
}

CliOptions compressOptions() {
  CliOptions options = {
      {option::kIn, QStringLiteral("file"), QStringLiteral("The map."), {}},
      {option::kFormat, QStringLiteral("format"), formatNames(), {}},
      {option::kQuality, QStringLiteral("quality"),
       QStringLiteral("fast|normal|best: the search depth of Relief's BC, ETC2 and EAC encoders "
                      "(BC6H: 2, 6 or all 32 partitions tried); astcenc's fast, medium and "
                      "thorough presets."),
       QStringLiteral("normal")},
      {option::kMips,
       {},
       QStringLiteral("Write a full mip chain, each level filtered for the map's kind."),
       {}},
      {option::kMipFilter, QStringLiteral("box|kaiser"),
       QStringLiteral("The mip chain's filter: box (area average), or kaiser (a Kaiser-windowed "
                      "sinc, sharper and without the box's aliasing; wraps at the edges)."),
       QStringLiteral("box")},
      {option::kAlphaCoverage,
       QStringLiteral("cutoff"),
       QStringLiteral("A colour map with alpha cut out by an alpha test at this cutoff (0..1): "
                      "every mip level keeps level 0's share of texels at or above it, so "
                      "leaves and fences do not thin away far off. Needs --mips."),
       {}},
      {option::kRoughnessFromNormals,
       QStringLiteral("normal-map"),
       QStringLiteral("The map is a roughness map: widen its mips by this normal map's spread "
                      "under each texel (Toksvig), so bumps far away stay rough instead of "
                      "turning into a mirror. Needs --mips and a normal map of the same size."),
       {}},
      {option::kOut, QStringLiteral("file"), QStringLiteral("Output .dds or .ktx2 file."), {}},
      {option::kZstd, QStringLiteral("level"),
       QStringLiteral("KTX2 only: supercompress the levels with Zstandard at this level "
                      "(1 fastest .. 22 smallest; 0 none). Lossless: the GPU gets the same "
                      "blocks, the file and the download are smaller."),
       QStringLiteral("0")},
      {option::kRdo, QStringLiteral("lambda"),
       QStringLiteral("BC1, BC3, BC4, BC5, BC7: trade quality for size after Zstandard (or a "
                      "game's LZ): blocks repeat bytes of their neighbours where that costs "
                      "less than lambda times the bits it saves. 0 is off (the encoder's blocks "
                      "bit for bit); 1-10 is mild, 50 and up strong. Use with --zstd."),
       QStringLiteral("0")},
      {option::kAllow8Bit,
       {},
       QStringLiteral("BC6H: take an 8-bit map anyway, its 0..1 values stored as half floats "
                      "(BC6H is for EXR, HDR and 16-bit float maps; 8-bit maps are refused "
                      "without this)."),
       {}},
      {option::kPerceptual,
       {},
       QStringLiteral("BC1-BC3 colour: weigh the error by luminance (Rec. 709) instead of "
                      "alike per channel, as PSNR measures it."),
       {}},
      {option::kMetrics,
       QStringLiteral("text|json"),
       QStringLiteral("Print the quality metrics: text or json (on standard output)."),
       {}},
  };
  for (CliOption& option : slotOptions())
    options.push_back(std::move(option));
  // Choose for me: run in the render helper (ChooseCompression.h), listed here for --help.
  options.push_back({option::kPreset,
                     QStringLiteral("preset"),
                     QStringLiteral("Instead of --in/--format/--out: choose every map's format "
                                    "for a goal (--budget, --target-flip or --target-psnr), "
                                    "judged on the rendered material, and write the files into "
                                    "--out-dir (--zstd defaults to 19 here). Needs a display."),
                     {}});
  for (CliOption& goal : chooseGoalOptions())
    options.push_back(std::move(goal));
  options.push_back({option::kSize, QStringLiteral("WxH"),
                     QStringLiteral("With --preset: the rendered views' size."),
                     QStringLiteral("320x240")});
  options.push_back(jsonOption());
  return options;
}

// compress also knows --roughness-from-normals (a roughness map); compare does not, and asking
// QCommandLineParser about an option it was not given prints a warning.
std::optional<core::MapSlot> slotOption(const QCommandLineParser& parser,
                                        bool roughnessOption = false) {
  if (roughnessOption && parser.isSet(option::kRoughnessFromNormals))
    return core::MapSlot::Roughness;
  if (parser.isSet(option::kNormal))
    return core::MapSlot::Normal;
  if (parser.isSet(option::kHeight))
    return core::MapSlot::Height;
  return std::nullopt;
}

// The job (the map loaded), the output path and where it goes; an exit code when they are wrong.
std::optional<int> buildJob(const QCommandLineParser& parser, core::CompressionJob& job,
                            std::string& outPath) {
  const std::optional<core::TextureFormat> format =
      core::findTextureFormat(parser.value(option::kFormat).toStdString());
  if (!format) {
    printError(QStringLiteral("--format: unknown format '%1' (one of %2)")
                   .arg(parser.value(option::kFormat), formatNames()));
    return kExitUsage;
  }
  const auto quality = core::findCompressionQuality(parser.value(option::kQuality).toStdString());
  if (!quality) {
    printError(QStringLiteral("--quality: '%1' is not fast, normal or best")
                   .arg(parser.value(option::kQuality)));
    return kExitUsage;
  }
  const QString metrics = parser.value(option::kMetrics);
  if (parser.isSet(option::kMetrics) && metrics != QStringLiteral("json") &&
      metrics != QStringLiteral("text")) {
    printError(QStringLiteral("--metrics: '%1' is not text or json").arg(metrics));
    return kExitUsage;
  }
  const std::optional<double> heightScale =
      numberOption(parser, option::kHeightScale, kDefaultHeightScale);
  if (!heightScale)
    return kExitUsage;
  outPath = parser.value(option::kOut).toStdString();
  const std::optional<core::TextureContainer> container = core::containerForPath(outPath);
  if (!container) {
    printError(QString::fromStdString(outPath) +
               QStringLiteral(": the output must end in .dds or .ktx2"));
    return kExitUsage;
  }
  if (!core::containerHolds(*container, *format)) {
    printError(QString::fromStdString(outPath) + QStringLiteral(": ") +
               qstr(core::textureFormatInfo(*format).label) +
               QStringLiteral(" has no DDS format that common readers open; use .ktx2"));
    return kExitUsage;
  }
  const std::optional<int> zstdLevel =
      integerOption(parser, option::kZstd, 0, 0, core::kMaxZstdLevel);
  if (!zstdLevel)
    return kExitUsage;
  if (*zstdLevel > 0 && *container != core::TextureContainer::Ktx2) {
    printError(QString::fromStdString(outPath) +
               QStringLiteral(": --zstd is a KTX2 feature; DDS has no supercompression"));
    return kExitUsage;
  }
  const std::string inPath = parser.value(option::kIn).toStdString();
  core::Result<core::Image> map = core::loadMapFile(inPath);
  if (!map) {
    printError(QString::fromStdString(map.error()));
    return kExitFailure;
  }
  // Without --normal or --height a map is colour, except that a one-channel format holds data.
  job.slot = slotOption(parser, true)
                 .value_or(core::isSingleChannelFormat(*format) ? core::MapSlot::Height
                                                                : core::MapSlot::Color);
  job.map = std::make_shared<const core::Image>(std::move(map).value());
  const std::optional<core::MipFilter> mipFilter =
      core::findMipFilter(parser.value(option::kMipFilter).toStdString());
  if (!mipFilter) {
    printError(QStringLiteral("--mip-filter: '%1' is not box or kaiser")
                   .arg(parser.value(option::kMipFilter)));
    return kExitUsage;
  }
  job.settings = {*format,
                  *quality,
                  parser.isSet(option::kMips),
                  *zstdLevel,
                  parser.isSet(option::kPerceptual),
                  *mipFilter};
  if (parser.isSet(option::kRdo)) {
    const std::optional<double> lambda = numberOption(parser, option::kRdo, 0.0);
    if (!lambda)
      return kExitUsage;
    if (*lambda < 0.0 || *lambda > core::kMaxRdoLambda) {
      printError(QStringLiteral("--rdo: a lambda from 0 (off) to %1").arg(core::kMaxRdoLambda));
      return kExitUsage;
    }
    if (*lambda > 0.0 && !core::formatHasRdo(*format)) {
      printError(QStringLiteral("--rdo: %1 has no rate-distortion optimisation (BC1, BC3, BC4, "
                                "BC5 and BC7 do)")
                     .arg(qstr(core::textureFormatInfo(*format).label)));
      return kExitUsage;
    }
    job.settings.rdoLambda = float(*lambda);
  }
  if (parser.isSet(option::kAlphaCoverage)) {
    const std::optional<double> cutoff = numberOption(parser, option::kAlphaCoverage, 0.5);
    if (!cutoff)
      return kExitUsage;
    if (*cutoff <= 0.0 || *cutoff >= 1.0 || !parser.isSet(option::kMips)) {
      printError(
          QStringLiteral("--alpha-coverage: a cutoff between 0 and 1 (exclusive), with "
                         "--mips (it shapes the mip levels)"));
      return kExitUsage;
    }
    if (job.map->channels() < 4) {
      printError(QStringLiteral("%1: --alpha-coverage needs an alpha channel; the map has %2")
                     .arg(parser.value(option::kIn))
                     .arg(job.map->channels()));
      return kExitUsage;
    }
    job.settings.alphaCoverage = float(*cutoff);
  }
  if (parser.isSet(option::kRoughnessFromNormals)) {
    if (!parser.isSet(option::kMips)) {
      printError(QStringLiteral("--roughness-from-normals widens the mips: it needs --mips"));
      return kExitUsage;
    }
    core::Result<core::Image> normals =
        core::loadMapFile(parser.value(option::kRoughnessFromNormals).toStdString());
    if (!normals) {
      printError(QString::fromStdString(normals.error()));
      return kExitFailure;
    }
    job.spreadNormals = std::make_shared<const core::Image>(std::move(normals).value());
    job.settings.roughnessFromNormals = true;
  }
  job.heightScale = *heightScale;
  job.measure = parser.isSet(option::kMetrics);
  job.acceptIntegerMaps = parser.isSet(option::kAllow8Bit);
  if (const std::string problem = core::formatSlotProblem(*format, job.slot); !problem.empty()) {
    printError(QString::fromStdString(inPath + ": " + problem) +
               QStringLiteral("; pass --normal or --height if the map is one, or choose another "
                              "format"));
    return kExitUsage;
  }
  if (const std::string problem = core::formatMapProblem(*job.map, *format, job.acceptIntegerMaps);
      !problem.empty()) {
    printError(QString::fromStdString(inPath + ": " + problem) +
               (job.map->sourceBitsPerChannel() == 8
                    ? QStringLiteral("; pass --allow-8bit to store it anyway")
                    : QString()));
    return kExitUsage;
  }
  return std::nullopt;
}

}  // namespace

int runCompress(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Compress a map into a GPU block format and save it as DDS (BC formats) or KTX2 (all)."));
  addOptions(parser, compressOptions());
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli compress --in MAP --format FORMAT "
                                             "--out MAP.dds|MAP.ktx2 [options]")))
    return *exit;
  for (const QString& chooserOnly : {option::kBudget, option::kTargetFlip, option::kTargetPsnr,
                                     option::kDevice, option::kOutDir}) {
    if (parser.isSet(chooserOnly)) {
      printError(QStringLiteral("--%1 chooses formats for a preset's maps: give --preset PRESET")
                     .arg(chooserOnly));
      return kExitUsage;
    }
  }
  if (!missingOptions(parser, {option::kIn, option::kOut, option::kFormat}).isEmpty()) {
    printError(QStringLiteral("compress needs --in MAP, --format FORMAT and --out FILE"));
    return kExitUsage;
  }
  core::CompressionJob job;
  std::string outPath;
  if (auto exit = buildJob(parser, job, outPath))
    return *exit;
  const QString inPath = parser.value(option::kIn);
  core::Result<core::CompressionOutcome> outcome = [&] {
    TerminalProgress progress(QStringLiteral("compress ") +
                              QFileInfo(parser.value(option::kIn)).fileName());
    return core::runCompressionJob(job, progress.control());
  }();
  if (!outcome) {
    printError(inPath + QStringLiteral(": ") + QString::fromStdString(outcome.error()));
    return kExitFailure;
  }
  for (const std::string& warning : outcome->warnings)
    printError(QStringLiteral("warning: %1: %2").arg(inPath, QString::fromStdString(warning)));
  const core::CompressedTexture& texture = *outcome->texture;
  if (core::Status saved = core::saveCompressedTexture(texture, outPath, job.settings.zstdLevel);
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  if (!job.measure) {
    printNote(QStringLiteral("%1: %2, %3x%4, %5 level(s), %6 bytes of blocks, %7 bytes on disk, "
                             "%8 s\n")
                  .arg(QString::fromStdString(outPath),
                       qstr(core::textureFormatInfo(job.settings.format).label))
                  .arg(job.map->width())
                  .arg(job.map->height())
                  .arg(texture.levels.size())
                  .arg(texture.byteSize())
                  .arg(QFileInfo(QString::fromStdString(outPath)).size())
                  .arg(outcome->report.encodeSeconds, 0, 'f', 2));
  } else if (parser.value(option::kMetrics) == QStringLiteral("json")) {
    printOut(QString::fromUtf8(QJsonDocument(core::reportToJson(outcome->report)).toJson()));
  } else {
    printOut(QString::fromStdString(core::reportToText(outcome->report)));
  }
  return kExitOk;
}

int runDecode(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Decode a DDS or KTX2 file to an image: the map it holds (normal Z rebuilt from X and Y "
      "for two-channel formats), or with --raw the RGBA texels a GPU samples."));
  parser.addPositionalArgument(QStringLiteral("texture"), QStringLiteral(".dds or .ktx2 file"));
  addOptions(parser, {{option::kOut, QStringLiteral("file"), QStringLiteral("Output image."), {}},
                      {option::kLevel, QStringLiteral("n"), QStringLiteral("Mip level."),
                       QStringLiteral("0")},
                      {option::kRaw, {}, QStringLiteral("Write the texels unchanged."), {}},
                      jsonOption()});
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli decode F.dds|F.ktx2 --out F.png")))
    return *exit;
  if (parser.positionalArguments().size() != 1 || !parser.isSet(option::kOut)) {
    printError(QStringLiteral("decode takes one .dds or .ktx2 file and --out FILE"));
    return kExitUsage;
  }
  const std::optional<int> level =
      integerOption(parser, option::kLevel, 0, 0, std::numeric_limits<int>::max());
  if (!level)
    return kExitUsage;
  const std::string path = parser.positionalArguments().front().toStdString();
  core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path);
  if (!texture) {
    printError(QString::fromStdString(texture.error()));
    return kExitFailure;
  }
  core::Result<core::Image> image = parser.isSet(option::kRaw)
                                        ? core::decodeLevel(texture.value(), *level)
                                        : core::decodeAsMap(texture.value(), *level);
  if (!image) {
    printError(QString::fromStdString(path + ": " + image.error()));
    return kExitFailure;
  }
  const std::string out = parser.value(option::kOut).toStdString();
  if (core::Status saved = core::saveImage(image.value(), out); !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  if (parser.isSet(option::kJson)) {
    printJson({{QStringLiteral("output"), QString::fromStdString(out)},
               {QStringLiteral("format"), qstr(core::textureFormatInfo(texture->format).name)},
               {QStringLiteral("width"), image->width()},
               {QStringLiteral("height"), image->height()},
               {QStringLiteral("level"), *level},
               {QStringLiteral("levels"), int(texture->levels.size())}});
    return kExitOk;
  }
  printNote(
      QStringLiteral("%1: %2 %3x%4 level %5 of %6\n")
          .arg(QString::fromStdString(out), qstr(core::textureFormatInfo(texture->format).label))
          .arg(image->width())
          .arg(image->height())
          .arg(*level)
          .arg(texture->levels.size()));
  return kExitOk;
}

int runCompare(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Measure how far CANDIDATE is from REFERENCE: PSNR per channel and overall, SSIM, "
      "maximum error; angular error for normal maps; parallax shift for height maps; size "
      "and rate when CANDIDATE is a DDS or KTX2 file. relief-cli compare --rendered PRESET "
      "[--json] instead renders the preset's material with its maps as they are and as its "
      "compression choices make them, and compares the pictures (see render "
      "--compression-error); relief-cli compare --rendered PRESET --slot SLOT FILE.ktx2 "
      "[FILE.dds ...] measures each compressed file in that map slot alone, one row a file."));
  parser.addPositionalArgument(QStringLiteral("reference"), QStringLiteral("The original."));
  parser.addPositionalArgument(QStringLiteral("candidate"),
                               QStringLiteral("An image or a .dds/.ktx2 file."));
  CliOptions options = slotOptions();
  options.push_back({option::kJson, {}, QStringLiteral("Print the metrics as JSON."), {}});
  options.push_back({option::kFlipMap,
                     QStringLiteral("file"),
                     QStringLiteral("Also write the per-pixel FLIP error as a heat map (navy: "
                                    "none, red: most), an image the size of the maps."),
                     {}});
  addOptions(parser, options);
  if (auto exit =
          parseOrExit(parser, arguments,
                      QStringLiteral("relief-cli compare REFERENCE CANDIDATE [--normal] [--json] "
                                     "[--flip-map FILE]")))
    return *exit;
  if (parser.positionalArguments().size() != 2) {
    printError(QStringLiteral("compare takes two files: REFERENCE CANDIDATE"));
    return kExitUsage;
  }
  const std::optional<double> heightScale =
      numberOption(parser, option::kHeightScale, kDefaultHeightScale);
  if (!heightScale)
    return kExitUsage;
  const std::string referencePath = parser.positionalArguments()[0].toStdString();
  const std::string candidatePath = parser.positionalArguments()[1].toStdString();
  core::Result<core::Image> reference = core::loadMapFile(referencePath);
  if (!reference) {
    printError(QString::fromStdString(reference.error()));
    return kExitFailure;
  }
  core::Result<Candidate> candidate = loadCandidate(candidatePath);
  if (!candidate) {
    printError(QString::fromStdString(candidate.error()));
    return kExitFailure;
  }
  const core::Image& image = candidate->image;
  if (image.width() != reference->width() || image.height() != reference->height()) {
    printError(QStringLiteral("%1 is %2x%3 but %4 is %5x%6; compare needs the same size")
                   .arg(QString::fromStdString(candidatePath))
                   .arg(image.width())
                   .arg(image.height())
                   .arg(QString::fromStdString(referencePath))
                   .arg(reference->width())
                   .arg(reference->height()));
    return kExitFailure;
  }
  const core::MapSlot slot = slotOption(parser).value_or(
      candidate->texture ? candidate->texture->slot : core::MapSlot::Color);
  if (slot == core::MapSlot::Normal && (reference->channels() < 3 || image.channels() < 3)) {
    printError(QStringLiteral("--normal needs RGB normal maps (0.5 + 0.5 n) on both sides"));
    return kExitFailure;
  }
  core::Image flipError;
  core::CompressionReport report =
      core::makeCompressionReport(reference.value(), image, slot, *heightScale,
                                  parser.isSet(option::kFlipMap) ? &flipError : nullptr);
  if (candidate->texture) {
    report.format = candidate->texture->format;
    report.size = core::measureSize(candidate->texture->format, reference->channels(),
                                    candidate->texture->byteSize());
  }
  if (parser.isSet(option::kFlipMap)) {
    core::Image heat(flipError.width(), flipError.height(), 3, core::ColorSpace::Srgb);
    for (int y = 0; y < heat.height(); ++y) {
      for (int x = 0; x < heat.width(); ++x) {
        const glm::vec3 colour = core::heatmapColor(flipError.at(x, y, 0));
        for (int c = 0; c < 3; ++c)
          heat.at(x, y, c) = colour[c];
      }
    }
    const std::string mapPath = parser.value(option::kFlipMap).toStdString();
    if (core::Status saved = core::saveImage(heat, mapPath, core::SampleFormat::UInt8); !saved) {
      printError(QString::fromStdString(saved.error()));
      return kExitFailure;
    }
  }
  if (parser.isSet(option::kJson))
    printOut(QString::fromUtf8(QJsonDocument(core::reportToJson(report)).toJson()));
  else
    printOut(QString::fromStdString(core::reportToText(report)));
  return kExitOk;
}

}  // namespace relief::cli
