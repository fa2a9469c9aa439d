// CompressPanel; see CompressPanel.h.
#include "ui/panels/CompressPanel.h"

#include "core/compression/BlockRdo.h"
#include "core/compression/TextureFile.h"
#include "ui/QtText.h"
#include "ui/compare/ChooseForMeDialog.h"
#include "ui/compare/CompareAllDialog.h"
#include "ui/compare/CompareDialog.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

namespace relief::ui::inline panels {
namespace {

constexpr int kUncompressed = -1;

QString qualityText(const core::CompressionOutcome& outcome) {
  const core::CompressionReport& report = outcome.report;
  if (report.normal) {
    return QObject::tr("%1° mean, %2° p99")
        .arg(report.normal->meanDegrees, 0, 'f', 2)
        .arg(report.normal->p99Degrees, 0, 'f', 1);
  }
  QString text = std::isfinite(report.image.psnr)
                     ? QObject::tr("%1 dB").arg(report.image.psnr, 0, 'f', 1)
                     : QObject::tr("exact");
  text += QObject::tr(", SSIM %1").arg(report.image.ssim, 0, 'f', 3);
  text += QObject::tr(", FLIP %1").arg(report.flip, 0, 'f', 4);
  if (report.height)
    text += QObject::tr(", shift %1 tx").arg(report.height->meanTexels, 0, 'f', 3);
  return text;
}

}  // namespace

CompressPanel::CompressPanel(MaterialDocument* document, ViewDocument* view, QWidget* parent)
    : QWidget(parent), m_document(document), m_viewDocument(view) {
  m_runner = new CompressionRunner(this);
  // Created in the order Tab visits them: the formats, the options and actions, the results.
  QGridLayout* formats = formatGrid();
  createOptionsAndActions();
  createResults();
  layOut(formats);
  connectSignals();
  syncFromDocument();
  showOutcomes();
}

// One row per map slot: its label, the formats that suit it and the quality.
QGridLayout* CompressPanel::formatGrid() {
  auto* grid = new QGridLayout;
  grid->addWidget(new QLabel(tr("<b>Map</b>"), this), 0, 0);
  grid->addWidget(new QLabel(tr("<b>Format</b>"), this), 0, 1);
  grid->addWidget(new QLabel(tr("<b>Quality</b>"), this), 0, 2);
  int gridRow = 1;
  for (core::MapSlot slot : core::kAllMapSlots) {
    Row& row = m_rows[std::size_t(slot)];
    row.label = new QLabel(toQString(core::mapSlotLabel(slot)), this);
    row.format = new QComboBox(this);
    row.format->addItem(tr("Uncompressed"), kUncompressed);
    for (core::TextureFormat format : core::formatsForSlot(slot)) {
      const core::TextureFormatInfo& info = core::textureFormatInfo(format);
      row.format->addItem(
          tr("%1 — %2 bpp").arg(toQString(info.label)).arg(core::bitsPerPixel(format), 0, 'g', 3),
          int(format));
    }
    // Half floats (BC6H) for single-value maps (a float height), enabled for 16- and 32-bit
    // maps only (syncFromDocument: core::formatsForMap). A material's colour map is
    // sRGB-encoded, which BC6H cannot hold, so its row never lists them.
    for (const core::TextureFormatInfo& info : core::allTextureFormats()) {
      if (core::isHalfFloatFormat(info.format) &&
          core::mapSlotTexels(slot) == core::MapTexels::Scalar) {
        row.format->addItem(tr("%1 — %2 bpp, float maps")
                                .arg(toQString(info.label))
                                .arg(core::bitsPerPixel(info.format), 0, 'g', 3),
                            int(info.format));
      }
    }
    row.format->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    row.format->setMinimumContentsLength(10);
    row.quality = new QComboBox(this);
    for (core::CompressionQuality quality :
         {core::CompressionQuality::Fast, core::CompressionQuality::Normal,
          core::CompressionQuality::Best}) {
      row.quality->addItem(toQString(core::compressionQualityName(quality)), int(quality));
    }
    row.quality->setToolTip(
        tr("fast: range fit / astcenc fast; normal: cluster fit / medium; "
           "best: iterative cluster fit / thorough"));
    grid->addWidget(row.label, gridRow, 0);
    grid->addWidget(row.format, gridRow, 1);
    grid->addWidget(row.quality, gridRow, 2);
    ++gridRow;
    connect(row.format, &QComboBox::currentIndexChanged, this, [this, slot] { writeChoice(slot); });
    connect(row.quality, &QComboBox::currentIndexChanged, this,
            [this, slot] { writeChoice(slot); });
  }
  grid->setColumnStretch(1, 1);
  return grid;
}

void CompressPanel::createOptionsAndActions() {
  m_mipmaps = new QCheckBox(tr("Mipmaps"), this);
  m_mipmaps->setToolTip(
      tr("A full mip chain: colour filtered in linear light, normals "
         "renormalised, heights averaged; each level compressed. Without it the map ships "
         "as level 0 alone, and the viewport shows what that does far away (View > Distance)."));
  m_mipmaps->setChecked(true);
  m_mipFilter = new QComboBox(this);
  m_mipFilter->setObjectName(QStringLiteral("mipFilter"));
  m_mipFilter->addItem(tr("Box"), int(core::MipFilter::Box));
  m_mipFilter->addItem(tr("Kaiser"), int(core::MipFilter::Kaiser));
  m_mipFilter->setToolTip(
      tr("How each mip level is filtered from the one above: Box averages 2×2 texels; Kaiser "
         "(a windowed sinc, NVIDIA Texture Tools' default) keeps the distant levels sharper "
         "without the box's aliasing. The viewport samples this chain, original or compressed: "
         "View > Distance shows the levels a far view reads."));
  m_roughnessFold = new QCheckBox(tr("Roughness from normals"), this);
  m_roughnessFold->setObjectName(QStringLiteral("roughnessFromNormals"));
  m_roughnessFold->setToolTip(
      tr("Widen the roughness map's mips by the normal map's spread under each texel "
         "(Toksvig): far away, bumps average into a flat normal, and without this the surface "
         "turns into a mirror with a shimmering highlight. Needs a compressed roughness map with "
         "mipmaps and a normal map of its size; the viewport and the export use it."));
  m_zstd = new QSpinBox(this);
  m_zstd->setRange(0, core::kMaxZstdLevel);
  m_zstd->setSpecialValueText(tr("off"));
  m_zstd->setPrefix(tr("level "));
  m_zstd->setToolTip(
      tr("KTX2 files: supercompress the blocks with Zstandard (lossless; 1 fastest, 22 "
         "smallest). The GPU gets the same blocks; the file and the download shrink. The "
         "results show the size on disk."));
  m_rdo = new QSlider(Qt::Horizontal, this);
  m_rdo->setObjectName(QStringLiteral("rdoLambda"));
  m_rdo->setRange(0, kRdoSteps);
  m_rdo->setToolTip(
      tr("Rate-distortion optimisation for BC1, BC3, BC4, BC5 and BC7: blocks repeat their "
         "neighbours' bytes where that costs little quality, so the file after Zstandard (or a "
         "game's own LZ) shrinks. Off at the left; further right trades more (lambda 0.5 to 768). "
         "On release the maps are compressed again and the results show the new size and "
         "quality."));
  m_rdoLabel = new QLabel(this);
  m_rdoLabel->setMinimumWidth(m_rdoLabel->fontMetrics().horizontalAdvance(tr("RDO 512")));
  m_compress = new QPushButton(tr("Compress"), this);
  m_compress->setToolTip(tr("Compress the chosen maps in the background (Ctrl+Shift+K)"));
  m_cancel = new QPushButton(tr("Cancel"), this);
  m_cancel->setEnabled(false);
  m_progress = new QProgressBar(this);
  m_progress->setRange(0, 1000);
  m_progress->setTextVisible(false);
  m_status = new QLabel(tr("Choose a format per map, then Compress."), this);
  m_status->setWordWrap(true);
}

// What the viewport shows, the results table and what can be done with a result.
void CompressPanel::createResults() {
  m_view = new QComboBox(this);
  m_view->addItem(tr("Original maps"), int(ViewDocument::CompressedView::Original));
  m_view->addItem(tr("Compressed maps"), int(ViewDocument::CompressedView::Compressed));
  m_view->addItem(tr("Wipe: original | compressed"), int(ViewDocument::CompressedView::Wipe));
  m_view->setToolTip(tr("What the 3D viewport shows; in the wipe, drag the divider"));
  m_view->setEnabled(false);

  m_results = new QTableWidget(0, 4, this);
  m_results->setHorizontalHeaderLabels(
      {tr("Map"), tr("Format"), tr("Rate · KTX2 on disk"), tr("Quality")});
  m_results->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_results->setSelectionMode(QAbstractItemView::SingleSelection);
  m_results->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_results->verticalHeader()->hide();
  m_results->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_results->horizontalHeader()->setStretchLastSection(true);
  m_results->setWordWrap(true);
  m_results->setMinimumHeight(110);

  m_compareButton = new QPushButton(tr("Compare 2D…"), this);
  m_compareButton->setToolTip(tr("Wipe, side by side and difference views of the selected map"));
  m_compareAllButton = new QPushButton(tr("Compare All Formats…"), this);
  m_compareAllButton->setToolTip(
      tr("Compress the selected map (or the first one) in every format and chart the results"));
  m_chooseForMeButton = new QPushButton(tr("Choose for Me…"), this);
  m_chooseForMeButton->setObjectName(QStringLiteral("chooseForMe"));
  m_chooseForMeButton->setToolTip(
      tr("Pick every map's format for a size budget or a quality target, judged on the "
         "rendered material"));
  m_saveButton = new QPushButton(tr("Save As…"), this);
  m_saveButton->setToolTip(tr("Save the selected compressed map as DDS or KTX2"));
}

void CompressPanel::layOut(QGridLayout* formats) {
  auto* actions = new QHBoxLayout;
  actions->addWidget(m_compress);
  actions->addWidget(m_cancel);
  actions->addWidget(m_chooseForMeButton);
  auto* viewRow = new QHBoxLayout;
  viewRow->addWidget(new QLabel(tr("Viewport:"), this));
  viewRow->addWidget(m_view, 1);
  auto* rowButtons = new QHBoxLayout;
  rowButtons->addWidget(m_compareButton);
  rowButtons->addWidget(m_compareAllButton);
  rowButtons->addWidget(m_saveButton);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(formats);
  auto* options = new QHBoxLayout;
  options->addWidget(m_mipmaps);
  options->addWidget(m_mipFilter);
  options->addStretch(1);
  options->addWidget(new QLabel(tr("KTX2 Zstandard:"), this));
  options->addWidget(m_zstd);
  layout->addLayout(options);
  auto* rdoRow = new QHBoxLayout;
  rdoRow->addWidget(new QLabel(tr("Smaller after Zstd:"), this));
  rdoRow->addWidget(m_rdo, 1);
  rdoRow->addWidget(m_rdoLabel);
  layout->addLayout(rdoRow);
  layout->addWidget(m_roughnessFold);
  layout->addLayout(actions);
  layout->addWidget(m_progress);
  layout->addWidget(m_status);
  layout->addLayout(viewRow);
  layout->addWidget(m_results, 1);
  layout->addLayout(rowButtons);
}

void CompressPanel::connectSignals() {
  connect(m_compress, &QPushButton::clicked, this, &CompressPanel::compress);
  connect(m_cancel, &QPushButton::clicked, this, &CompressPanel::cancel);
  connect(m_compareButton, &QPushButton::clicked, this, &CompressPanel::openCompare);
  connect(m_compareAllButton, &QPushButton::clicked, this, &CompressPanel::openCompareAll);
  connect(m_chooseForMeButton, &QPushButton::clicked, this, &CompressPanel::openChooseForMe);
  connect(m_saveButton, &QPushButton::clicked, this, &CompressPanel::saveSelected);
  connect(m_results, &QTableWidget::cellDoubleClicked, this, &CompressPanel::openCompare);
  connect(m_view, &QComboBox::currentIndexChanged, this, [this] {
    m_viewDocument->setCompressedView(ViewDocument::CompressedView(m_view->currentData().toInt()));
  });
  connect(m_runner, &CompressionRunner::progress, this,
          [this](double fraction, const QString& what) {
            m_progress->setValue(int(std::lround(fraction * 1000.0)));
            m_status->setText(tr("Compressing %1…").arg(what));
          });
  connect(m_runner, &CompressionRunner::finished, this, &CompressPanel::showFinished);
  connect(m_runner, &CompressionRunner::cancelled, this, [this] {
    m_wipeWhenCompressed = false;
    m_compress->setEnabled(true);
    m_cancel->setEnabled(false);
    m_progress->setValue(0);
    m_status->setText(tr("Cancelled; the previous results are unchanged."));
  });
  connect(m_runner, &CompressionRunner::failed, this, [this](const QString& message) {
    m_wipeWhenCompressed = false;
    m_compress->setEnabled(true);
    m_cancel->setEnabled(false);
    m_progress->setValue(0);
    m_status->setText(tr("Compression failed: %1").arg(message));
  });
  connect(m_document, &MaterialDocument::materialReset, this, [this] {
    syncFromDocument();
    dropStalePreviews();
  });
  connect(m_document, &MaterialDocument::mapChanged, this, [this] {
    syncFromDocument();
    dropStalePreviews();
  });
  connect(m_document, &MaterialDocument::compressionChanged, this, [this] { syncFromDocument(); });
  connect(m_mipmaps, &QCheckBox::toggled, this, [this] { writeMipChain(); });
  connect(m_rdo, &QSlider::valueChanged, this, [this] {
    showRdoValue();
    if (!m_rdo->isSliderDown())
      writeRdo();  // keys and clicks; a drag writes on release
  });
  connect(m_rdo, &QSlider::sliderReleased, this, [this] { writeRdo(); });
  connect(m_mipFilter, &QComboBox::activated, this, [this] { writeMipChain(); });
  connect(m_roughnessFold, &QCheckBox::toggled, this, [this](bool on) {
    core::MapCompression choice = m_document->compression(core::MapSlot::Roughness);
    if (m_syncing || !choice || choice->roughnessFromNormals == on)
      return;
    choice->roughnessFromNormals = on;
    m_document->setCompression(core::MapSlot::Roughness, choice);
  });
}

// The RDO slider's steps: off, then round lambdas from 0.5 to 768, each 1.33 to 2 times the last
// (1, 2, 3, 4, 6, 8, ...), so the mild end has room and the label reads as a number one types.
namespace {
constexpr std::array<double, 21> kRdoLambdaSteps = {0.0,  0.5,   1.0,   2.0,   3.0,   4.0,   6.0,
                                                    8.0,  12.0,  16.0,  24.0,  32.0,  48.0,  64.0,
                                                    96.0, 128.0, 192.0, 256.0, 384.0, 512.0, 768.0};
}  // namespace

double CompressPanel::rdoLambda() const {
  return kRdoLambdaSteps[std::size_t(std::clamp(m_rdo->value(), 0, kRdoSteps))];
}

int CompressPanel::rdoStep(double lambda) {
  int nearest = 0;
  for (int step = 1; step <= kRdoSteps; ++step) {
    if (std::abs(kRdoLambdaSteps[std::size_t(step)] - lambda) <
        std::abs(kRdoLambdaSteps[std::size_t(nearest)] - lambda))
      nearest = step;
  }
  return nearest;
}

void CompressPanel::showRdoValue() {
  const double lambda = rdoLambda();
  m_rdoLabel->setText(lambda == 0.0 ? tr("off") : tr("RDO %1").arg(lambda, 0, 'g', 3));
}

// The trade is one choice for every map whose format has RDO, written as one undo step; with
// results on show, the maps are compressed again so the table shows the size and quality.
void CompressPanel::writeRdo() {
  if (m_syncing)
    return;
  const float lambda = float(rdoLambda());
  bool changes = false;
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MapCompression& choice = m_document->compression(slot);
    changes =
        changes || (choice && core::formatHasRdo(choice->format) && choice->rdoLambda != lambda);
  }
  if (!changes)
    return;
  // RDO pays after LZ: with Zstandard off the sizes shown would not move.
  if (lambda > 0.0f && m_zstd->value() == 0)
    m_zstd->setValue(kRdoZstdLevel);
  m_document->undoStack()->beginMacro(lambda > 0.0f ? tr("RDO %1").arg(double(lambda), 0, 'g', 3)
                                                    : tr("No RDO"));
  for (core::MapSlot slot : core::kAllMapSlots) {
    core::MapCompression choice = m_document->compression(slot);
    if (!choice || !core::formatHasRdo(choice->format))
      continue;
    choice->rdoLambda = lambda;
    m_document->setCompression(slot, choice);
  }
  m_document->undoStack()->endMacro();
  if (!m_outcomes.empty() && !m_runner->isRunning())
    compress();
}

