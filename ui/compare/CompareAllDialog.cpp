// CompareAllDialog; see CompareAllDialog.h.
#include "ui/compare/CompareAllDialog.h"

#include "core/compression/BlockRdo.h"
#include "core/compression/TextureFile.h"
#include "ui/QtText.h"
#include "ui/tasks/CliProcess.h"

#include <QChart>
#include <QChartView>
#include <QCursor>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolTip>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline compare {
namespace {

// The chart's bits-per-texel axis runs 0..kChartBits. A point label ("bc7 (8.03 on disk)") is
// about kLabelWidth of the plot's width and kLabelHeight of its height in the dialog's default
// size; closer points than that would print their labels over each other.
constexpr double kChartBits = 9.0;
// The trades Compare All tries for each format with RDO, under Zstandard (BlockRdo.h).
constexpr float kRdoLambdas[] = {8.0f, 32.0f};
// Where a row's format item keeps its RDO lambda (Qt::UserRole holds the format) and the index
// of its outcome (the rows sort; the outcomes keep their order).
constexpr int kRdoRole = Qt::UserRole + 1;
constexpr int kOutcomeRole = Qt::UserRole + 2;
constexpr double kLabelWidth = 0.22;
constexpr double kLabelHeight = 0.07;

enum Column {
  FormatColumn,
  BitsColumn,
  DiskColumn,
  RatioColumn,
  QualityColumn,
  SsimColumn,
  FlipColumn,
  RenderedColumn,
  DetailColumn,
  SecondsColumn,
  ColumnCount
};

// A cell that sorts by number rather than by text.
class NumberItem : public QTableWidgetItem {
 public:
  using QTableWidgetItem::QTableWidgetItem;
  bool operator<(const QTableWidgetItem& other) const override {
    return data(Qt::UserRole).toDouble() < other.data(Qt::UserRole).toDouble();
  }
};

QTableWidgetItem* sortableNumber(double value, const QString& text) {
  auto* item = new NumberItem(text);
  item->setData(Qt::UserRole, value);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

}  // namespace

CompareAllDialog::CompareAllDialog(QWidget* parent)
    : QDialog(parent), m_cliPath(CliProcess::defaultProgram()), m_process(new CliProcess(this)) {
  setWindowTitle(tr("Compare All Formats"));
  resize(940, 720);
  m_runner = new CompressionRunner(this);
  m_table = new QTableWidget(0, ColumnCount, this);
  m_table->setHorizontalHeaderLabels({tr("Format"), tr("Bits/texel"), tr("On disk"), tr("vs RGBA8"),
                                      tr("Quality"), tr("SSIM"), tr("FLIP"), tr("Rendered FLIP"),
                                      tr("Detail"), tr("Seconds")});
  m_table->horizontalHeaderItem(RenderedColumn)
      ->setToolTip(tr("The material rendered with this map alone compressed (with the mip chain it "
                      "ships with, as counted on disk) against the original: FLIP, the perceptual "
                      "difference, mean of a close, a grazing and a far view. Lower is better."));
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  // Columns as wide as their header and values (the on-disk header says what it counts), the
  // detail column takes the rest.
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setSectionResizeMode(DetailColumn, QHeaderView::Stretch);
  m_table->verticalHeader()->hide();

  auto* chart = new QChart;
  chart->legend()->hide();
  chart->setTheme(QChart::ChartThemeDark);
  m_chartView = new QChartView(chart, this);
  m_chartView->setRenderHint(QPainter::Antialiasing);
  m_chartView->setMinimumHeight(280);

  m_progress = new QProgressBar(this);
  m_progress->setRange(0, 1000);
  m_status = new QLabel(this);
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_use = new QPushButton(tr("Use Format"), this);
  m_use->setEnabled(false);
  m_use->setToolTip(tr("Set the Compress panel's format for this map to the selected row"));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  buttons->addButton(m_use, QDialogButtonBox::ActionRole);

  auto* progressRow = new QHBoxLayout;
  progressRow->addWidget(m_progress, 1);
  progressRow->addWidget(m_cancel);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_table, 1);
  layout->addWidget(m_chartView, 1);
  layout->addLayout(progressRow);
  layout->addWidget(m_status);
  layout->addWidget(buttons);

