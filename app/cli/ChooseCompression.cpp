// ChooseCompression; see ChooseCompression.h.
#include "ChooseCompression.h"

#include "app/cli/CliOptionNames.h"

#include "ChooseOptions.h"
#include "TerminalProgress.h"
#include "core/base/AtomicFile.h"
#include "core/base/ByteSize.h"
#include "renderer/OffscreenRenderer.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QStringList>

#include <cmath>
#include <cstdio>

namespace relief::cli {
namespace {

QString formatName(core::TextureFormat format) {
  return qstr(core::textureFormatInfo(format).name);
}

// "bc7", or "bc7 rdo 16" for a candidate with an RDO trade.
QString optionName(const core::ChooserOption& option) {
  return option.rdoLambda > 0.0f ? QStringLiteral("%1 rdo %2")
                                       .arg(formatName(option.format))
                                       .arg(double(option.rdoLambda))
                                 : formatName(option.format);
}

QString describeGoal(const core::ChooserGoal& goal) {
  switch (goal.kind) {
    case core::ChooserGoalKind::Budget:
      return QStringLiteral("at most %1 as shipped")
          .arg(qstr(core::describeByteSize(std::uint64_t(goal.value))));
    case core::ChooserGoalKind::Flip:
      return QStringLiteral("rendered FLIP at most %1").arg(goal.value, 0, 'f', 4);
    case core::ChooserGoalKind::Psnr:
      return QStringLiteral("rendered PSNR at least %1 dB").arg(goal.value, 0, 'f', 2);
  }
  return {};  // not reached: every kind is handled above
}

QString psnrText(double psnr) {
  return std::isinf(psnr) ? QStringLiteral("identical")
                          : QStringLiteral("%1 dB").arg(psnr, 0, 'f', 2);
}

QJsonValue psnrJson(double psnr) {
  return std::isinf(psnr) ? QJsonValue() : QJsonValue(psnr);  // JSON has no infinity
}

// "color bc1, normal bc5, height bc4".
QString describePick(const renderer::ChooserResult& result, const core::ChooserPick& pick) {
  QStringList parts;
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    parts << QStringLiteral("%1 %2").arg(
        qstr(core::mapSlotName(result.maps[m].slot)),
        optionName(result.maps[m].candidates[pick.options[m]].option));
  }
  return parts.join(QStringLiteral(", "));
}

// Why the pick won: the rule, then each map's trade against its next-smaller candidate.
QString describeWhy(const renderer::ChooserResult& result, const core::ChooserGoal& goal) {
  const core::ChooserPick& pick = *result.pick;
  QString why = goal.kind == core::ChooserGoalKind::Budget
                    ? QStringLiteral(
                          "the least FLIP, rendered together, of the %1 combinations "
                          "within the budget whose maps' errors sum lowest.")
                          .arg(result.combinationsMeasured)
                    : QStringLiteral(
                          "the fewest bytes that, rendered together, meet the target "
                          "(%1 combination(s) rendered).")
                          .arg(result.combinationsMeasured);
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    const auto& candidates = result.maps[m].candidates;
    const std::size_t chosen = pick.options[m];
    if (candidates.size() < 2)
      continue;
    const core::ChooserOption& mine = candidates[chosen].option;
    // The nearest alternative by size: the next-smaller one, else the next-larger one.
    const core::ChooserOption* other = nullptr;
    for (const renderer::ChooserCandidate& candidate : candidates) {
      const core::ChooserOption& option = candidate.option;
      if (&candidate == &candidates[chosen])
        continue;
      const bool smaller = option.bytes < mine.bytes;
      if (!other || (smaller && (other->bytes > mine.bytes || option.bytes > other->bytes)) ||
          (!smaller && other->bytes > mine.bytes && option.bytes < other->bytes))
        other = &option;
    }
    const double bytes = double(other->bytes) - double(mine.bytes);
    why +=
        QStringLiteral("\n  %1: %2 instead of %3 %4 %5 and %6 FLIP by %7")
            .arg(qstr(core::mapSlotName(result.maps[m].slot)), optionName(mine), optionName(*other),
                 bytes > 0 ? QStringLiteral("saves") : QStringLiteral("costs"),
                 qstr(core::describeByteSize(std::uint64_t(std::abs(bytes)))),
                 other->flip > mine.flip ? QStringLiteral("lowers") : QStringLiteral("raises"))
            .arg(std::abs(other->flip - mine.flip), 0, 'f', 4);
  }
  return why;
}