// The mip chain is one choice for every compressed map (as the panel compresses them): written
// into each slot's choice, so presets save it and the viewport samples it, as one undo step.
void CompressPanel::writeMipChain() {
  m_mipFilter->setEnabled(m_mipmaps->isChecked());
  if (m_syncing)
    return;
  const bool mipmaps = m_mipmaps->isChecked();
  const auto filter = core::MipFilter(m_mipFilter->currentData().toInt());
  bool changes = false;
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MapCompression& choice = m_document->compression(slot);
    changes = changes || (choice && (choice->mipmaps != mipmaps || choice->mipFilter != filter));
  }
  if (!changes)
    return;
  m_document->undoStack()->beginMacro(mipmaps ? tr("Mip chain: %1").arg(m_mipFilter->currentText())
                                              : tr("No mipmaps"));
  for (core::MapSlot slot : core::kAllMapSlots) {
    core::MapCompression choice = m_document->compression(slot);
    if (!choice)
      continue;
    choice->mipmaps = mipmaps;
    choice->mipFilter = filter;
    m_document->setCompression(slot, choice);
  }
  m_document->undoStack()->endMacro();
}

void CompressPanel::showFinished(const std::vector<core::CompressionOutcome>& outcomes) {
  m_compress->setEnabled(true);
  m_cancel->setEnabled(false);
  m_progress->setValue(1000);
  double seconds = 0.0;
  for (const core::CompressionOutcome& outcome : outcomes) {
    m_outcomes[outcome.job.slot] = outcome;
    seconds += outcome.report.encodeSeconds;
  }
  dropStalePreviews();
  QString status =
      tr("Compressed %n map(s) in %1 s.", nullptr, int(outcomes.size())).arg(seconds, 0, 'f', 2);
  for (const core::CompressionOutcome& outcome : outcomes) {
    for (const std::string& warning : outcome.warnings) {
      status += tr(" The %1 map: %2.")
                    .arg(toQString(core::mapSlotLabel(outcome.job.slot)).toLower(),
                         QString::fromStdString(warning));
    }
  }
  m_status->setText(status);
  if (m_view->currentIndex() == 0 || m_wipeWhenCompressed)
    m_view->setCurrentIndex(m_view->findData(int(ViewDocument::CompressedView::Wipe)));
  m_wipeWhenCompressed = false;
  showOutcomes();
  showPreviews();
}