  connect(buttons, &QDialogButtonBox::rejected, this, &CompareAllDialog::reject);
  connect(m_cancel, &QPushButton::clicked, m_runner, &CompressionRunner::cancel);
  connect(m_cancel, &QPushButton::clicked, m_process, &CliProcess::cancel);
  connect(m_table, &QTableWidget::itemSelectionChanged, this,
          [this] { m_use->setEnabled(selectedFormat().has_value()); });
  connect(m_table, &QTableWidget::cellDoubleClicked, m_use, &QPushButton::click);
  connect(m_use, &QPushButton::clicked, this, [this] {
    if (const auto format = selectedFormat())
      Q_EMIT formatChosen(m_slot, *format, selectedRdoLambda());
  });
  connect(m_runner, &CompressionRunner::progress, this,
          [this](double fraction, const QString& what) {
            m_progress->setValue(int(std::lround(fraction * 1000.0)));
            m_status->setText(tr("Compressing %1…").arg(what));
          });
  connect(m_runner, &CompressionRunner::jobFinished, this,
          [this](const core::CompressionOutcome& outcome) {
            m_outcomes.push_back(outcome);
            addRow(outcome);
            updateChart();
          });
  connect(m_runner, &CompressionRunner::finished, this, [this] {
    m_progress->setValue(1000);
    m_cancel->setEnabled(false);
    m_status->setText(
        tr("%1 formats compared. Select one and press Use Format.").arg(m_outcomes.size()));
    startRendering();
  });
  connect(m_process, &CliProcess::progress, this, [this](double fraction) {
    m_progress->setValue(int(std::lround(fraction * 1000.0)));
    // The CLI reports the original's render, then one step a format.
    const int rendered = int(std::lround(fraction * double(m_outcomes.size() + 1))) - 1;
    m_status->setText(tr("%1 formats compared. Rendering the material with each: %2 of %3…")
                          .arg(m_outcomes.size())
                          .arg(std::max(rendered, 0))
                          .arg(m_outcomes.size()));
  });
  connect(m_process, &CliProcess::finished, this, &CompareAllDialog::showRendered);
  connect(m_process, &CliProcess::cancelled, this, [this] {
    m_cancel->setEnabled(false);
    m_status->setText(
        tr("%1 formats compared; the rendered error was cancelled.").arg(m_outcomes.size()));
  });
  connect(m_process, &CliProcess::failedToStart, this, [this](const QString& message) {
    m_cancel->setEnabled(false);
    m_status->setText(
        tr("%1 formats compared; no rendered error: %2").arg(m_outcomes.size()).arg(message));
  });
  connect(m_runner, &CompressionRunner::cancelled, this, [this] {
    m_cancel->setEnabled(false);
    m_status->setText(tr("Cancelled after %1 formats.").arg(m_outcomes.size()));
  });
  connect(m_runner, &CompressionRunner::failed, this, [this](const QString& message) {
    m_cancel->setEnabled(false);
    m_status->setText(tr("Failed: %1").arg(message));
  });
}

CompareAllDialog::~CompareAllDialog() = default;  // the CliProcess kills a running child

bool CompareAllDialog::rendering() const {
  return m_process->running();
}