QString table(const renderer::ChooserResult& result) {
  QString text = QStringLiteral("map        format         as shipped   FLIP alone   PSNR alone\n");
  // For a budget the rows are screened at fast; the chosen ones are compressed again at the
  // quality asked for, and their rows are those files'.
  const std::vector<const renderer::ChooserCandidate*> chosen = result.chosen();
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    for (const renderer::ChooserCandidate& candidate : result.maps[m].candidates) {
      const bool picked = chosen[m] == &candidate;
      text +=
          QStringLiteral("%1 %2 %3 %4   %5   %6%7\n")
              .arg(&candidate == &result.maps[m].candidates.front()
                       ? qstr(core::mapSlotName(result.maps[m].slot))
                       : QString(),
                   -9)
              .arg(picked ? QStringLiteral("*") : QStringLiteral(" "))
              .arg(optionName(candidate.option), -14)
              .arg(qstr(core::describeByteSize(candidate.option.bytes)), 11)
              .arg(candidate.option.flip, 10, 'f', 4)
              .arg(psnrText(core::psnrFromMse(candidate.option.mse)), 10)
              .arg(picked ? QStringLiteral("   chosen, %1")
                                .arg(qstr(core::compressionQualityName(candidate.settings.quality)))
                          : QString());
    }
  }
  return text;
}

QJsonObject report(const renderer::ChooserResult& result, const ChooseRequest& request,
                   const QStringList& files) {
  const core::ChooserGoal& goal = request.chooser.goal;
  const QString kind = goal.kind == core::ChooserGoalKind::Budget ? QStringLiteral("budget")
                       : goal.kind == core::ChooserGoalKind::Flip ? QStringLiteral("flip")
                                                                  : QStringLiteral("psnr");
  const std::vector<const renderer::ChooserCandidate*> chosen = result.chosen();
  QJsonArray maps;
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    QJsonArray candidates;
    for (const renderer::ChooserCandidate& candidate : result.maps[m].candidates) {
      candidates.append(
          QJsonObject{{QStringLiteral("format"), formatName(candidate.option.format)},
                      {QStringLiteral("rdo"), double(candidate.option.rdoLambda)},
                      {QStringLiteral("bytes"), double(candidate.option.bytes)},
                      {QStringLiteral("flip"), candidate.option.flip},
                      {QStringLiteral("psnr"), psnrJson(core::psnrFromMse(candidate.option.mse))},
                      // For a budget, candidates are screened at fast; the chosen ones are
                      // shipped (and measured again) at the quality asked for.
                      {QStringLiteral("quality"),
                       qstr(core::compressionQualityName(candidate.settings.quality))},
                      {QStringLiteral("chosen"), chosen[m] == &candidate}});
    }
    QJsonObject entry{{QStringLiteral("slot"), qstr(core::mapSlotName(result.maps[m].slot))},
                      {QStringLiteral("candidates"), candidates}};
    if (chosen[m]) {
      entry.insert(QStringLiteral("format"), formatName(chosen[m]->option.format));
      entry.insert(QStringLiteral("rdo"), double(chosen[m]->option.rdoLambda));
      entry.insert(QStringLiteral("file"), files.value(int(m)));
    }
    maps.append(entry);
  }
  QJsonObject object{
      {QStringLiteral("goal"),
       QJsonObject{{QStringLiteral("kind"), kind}, {QStringLiteral("value"), goal.value}}},
      {QStringLiteral("device"), qstr(core::chooserPlatformName(request.chooser.platform))},
      {QStringLiteral("quality"), qstr(core::compressionQualityName(request.chooser.quality))},
      {QStringLiteral("zstd"), request.chooser.zstdLevel},
      {QStringLiteral("viewSize"),
       QStringLiteral("%1x%2").arg(request.chooser.width).arg(request.chooser.height)},
      {QStringLiteral("met"), result.pick.has_value()},
      {QStringLiteral("maps"), maps},
      {QStringLiteral("closest"),
       QJsonObject{{QStringLiteral("bytes"), double(result.closest.bytes)},
                   {QStringLiteral("flipEstimate"), result.closest.flip},
                   {QStringLiteral("psnrEstimate"), psnrJson(result.closest.psnr)},
                   {QStringLiteral("formats"), describePick(result, result.closest)}}},
  };
  if (const auto& pick = result.pick) {
    QJsonArray views;
    for (const renderer::RenderedErrorRow& row : result.measured) {
      views.append(QJsonObject{{QStringLiteral("view"), QString::fromStdString(row.view)},
                               {QStringLiteral("psnr"), psnrJson(row.psnr)},
                               {QStringLiteral("flip"), row.flipMean},
                               {QStringLiteral("uvShiftTexels"), row.uvShiftMeanTexels}});
    }
    object.insert(QStringLiteral("total"),
                  QJsonObject{{QStringLiteral("bytes"), double(pick->bytes)},
                              {QStringLiteral("flipEstimate"), pick->flip},
                              {QStringLiteral("psnrEstimate"), psnrJson(pick->psnr)},
                              {QStringLiteral("flip"), result.measuredFlip},
                              {QStringLiteral("psnr"), psnrJson(result.measuredPsnr)},
                              {QStringLiteral("views"), views}});
    object.insert(QStringLiteral("combinationsRendered"), result.combinationsMeasured);
  }
  return object;
}