CompressPanel::~CompressPanel() {
  m_runner->cancel();
  m_runner->waitForFinished();
}

// A half-float item is enabled only for a map it can take (a linear map of 16 or 32 bits per
// channel); its tooltip says why otherwise.
void CompressPanel::enableFloatFormats(QComboBox* box,
                                       const std::shared_ptr<const core::Image>& map,
                                       core::MapSlot slot) {
  auto* model = qobject_cast<QStandardItemModel*>(box->model());
  if (!model)
    return;
  const std::vector<core::TextureFormat> offered =
      map ? core::formatsForMap(*map, slot) : std::vector<core::TextureFormat>{};
  for (int i = 0; i < box->count(); ++i) {
    const int item = box->itemData(i).toInt();
    if (item == kUncompressed || !core::isHalfFloatFormat(core::TextureFormat(item)))
      continue;
    const bool usable =
        std::find(offered.begin(), offered.end(), core::TextureFormat(item)) != offered.end();
    model->item(i)->setEnabled(usable);
    model->item(i)->setToolTip(usable ? tr("Half floats: values beyond 0..1 and fine steps kept")
                                      : tr("For EXR, HDR and 16-bit float maps (linear); this "
                                           "map is 8-bit or sRGB"));
  }
}

void CompressPanel::syncFromDocument() {
  m_syncing = true;
  for (core::MapSlot slot : core::kAllMapSlots) {
    Row& row = m_rows[std::size_t(slot)];
    const bool present = m_document->material().hasMap(slot);
    row.label->setEnabled(present);
    row.format->setEnabled(present);
    row.quality->setEnabled(present);
    enableFloatFormats(row.format, present ? m_document->material().map(slot).image : nullptr,
                       slot);
    const core::MapCompression& choice = m_document->compression(slot);
    const int formatIndex = row.format->findData(choice ? int(choice->format) : kUncompressed);
    row.format->setCurrentIndex(std::max(0, formatIndex));
    row.quality->setCurrentIndex(
        row.quality->findData(int(choice ? choice->quality : core::CompressionQuality::Normal)));
  }
  // The chain shown is the first chosen map's (the panel writes one chain into all of them).
  for (core::MapSlot slot : core::kAllMapSlots) {
    if (const core::MapCompression& choice = m_document->compression(slot)) {
      m_mipmaps->setChecked(choice->mipmaps);
      m_mipFilter->setCurrentIndex(m_mipFilter->findData(int(choice->mipFilter)));
      break;
    }
  }
  m_mipFilter->setEnabled(m_mipmaps->isChecked());
  // The trade shown is the first map's that has RDO (the panel writes one into all of them).
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MapCompression& choice = m_document->compression(slot);
    if (choice && core::formatHasRdo(choice->format)) {
      m_rdo->setValue(rdoStep(choice->rdoLambda));
      break;
    }
  }
  showRdoValue();
  const core::MapCompression& roughness = m_document->compression(core::MapSlot::Roughness);
  m_roughnessFold->setEnabled(roughness && roughness->mipmaps &&
                              m_document->material().hasMap(core::MapSlot::Roughness) &&
                              m_document->material().hasMap(core::MapSlot::Normal));
  m_roughnessFold->setChecked(roughness && roughness->roughnessFromNormals);
  m_syncing = false;
}