void CompareAllDialog::start(core::MapSlot slot, std::shared_ptr<const core::Image> map,
                             core::CompressionQuality quality, bool mipmaps, int zstdLevel,
                             double heightScale) {
  m_process->abandon();  // the last map's rendering, if still going: this run replaces it
  m_slot = slot;
  m_texels = double(map->width()) * double(map->height());
  m_outcomes.clear();
  m_table->setRowCount(0);
  m_table->setSortingEnabled(false);
  setWindowTitle(tr("Compare All Formats: %1 map (%2x%3, quality %4)")
                     .arg(toQString(core::mapSlotLabel(slot)))
                     .arg(map->width())
                     .arg(map->height())
                     .arg(toQString(core::compressionQualityName(quality))));
  // The column says what it counts: mipmaps or not (as the panel's sizes), and Zstandard.
  const QString mipText = mipmaps ? tr("with mipmaps") : tr("level 0 only");
  m_table->horizontalHeaderItem(DiskColumn)
      ->setText(zstdLevel > 0 ? tr("On disk (%1, Zstd %2)").arg(mipText).arg(zstdLevel)
                              : tr("On disk (%1)").arg(mipText));
  m_table->horizontalHeaderItem(DiskColumn)
      ->setToolTip(
          tr("What ships: the KTX2 file's bits per level-0 texel, header included, %1%2")
              .arg(mipmaps ? tr("with the full mip chain (a third more)") : tr("level 0 alone"))
              .arg(zstdLevel > 0 ? tr(", levels supercompressed with Zstandard") : ""));
  m_table->horizontalHeaderItem(QualityColumn)
      ->setText(slot == core::MapSlot::Normal ? tr("Mean angle (°)")
                : core::isHdrMap(*map, slot)  ? tr("Exposure PSNR (dB)")
                                              : tr("PSNR (dB)"));
  m_table->horizontalHeaderItem(DetailColumn)
      ->setText(slot == core::MapSlot::Normal   ? tr("p99 angle, share > 2°")
                : slot == core::MapSlot::Height ? tr("Parallax shift (texels)")
                                                : tr("Max error"));
  m_zstdLevel = zstdLevel;
  std::vector<core::CompressionJob> jobs;
  for (core::TextureFormat format : core::formatsForMap(*map, slot)) {
    jobs.push_back({map, slot, {format, quality, mipmaps, zstdLevel}, heightScale});
    // Under Zstandard, the formats with RDO get a row per trade too: the size-quality curve.
    if (zstdLevel > 0 && core::formatHasRdo(format)) {
      for (float lambda : kRdoLambdas) {
        core::CompressionJob job{map, slot, {format, quality, mipmaps, zstdLevel}, heightScale};
        job.settings.rdoLambda = lambda;
        jobs.push_back(std::move(job));
      }
    }
  }
  m_cancel->setEnabled(true);
  m_progress->setValue(0);
  updateChart();
  m_runner->start(std::move(jobs));
}

double CompareAllDialog::onDiskBitsPerTexel(const core::CompressionOutcome& outcome) const {
  return m_texels > 0.0 ? double(outcome.report.size->ktx2Bytes) * 8.0 / m_texels : 0.0;
}

float CompareAllDialog::selectedRdoLambda() const {
  const QList<QTableWidgetItem*> selected = m_table->selectedItems();
  if (selected.isEmpty())
    return 0.0f;
  return m_table->item(selected.front()->row(), FormatColumn)->data(kRdoRole).toFloat();
}

// "BC1 (DXT1)", or "BC1 (DXT1) · RDO 8" for a row with a trade.
QString CompareAllDialog::rowName(const core::CompressionSettings& settings, bool shortName) {
  const core::TextureFormatInfo& info = core::textureFormatInfo(settings.format);
  const QString name = toQString(shortName ? info.name : info.label);
  return settings.rdoLambda > 0.0f ? tr("%1 · RDO %2").arg(name).arg(double(settings.rdoLambda))
                                   : name;
}

std::optional<core::TextureFormat> CompareAllDialog::selectedFormat() const {
  const QList<QTableWidgetItem*> selected = m_table->selectedItems();
  if (selected.isEmpty())
    return std::nullopt;
  const QTableWidgetItem* item = m_table->item(selected.front()->row(), FormatColumn);
  return core::TextureFormat(item->data(Qt::UserRole).toInt());
}