// Why the goal cannot be met, naming what comes closest.
QString unmetMessage(const renderer::ChooserResult& result, const ChooseRequest& request) {
  const core::ChooserGoal& goal = request.chooser.goal;
  const core::ChooserPick& closest = result.closest;
  if (goal.kind == core::ChooserGoalKind::Budget) {
    return QStringLiteral(
               "the budget of %1 cannot be met: the smallest these maps ship at is "
               "%2 (%3)")
        .arg(qstr(core::describeByteSize(std::uint64_t(goal.value))),
             qstr(core::describeByteSize(closest.bytes)), describePick(result, closest));
  }
  const QString best = goal.kind == core::ChooserGoalKind::Flip
                           ? QStringLiteral("FLIP %1").arg(closest.flip, 0, 'f', 4)
                           : QStringLiteral("PSNR %1").arg(psnrText(closest.psnr));
  return QStringLiteral(
             "%1 cannot be reached with %2 formats: the best combination (%3, %4) "
             "comes to %5 by the maps' errors summed%6")
      .arg(describeGoal(goal), qstr(core::chooserPlatformName(request.chooser.platform)))
      .arg(describePick(result, closest), qstr(core::describeByteSize(closest.bytes)), best,
           result.combinationsMeasured > 0
               ? QStringLiteral(", and the %1 cheapest combinations that might reach it "
                                "missed it rendered together")
                     .arg(result.combinationsMeasured)
               : QString());
}

}  // namespace

CliOptions chooseCompressionOptions() {
  CliOptions options = {
      {option::kChooseCompression,
       {},
       QStringLiteral("Choose every map's format for a goal (what `compress --preset` runs)."),
       {}},
      {option::kQuality, QStringLiteral("quality"),
       QStringLiteral("With --preset: the encoders' effort (fast|normal|best)."),
       QStringLiteral("normal")},
      {option::kZstd, QStringLiteral("level"),
       QStringLiteral("With --preset: the Zstandard level sizes count after (1..22)."),
       QStringLiteral("19")},
  };
  for (CliOption& goal : chooseGoalOptions())
    options.push_back(std::move(goal));
  return options;
}

QStringList chooseCompressionArguments(QStringList arguments) {
  for (int i = 2; i < arguments.size(); ++i) {
    if (arguments[i] == QStringLiteral("--") + option::kPreset) {
      arguments.removeAt(i);  // its value stays, as the positional preset
      break;
    }
    if (arguments[i].startsWith(QStringLiteral("--") + option::kPreset + QLatin1Char('='))) {
      arguments[i] = arguments[i].mid(option::kPreset.size() + 3);
      break;
    }
  }
  arguments << QStringLiteral("--") + option::kChooseCompression;
  return arguments;
}

std::optional<int> parseChooseRequest(const QCommandLineParser& parser, const QString& presetPath,
                                      ChooseRequest& request) {
  const QStringList goals = {option::kBudget, option::kTargetFlip, option::kTargetPsnr};
  int given = 0;
  for (const QString& goal : goals)
    given += parser.isSet(goal) ? 1 : 0;
  if (given != 1) {
    printError(
        QStringLiteral("compress --preset: give one goal: --budget SIZE, --target-flip X "
                       "or --target-psnr DB"));
    return kExitUsage;
  }
  core::ChooserGoal& goal = request.chooser.goal;
  if (parser.isSet(option::kBudget)) {
    const QString text = parser.value(option::kBudget);
    const std::optional<std::uint64_t> bytes = core::parseByteSize(text.toStdString());
    if (!bytes) {
      printError(QStringLiteral("--budget '%1': expected a size above 0, such as 6MB, 512KiB or "
                                "700000 (bytes)")
                     .arg(text));
      return kExitUsage;
    }
    goal = {core::ChooserGoalKind::Budget, double(*bytes)};
  } else {
    const bool flip = parser.isSet(option::kTargetFlip);
    const QString& name = flip ? option::kTargetFlip : option::kTargetPsnr;
    const std::optional<double> value = numberOption(parser, name, 0.0);
    if (!value)
      return kExitUsage;
    if (flip ? (*value <= 0.0 || *value >= 1.0) : *value <= 0.0) {
      printError(flip ? QStringLiteral("--target-flip: expected a FLIP between 0 and 1 (0.02 is "
                                       "hard to see)")
                      : QStringLiteral("--target-psnr: expected decibels above 0"));
      return kExitUsage;
    }
    goal = {flip ? core::ChooserGoalKind::Flip : core::ChooserGoalKind::Psnr, *value};
  }
  const std::optional<core::ChooserPlatform> platform =
      core::findChooserPlatform(parser.value(option::kDevice).toStdString());
  if (!platform) {
    printError(QStringLiteral("--device %1: expected desktop or mobile")
                   .arg(parser.value(option::kDevice)));
    return kExitUsage;
  }
  request.chooser.platform = *platform;
  const std::optional<core::CompressionQuality> quality =
      core::findCompressionQuality(parser.value(option::kQuality).toStdString());
  if (!quality) {
    printError(QStringLiteral("--quality %1: expected fast, normal or best")
                   .arg(parser.value(option::kQuality)));
    return kExitUsage;
  }
  request.chooser.quality = *quality;
  const std::optional<int> zstd = integerOption(parser, option::kZstd, 19, 1, 22);
  if (!zstd)
    return kExitUsage;
  request.chooser.zstdLevel = *zstd;
  if (!parser.isSet(option::kOutDir)) {
    printError(QStringLiteral("compress --preset: give --out-dir FOLDER for the chosen files"));
    return kExitUsage;
  }
  request.outDir = parser.value(option::kOutDir);
  request.baseName = QFileInfo(presetPath).completeBaseName();
  if (request.baseName.endsWith(QStringLiteral(".relief")))
    request.baseName.chop(7);
  request.progressLines = parser.isSet(option::kProgressLines);
  return std::nullopt;
}