void CompressPanel::writeChoice(core::MapSlot slot) {
  if (m_syncing)
    return;
  const Row& row = m_rows[std::size_t(slot)];
  const int format = row.format->currentData().toInt();
  core::MapCompression choice;
  if (format != kUncompressed) {
    // A preset's choice keeps its Zstandard level and perceptual flag; the mip chain is the
    // panel's (one for every map).
    const core::MapCompression& previous = m_document->compression(slot);
    choice = core::CompressionSettings{
        core::TextureFormat(format),
        core::CompressionQuality(row.quality->currentData().toInt()),
        m_mipmaps->isChecked(),
        previous ? previous->zstdLevel : m_zstd->value(),
        previous && previous->perceptual,
        core::MipFilter(m_mipFilter->currentData().toInt()),
        previous && previous->roughnessFromNormals,
        previous ? previous->alphaCoverage : 0.0f,
        core::formatHasRdo(core::TextureFormat(format)) ? float(rdoLambda()) : 0.0f};
  }
  m_document->setCompression(slot, choice);
}

void CompressPanel::compress() {
  const core::Material& material = m_document->material();
  bool anyChosen = false;
  for (core::MapSlot slot : core::kAllMapSlots) {
    anyChosen =
        anyChosen || (material.hasMap(slot) &&
                      m_rows[std::size_t(slot)].format->currentData().toInt() != kUncompressed);
  }
  if (!anyChosen) {
    // Nothing chosen yet: the usual choices (BC1 or BC3 colour, BC5 normals, BC4 data), as one
    // undo step.
    m_document->undoStack()->beginMacro(tr("Suggested compression formats"));
    for (core::MapSlot slot : core::kAllMapSlots) {
      if (const core::Image* image = material.image(slot)) {
        Row& row = m_rows[std::size_t(slot)];
        row.format->setCurrentIndex(
            row.format->findData(int(core::suggestedFormat(slot, image->channels()))));
      }
    }
    m_document->undoStack()->endMacro();
  }
  std::vector<core::CompressionJob> jobs;
  const double heightScale = material.parameter(core::ParamId::HeightScale);
  for (core::MapSlot slot : core::kAllMapSlots) {
    const Row& row = m_rows[std::size_t(slot)];
    const int format = row.format->currentData().toInt();
    if (!material.hasMap(slot) || format == kUncompressed)
      continue;
    const core::MapCompression& choice = m_document->compression(slot);
    core::CompressionJob job;
    job.map = material.map(slot).image;
    job.slot = slot;
    job.settings = {core::TextureFormat(format),
                    core::CompressionQuality(row.quality->currentData().toInt()),
                    m_mipmaps->isChecked(),
                    m_zstd->value(),
                    false,
                    core::MipFilter(m_mipFilter->currentData().toInt()),
                    choice && choice->roughnessFromNormals,
                    choice ? choice->alphaCoverage : 0.0f,
                    choice ? choice->rdoLambda : 0.0f};
    job.heightScale = heightScale;
    job.spreadNormals = material.map(core::MapSlot::Normal).image;
    jobs.push_back(std::move(job));
  }
  if (jobs.empty()) {
    m_status->setText(tr("The material has no maps to compress."));
    return;
  }
  m_compress->setEnabled(false);
  m_cancel->setEnabled(true);
  m_progress->setValue(0);
  m_runner->start(std::move(jobs));
}