void CompareAllDialog::addRow(const core::CompressionOutcome& outcome) {
  const core::CompressionReport& report = outcome.report;
  const core::TextureFormat format = outcome.job.settings.format;
  m_table->setSortingEnabled(false);
  const int row = m_table->rowCount();
  m_table->insertRow(row);
  const bool materialChoice =
      m_materialChoice == format && outcome.job.settings.rdoLambda == m_materialChoiceRdo;
  auto* name = new QTableWidgetItem(
      materialChoice ? tr("%1  ← Choose for Me").arg(rowName(outcome.job.settings))
                     : rowName(outcome.job.settings));
  name->setData(Qt::UserRole, int(format));
  name->setData(kRdoRole, double(outcome.job.settings.rdoLambda));
  name->setData(kOutcomeRole, int(m_outcomes.size()) - 1);
  if (materialChoice) {
    QFont font = name->font();
    font.setBold(true);
    name->setFont(font);
    name->setToolTip(
        tr("Choose for Me picked this format for the map, judged on the whole "
           "material as rendered"));
  }
  m_table->setItem(row, FormatColumn, name);
  m_table->setItem(row, BitsColumn,
                   sortableNumber(report.size->bitsPerPixel,
                                  QString::number(report.size->bitsPerPixel, 'f', 2)));
  const double diskBits = onDiskBitsPerTexel(outcome);
  auto* disk = sortableNumber(diskBits, QString::number(diskBits, 'f', 2));
  disk->setToolTip(tr("%1 bytes").arg(report.size->ktx2Bytes));
  m_table->setItem(row, DiskColumn, disk);
  m_table->setItem(row, RatioColumn,
                   sortableNumber(report.size->ratioToRgba8,
                                  tr("%1:1").arg(report.size->ratioToRgba8, 0, 'f', 1)));
  if (report.normal) {
    m_table->setItem(row, QualityColumn,
                     sortableNumber(report.normal->meanDegrees,
                                    QString::number(report.normal->meanDegrees, 'f', 3)));
    m_table->setItem(
        row, DetailColumn,
        new QTableWidgetItem(tr("%1°, %2%")
                                 .arg(report.normal->p99Degrees, 0, 'f', 2)
                                 .arg(report.normal->shareAbove2Degrees * 100.0, 0, 'f', 2)));
  } else {
    const double psnr = std::isfinite(report.image.psnr) ? report.image.psnr : 999.0;
    m_table->setItem(row, QualityColumn, sortableNumber(psnr, QString::number(psnr, 'f', 2)));
    m_table->setItem(
        row, DetailColumn,
        new QTableWidgetItem(report.height
                                 ? tr("mean %1, max %2")
                                       .arg(report.height->meanTexels, 0, 'f', 3)
                                       .arg(report.height->maxTexels, 0, 'f', 3)
                                 : tr("%1/255").arg(report.image.maxError * 255.0, 0, 'f', 1)));
  }
  m_table->setItem(row, SsimColumn,
                   sortableNumber(report.image.ssim, QString::number(report.image.ssim, 'f', 4)));
  // FLIP: the perceptual difference (core/compression/Flip.h), lower is better.
  m_table->setItem(row, FlipColumn,
                   sortableNumber(report.flip, QString::number(report.flip, 'f', 4)));
  m_table->setItem(
      row, SecondsColumn,
      sortableNumber(report.encodeSeconds, QString::number(report.encodeSeconds, 'f', 2)));
  m_table->setSortingEnabled(true);
  if (m_outcomes.size() == 1)
    m_table->sortByColumn(BitsColumn, Qt::AscendingOrder);
}