int runChooseCompression(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                         const renderer::FrameSettings& frame, const ChooseRequest& request,
                         bool json) {
  TerminalProgress progress(QStringLiteral("choosing"));
  core::WorkControl control = progress.control();
  if (request.progressLines) {
    control.progress = [last = -1](double fraction) mutable {
      const int percent = int(std::floor(fraction * 100.0));
      if (percent == last)
        return;
      last = percent;
      std::fprintf(stderr, "progress %.2f\n", fraction);
      std::fflush(stderr);
    };
  }
  core::Result<renderer::ChooserResult> chosen =
      renderer::chooseCompression(offscreen, material, frame, request.chooser, control);
  if (!chosen) {
    printError(QStringLiteral("compress --preset: ") + QString::fromStdString(chosen.error()));
    return kExitFailure;
  }
  const renderer::ChooserResult& result = chosen.value();
  if (!result.pick) {
    if (json)
      printJson(report(result, request, {}));
    else
      printOut(table(result));
    printError(QStringLiteral("compress --preset: ") + unmetMessage(result, request));
    return kExitFailure;
  }
  if (!QDir().mkpath(request.outDir)) {
    printError(QStringLiteral("--out-dir %1: cannot create the folder").arg(request.outDir));
    return kExitFailure;
  }
  QStringList files;
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    const renderer::ChooserCandidate& pick = *result.chosen()[m];
    const QString path =
        QDir(request.outDir)
            .filePath(QStringLiteral("%1_%2.ktx2")
                          .arg(request.baseName, qstr(core::mapSlotName(result.maps[m].slot))));
    const std::string_view bytes(reinterpret_cast<const char*>(pick.file.data()), pick.file.size());
    if (core::Status written = core::writeFileAtomically(path.toStdString(), bytes); !written) {
      printError(QString::fromStdString(written.error()));
      return kExitFailure;
    }
    files << path;
  }
  const QJsonObject object = report(result, request, files);
  const QString jsonPath = QDir(request.outDir).filePath(QStringLiteral("choice.json"));
  if (core::Status written = core::writeFileAtomically(
          jsonPath.toStdString(), QJsonDocument(object).toJson().toStdString());
      !written) {
    printError(QString::fromStdString(written.error()));
    return kExitFailure;
  }
  if (json) {
    printJson(object);
    return kExitOk;
  }
  const core::ChooserPick& pick = *result.pick;
  printOut(QStringLiteral("goal: %1 (KTX2, Zstandard %2), %3 formats, quality %4\n")
               .arg(describeGoal(request.chooser.goal))
               .arg(request.chooser.zstdLevel)
               .arg(qstr(core::chooserPlatformName(request.chooser.platform)),
                    qstr(core::compressionQualityName(request.chooser.quality))) +
           table(result) +
           QStringLiteral("chosen: %1: %2; rendered together FLIP %3 (summed estimate %4), "
                          "PSNR %5\nwhy: %6\n")
               .arg(describePick(result, pick), qstr(core::describeByteSize(pick.bytes)))
               .arg(result.measuredFlip, 0, 'f', 4)
               .arg(pick.flip, 0, 'f', 4)
               .arg(psnrText(result.measuredPsnr), describeWhy(result, request.chooser.goal)) +
           QStringLiteral("wrote %1 and %2\n").arg(files.join(QStringLiteral(", ")), jsonPath));
  return kExitOk;
}

}  // namespace relief::cli