void CompressPanel::cancel() {
  m_runner->cancel();
}

void CompressPanel::dropStalePreviews() {
  // A preview belongs to the map it was made from; once the slot holds another, it is gone.
  bool dropped = false;
  for (auto it = m_outcomes.begin(); it != m_outcomes.end();) {
    const bool current = m_document->material().map(it->first).image == it->second.job.map;
    dropped = dropped || !current;
    it = current ? std::next(it) : m_outcomes.erase(it);
  }
  if (dropped) {
    showOutcomes();
    showPreviews();
  }
}

void CompressPanel::showOutcomes() {
  m_results->setRowCount(0);
  for (const auto& [slot, outcome] : m_outcomes) {
    const int row = m_results->rowCount();
    m_results->insertRow(row);
    auto* name = new QTableWidgetItem(toQString(core::mapSlotLabel(slot)));
    name->setData(Qt::UserRole, int(slot));
    m_results->setItem(row, 0, name);
    const core::TextureFormatInfo& info = core::textureFormatInfo(outcome.job.settings.format);
    auto* formatItem = new QTableWidgetItem(toQString(info.name).toUpper());
    formatItem->setToolTip(toQString(info.label));
    m_results->setItem(row, 1, formatItem);
    const core::SizeFigures& size = *outcome.report.size;
    auto* sizeItem = new QTableWidgetItem(
        tr("%1 bpp, %2:1").arg(size.bitsPerPixel, 0, 'g', 3).arg(size.ratioToSource, 0, 'g', 3));
    sizeItem->setText(sizeItem->text() +
                      tr(" · %1 KiB").arg(double(size.ktx2Bytes) / 1024.0, 0, 'f', 0));
    sizeItem->setToolTip(
        tr("%1 KiB of blocks with mipmaps; %2:1 against RGBA8; the KTX2 file is %3 bytes%4")
            .arg(double(size.bytes) / 1024.0, 0, 'f', 0)
            .arg(size.ratioToRgba8, 0, 'g', 3)
            .arg(size.ktx2Bytes)
            .arg(size.zstdLevel > 0 ? tr(" (Zstandard level %1)").arg(size.zstdLevel) : ""));
    m_results->setItem(row, 2, sizeItem);
    m_results->setItem(row, 3, new QTableWidgetItem(qualityText(outcome)));
  }
  m_results->resizeRowsToContents();
  if (m_results->rowCount() > 0 && m_results->selectedItems().isEmpty())
    m_results->selectRow(0);
  const bool any = !m_outcomes.empty();
  m_view->setEnabled(any);
  m_compareButton->setEnabled(any);
  m_saveButton->setEnabled(any);
}