void CompareAllDialog::updateChart() {
  QChart* chart = m_chartView->chart();
  chart->removeAllSeries();
  for (QAbstractAxis* axis : chart->axes()) {
    chart->removeAxis(axis);  // hands the axis back to us
    delete axis;
  }
  const bool normal = m_slot == core::MapSlot::Normal;
  chart->setTitle(normal ? tr("Mean angular error against bits per texel (lower is better)")
                         : tr("PSNR against bits per texel (higher is better)"));
  // With Zstandard the axis is what ships (RDO moves nothing else); otherwise the format's rate.
  const bool onDisk = m_zstdLevel > 0;
  double chartBits = kChartBits;
  for (const core::CompressionOutcome& outcome : m_outcomes)
    chartBits = std::max(chartBits, std::ceil(onDiskBitsPerTexel(outcome) + 0.5));
  if (!onDisk)
    chartBits = kChartBits;
  // One series per format, so each point carries its format's name as its label (Qt 6.4 has
  // no per-point label text).
  const auto quality = [normal](const core::CompressionOutcome& outcome) {
    return normal ? outcome.report.normal->meanDegrees : std::min(outcome.report.image.psnr, 99.0);
  };
  double low = 1e9, high = -1e9;
  for (const core::CompressionOutcome& outcome : m_outcomes) {
    low = std::min(low, quality(outcome));
    high = std::max(high, quality(outcome));
  }
  const double yLow = high > low ? std::floor(low - 0.1 * (high - low)) : low - 1.0;
  const double yHigh = high > low ? std::ceil(high + 0.1 * (high - low)) : high + 1.0;
  std::vector<QScatterSeries*> series;
  std::vector<QPointF> labelled;  // points whose label is shown, in axis fractions
  for (const core::CompressionOutcome& outcome : m_outcomes) {
    const QPointF at(onDisk ? onDiskBitsPerTexel(outcome) : outcome.report.size->bitsPerPixel,
                     quality(outcome));
    auto* point = new QScatterSeries;
    point->setName(rowName(outcome.job.settings));
    point->setMarkerSize(10.0);
    // The label says what ships too: the KTX2 file's bits per texel on disk.
    const QString label = onDisk ? rowName(outcome.job.settings, true)
                                 : tr("%1 (%2 on disk)")
                                       .arg(rowName(outcome.job.settings, true))
                                       .arg(onDiskBitsPerTexel(outcome), 0, 'f', 2);
    point->setPointLabelsFormat(label);
    point->setPointLabelsClipping(false);
    // Qt centres a point's label above it: two points closer than a label's size would print
    // over each other (BC4 and EAC R11 of a height map sit at the same rate and nearly the same
    // PSNR). The later one's label is left off; the legend and a tooltip still name it.
    const QPointF fraction(at.x() / chartBits, (at.y() - yLow) / std::max(yHigh - yLow, 1e-9));
    const bool overlaps = std::any_of(labelled.begin(), labelled.end(), [&](QPointF other) {
      return std::abs(other.x() - fraction.x()) < kLabelWidth &&
             std::abs(other.y() - fraction.y()) < kLabelHeight;
    });
    point->setPointLabelsVisible(!overlaps);
    if (!overlaps)
      labelled.push_back(fraction);
    connect(point, &QScatterSeries::hovered, this, [label](const QPointF&, bool entered) {
      if (entered)
        QToolTip::showText(QCursor::pos(), label);
      else
        QToolTip::hideText();
    });
    point->append(at);
    chart->addSeries(point);
    series.push_back(point);
  }
  auto* x = new QValueAxis;
  x->setTitleText(onDisk ? tr("bits per texel on disk (KTX2, Zstandard %1)").arg(m_zstdLevel)
                         : tr("bits per texel"));
  x->setRange(0.0, chartBits);
  x->setTickCount(10);
  x->setLabelFormat(QStringLiteral("%d"));
  auto* y = new QValueAxis;
  y->setTitleText(normal ? tr("mean angular error (°)") : tr("PSNR (dB)"));
  y->setRange(yLow, yHigh);
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  for (QScatterSeries* point : series) {
    point->attachAxis(x);
    point->attachAxis(y);
  }
}