void CompressPanel::showPreviews() {
  std::vector<ViewDocument::CompressedPreview> previews;
  for (const auto& [slot, outcome] : m_outcomes)
    previews.push_back({slot, outcome.job.map, outcome.texture, outcome.decoded});
  m_viewDocument->setCompressedPreviews(std::move(previews));
}

std::optional<core::MapSlot> CompressPanel::selectedSlot() const {
  const QList<QTableWidgetItem*> selected = m_results->selectedItems();
  if (selected.isEmpty())
    return std::nullopt;
  return core::MapSlot(m_results->item(selected.front()->row(), 0)->data(Qt::UserRole).toInt());
}

CompareDialog* CompressPanel::compareDialog() {
  if (!m_compareDialog)
    m_compareDialog = new CompareDialog(this);
  return m_compareDialog;
}

CompareAllDialog* CompressPanel::compareAllDialog() {
  if (!m_compareAllDialog) {
    m_compareAllDialog = new CompareAllDialog(this);
    connect(m_compareAllDialog, &CompareAllDialog::formatChosen, this,
            [this](core::MapSlot slot, core::TextureFormat format, float rdoLambda) {
              Row& row = m_rows[std::size_t(slot)];
              row.format->setCurrentIndex(row.format->findData(int(format)));
              if (rdoLambda > 0.0f)
                m_rdo->setValue(rdoStep(rdoLambda));  // one trade for every map, as the slider
              Q_EMIT statusMessage(tr("%1 map will be compressed as %2")
                                       .arg(toQString(core::mapSlotLabel(slot)),
                                            toQString(core::textureFormatInfo(format).label)));
            });
  }
  return m_compareAllDialog;
}