void CompareAllDialog::startRendering() {
  if (!m_preset || m_outcomes.empty())
    return;
  // The material as a preset in a folder of its own (maps made in the editor are written
  // there), and each row's texture as a KTX2 file beside it, in the outcomes' order.
  m_folder = std::make_unique<QTemporaryDir>();
  const QString presetPath = m_folder->filePath(QStringLiteral("material.relief"));
  core::Result<core::SavedPreset> saved =
      m_folder->isValid() ? core::savePreset(*m_preset, presetPath.toStdString())
                          : core::makeError(m_folder->errorString().toStdString());
  if (!saved) {
    m_status->setText(tr("No rendered error: cannot hand the material over: %1")
                          .arg(QString::fromStdString(saved.error())));
    return;
  }
  QStringList arguments = {QStringLiteral("compare"), QStringLiteral("--rendered"), presetPath,
                           QStringLiteral("--slot"), toQString(core::mapSlotName(m_slot))};
  for (std::size_t i = 0; i < m_outcomes.size(); ++i) {
    const QString file = m_folder->filePath(QStringLiteral("format%1.ktx2").arg(i));
    if (core::Status written =
            core::saveCompressedTexture(*m_outcomes[i].texture, file.toStdString());
        !written) {
      m_status->setText(tr("No rendered error: %1").arg(QString::fromStdString(written.error())));
      return;
    }
    arguments << file;
  }
  arguments << QStringLiteral("--json") << QStringLiteral("--progress-lines");
  if (!m_viewSize.isEmpty()) {
    arguments << QStringLiteral("--size")
              << QStringLiteral("%1x%2").arg(m_viewSize.width()).arg(m_viewSize.height());
  }
  m_progress->setValue(0);
  m_cancel->setEnabled(true);
  m_status->setText(
      tr("%1 formats compared. Rendering the material with each…").arg(m_outcomes.size()));
  m_process->start(m_cliPath, arguments);
}

void CompareAllDialog::showRendered(int exitCode, const QJsonObject& report,
                                    const QString& errors) {
  m_cancel->setEnabled(false);
  m_progress->setValue(1000);
  const QJsonArray candidates = report.value(QStringLiteral("candidates")).toArray();
  if (exitCode != 0 || candidates.size() != qsizetype(m_outcomes.size())) {
    QString message = errors;
    message.replace(QStringLiteral("relief-cli: "), QString());
    m_status->setText(tr("%1 formats compared; no rendered error: %2")
                          .arg(m_outcomes.size())
                          .arg(message.isEmpty() ? tr("exit code %1").arg(exitCode) : message));
    return;
  }
  m_table->setSortingEnabled(false);
  for (int row = 0; row < m_table->rowCount(); ++row) {
    const int outcome = m_table->item(row, FormatColumn)->data(kOutcomeRole).toInt();
    const double flip = candidates[outcome][QStringLiteral("flip")].toDouble();
    const QJsonValue psnr = candidates[outcome][QStringLiteral("psnr")];
    auto* item = sortableNumber(flip, QString::number(flip, 'f', 4));
    item->setToolTip(
        tr("Rendered PSNR %1")
            .arg(psnr.isNull() ? tr("identical") : tr("%1 dB").arg(psnr.toDouble(), 0, 'f', 2)));
    m_table->setItem(row, RenderedColumn, item);
  }
  m_table->setSortingEnabled(true);
  m_status->setText(tr("%1 formats compared, each also rendered in the material (Rendered "
                       "FLIP). Select one and press Use Format.")
                        .arg(m_outcomes.size()));
}

void CompareAllDialog::reject() {
  m_runner->cancel();
  m_process->cancel();
  QDialog::reject();
}

}  // namespace relief::ui::inline compare