ChooseForMeDialog* CompressPanel::chooseForMeDialog() {
  if (!m_chooseForMeDialog) {
    m_chooseForMeDialog = new ChooseForMeDialog(m_document, m_viewDocument, this);
    connect(m_chooseForMeDialog, &ChooseForMeDialog::applied, this, [this] {
      m_wipeWhenCompressed = true;
      if (m_zstd->value() == 0)
        m_zstd->setValue(kRdoZstdLevel);  // the sizes the choice was made for
      compress();
      Q_EMIT statusMessage(tr("Choose for Me's formats applied; compressing for the wipe"));
    });
  }
  return m_chooseForMeDialog;
}

void CompressPanel::openChooseForMe() {
  ChooseForMeDialog* dialog = chooseForMeDialog();
  dialog->show();
  dialog->raise();
}

void CompressPanel::openCompare() {
  const std::optional<core::MapSlot> slot = selectedSlot();
  if (!slot || !m_outcomes.count(*slot))
    return;
  const core::CompressionOutcome& outcome = m_outcomes.at(*slot);
  CompareDialog* dialog = compareDialog();
  dialog->setComparison(
      tr("%1 map as %2")
          .arg(toQString(core::mapSlotLabel(*slot)),
               toQString(core::textureFormatInfo(outcome.job.settings.format).label)),
      outcome.job.map, outcome.decoded, outcome.report);
  dialog->show();
  dialog->raise();
}

void CompressPanel::openCompareAll() {
  std::optional<core::MapSlot> slot = selectedSlot();
  if (!slot) {
    for (core::MapSlot candidate : core::kAllMapSlots) {
      if (m_document->material().hasMap(candidate)) {
        slot = candidate;
        break;
      }
    }
  }
  if (!slot) {
    m_status->setText(tr("Load a map first: there is nothing to compare."));
    return;
  }
  const Row& row = m_rows[std::size_t(*slot)];
  CompareAllDialog* dialog = compareAllDialog();
  std::optional<core::TextureFormat> materialChoice;
  float materialChoiceRdo = 0.0f;
  if (m_chooseForMeDialog && m_chooseForMeDialog->chosen().count(*slot)) {
    materialChoice = m_chooseForMeDialog->chosen().at(*slot).format;
    materialChoiceRdo = m_chooseForMeDialog->chosen().at(*slot).rdoLambda;
  }
  dialog->setMaterialChoice(materialChoice, materialChoiceRdo);
  // The rendered error is judged from the viewport's camera and light, as Choose for Me's.
  dialog->setMaterial(m_document->toPreset(m_viewDocument->viewState()));
  dialog->start(*slot, m_document->material().map(*slot).image,
                core::CompressionQuality(row.quality->currentData().toInt()),
                m_mipmaps->isChecked(), m_zstd->value(),
                m_document->material().parameter(core::ParamId::HeightScale));
  dialog->show();
  dialog->raise();
}

void CompressPanel::saveSelected() {
  const std::optional<core::MapSlot> slot = selectedSlot();
  if (!slot || !m_outcomes.count(*slot))
    return;
  const core::CompressionOutcome& outcome = m_outcomes.at(*slot);
  const core::TextureFormat format = outcome.job.settings.format;
  QStringList filters;  // KTX2 first: it holds every format
  for (core::TextureContainer container :
       {core::TextureContainer::Ktx2, core::TextureContainer::Dds}) {
    if (core::containerHolds(container, format)) {
      const core::TextureContainerInfo& info = core::textureContainerInfo(container);
      filters << QStringLiteral("%1 (*.%2)").arg(toQString(info.label), toQString(info.extension));
    }
  }
  const QString filter = filters.join(QStringLiteral(";;"));
  QString path = QFileDialog::getSaveFileName(
      this, tr("Save Compressed %1 Map").arg(toQString(core::mapSlotLabel(*slot))),
      QString::fromStdString(std::string(core::mapSlotName(*slot)) + "_" +
                             std::string(core::textureFormatInfo(format).name) + ".ktx2"),
      filter);
  if (path.isEmpty())
    return;
  if (!core::containerForPath(path.toStdString()))
    path += QStringLiteral(".ktx2");
  // The Zstandard level applies to KTX2; a DDS is written without (it has no supercompression).
  const bool ktx2 = core::containerForPath(path.toStdString()) == core::TextureContainer::Ktx2;
  if (core::Status saved = core::saveCompressedTexture(*outcome.texture, path.toStdString(),
                                                       ktx2 ? outcome.job.settings.zstdLevel : 0);
      !saved) {
    QMessageBox::warning(this, tr("Save Compressed Map"), QString::fromStdString(saved.error()));
    return;
  }
  Q_EMIT statusMessage(tr("Saved %1").arg(path));
}

}  // namespace relief::ui::inline panels
