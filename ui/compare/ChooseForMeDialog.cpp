// ChooseForMeDialog; see ChooseForMeDialog.h.
#include "ui/compare/ChooseForMeDialog.h"

#include "core/base/ByteSize.h"
#include "core/preset/MaterialPreset.h"
#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/tasks/CliProcess.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace relief::ui::inline compare {
namespace {

// The supercompression the sizes are counted after: relief-cli's default for the chooser.
constexpr int kZstdLevel = 19;

QString psnrText(const QJsonValue& psnr) {
  return psnr.isNull() ? QObject::tr("identical")
                       : QObject::tr("%1 dB").arg(psnr.toDouble(), 0, 'f', 2);
}

QString bytesText(const QJsonValue& bytes) {
  return toQString(core::describeByteSize(std::uint64_t(bytes.toDouble())));
}

}  // namespace

ChooseForMeDialog::ChooseForMeDialog(MaterialDocument* document, ViewDocument* view,
                                     QWidget* parent)
    : QDialog(parent),
      m_document(document),
      m_view(view),
      m_cliPath(CliProcess::defaultProgram()),
      m_process(new CliProcess(this)) {
  setWindowTitle(tr("Choose for Me"));
  m_goal = new QComboBox(this);
  m_goal->setObjectName(QStringLiteral("chooseGoal"));
  m_goal->addItem(tr("Size budget (all maps, KTX2 + Zstandard)"), int(Goal::Budget));
  m_goal->addItem(tr("Rendered FLIP at most"), int(Goal::Flip));
  m_goal->addItem(tr("Rendered PSNR at least"), int(Goal::Psnr));
  m_goal->setToolTip(
      tr("A budget gets the least error that fits; a quality target gets the "
         "fewest bytes that reach it, judged on the rendered material"));
  m_value = new QDoubleSpinBox(this);
  m_value->setObjectName(QStringLiteral("chooseValue"));
  m_device = new QComboBox(this);
  m_device->setObjectName(QStringLiteral("chooseDevice"));
  m_device->addItem(tr("Desktop (BC1–BC7)"), QStringLiteral("desktop"));
  m_device->addItem(tr("Mobile (ETC2/EAC, ASTC)"), QStringLiteral("mobile"));
  m_choose = new QPushButton(tr("Choose"), this);
  m_choose->setObjectName(QStringLiteral("chooseRun"));
  m_choose->setDefault(true);
  m_apply = new QPushButton(tr("Apply to the 3D Wipe"), this);
  m_apply->setObjectName(QStringLiteral("chooseApply"));
  m_apply->setToolTip(
      tr("Use the chosen formats for the material's maps (one undo step), "
         "compress them and show the wipe: original | compressed"));
  m_apply->setEnabled(false);
  m_progress = new QProgressBar(this);
  m_progress->setRange(0, 100);
  m_progress->setValue(0);
  m_summary = new QLabel(tr("Each candidate format is compressed with its mip chain and "
                            "rendered close, grazing and far away."),
                         this);
  m_summary->setWordWrap(true);
  m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_table = new QTableWidget(0, 5, this);
  m_table->setHorizontalHeaderLabels(
      {tr("Map"), tr("Format"), tr("As shipped"), tr("FLIP alone"), tr("PSNR alone")});
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setSelectionMode(QAbstractItemView::NoSelection);
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setMinimumSize(460, 200);

  auto* form = new QFormLayout;
  form->addRow(tr("Goal:"), m_goal);
  form->addRow(tr("Value:"), m_value);
  form->addRow(tr("For:"), m_device);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_choose);
  buttons->addStretch(1);
  buttons->addWidget(m_apply);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_progress);
  layout->addWidget(m_summary);
  layout->addWidget(m_table, 1);
  layout->addLayout(buttons);

  connect(m_goal, &QComboBox::currentIndexChanged, this, &ChooseForMeDialog::goalChanged);
  connect(m_choose, &QPushButton::clicked, this, &ChooseForMeDialog::choose);
  connect(m_apply, &QPushButton::clicked, this, &ChooseForMeDialog::apply);
  connect(m_process, &CliProcess::progress, this,
          [this](double fraction) { m_progress->setValue(int(std::lround(fraction * 100.0))); });
  connect(m_process, &CliProcess::finished, this, &ChooseForMeDialog::finished);
  connect(m_process, &CliProcess::cancelled, this, [this] {
    setRunning(false);
    m_progress->setValue(0);
    m_summary->setText(tr("Cancelled."));
  });
  connect(m_process, &CliProcess::failedToStart, this, [this](const QString& message) {
    setRunning(false);
    m_summary->setText(message);
  });
  goalChanged();
}

ChooseForMeDialog::~ChooseForMeDialog() = default;  // the CliProcess kills a running child

bool ChooseForMeDialog::running() const {
  return m_process->running();
}

void ChooseForMeDialog::goalChanged() {
  switch (Goal(m_goal->currentData().toInt())) {
    case Goal::Budget:
      m_value->setRange(0.01, 100000.0);
      m_value->setDecimals(2);
      m_value->setSingleStep(0.5);
      m_value->setSuffix(tr(" MB"));
      m_value->setValue(8.0);
      break;
    case Goal::Flip:
      m_value->setRange(0.001, 0.5);
      m_value->setDecimals(3);
      m_value->setSingleStep(0.005);
      m_value->setSuffix(QString());
      m_value->setValue(0.02);
      break;
    case Goal::Psnr:
      m_value->setRange(10.0, 80.0);
      m_value->setDecimals(1);
      m_value->setSingleStep(1.0);
      m_value->setSuffix(tr(" dB"));
      m_value->setValue(40.0);
      break;
  }
}

void ChooseForMeDialog::setRunning(bool running) {
  m_choose->setText(running ? tr("Cancel") : tr("Choose"));
  m_goal->setEnabled(!running);
  m_value->setEnabled(!running);
  m_device->setEnabled(!running);
  if (running)
    m_apply->setEnabled(false);
}

void ChooseForMeDialog::choose() {
  if (running()) {
    m_process->cancel();  // `cancelled` follows
    return;
  }
  m_chosen.clear();
  m_table->setRowCount(0);
  m_progress->setValue(0);
  // The material as a preset in a folder of its own; maps made in the editor are written there.
  m_folder = std::make_unique<QTemporaryDir>();
  const QString presetPath = m_folder->filePath(QStringLiteral("material.relief"));
  core::Result<core::SavedPreset> saved =
      core::savePreset(m_document->toPreset(m_view->viewState()), presetPath.toStdString());
  if (!m_folder->isValid() || !saved) {
    m_summary->setText(
        tr("Cannot hand the material over: %1")
            .arg(saved ? m_folder->errorString() : QString::fromStdString(saved.error())));
    return;
  }
  QStringList arguments = {QStringLiteral("compress"), QStringLiteral("--preset"), presetPath};
  switch (Goal(m_goal->currentData().toInt())) {
    case Goal::Budget:
      arguments << QStringLiteral("--budget")
                << QString::number(std::llround(m_value->value() * 1e6));
      break;
    case Goal::Flip:
      arguments << QStringLiteral("--target-flip") << QString::number(m_value->value());
      break;
    case Goal::Psnr:
      arguments << QStringLiteral("--target-psnr") << QString::number(m_value->value());
      break;
  }
  arguments << QStringLiteral("--device") << m_device->currentData().toString()
            << QStringLiteral("--zstd") << QString::number(kZstdLevel)
            << QStringLiteral("--out-dir") << m_folder->filePath(QStringLiteral("chosen"))
            << QStringLiteral("--json") << QStringLiteral("--progress-lines");
  if (!m_viewSize.isEmpty()) {
    arguments << QStringLiteral("--size")
              << QStringLiteral("%1x%2").arg(m_viewSize.width()).arg(m_viewSize.height());
  }
  m_summary->setText(tr("Compressing and rendering each candidate…"));
  setRunning(true);
  m_process->start(m_cliPath, arguments);
}

void ChooseForMeDialog::finished(int exitCode, const QJsonObject& report, const QString& errors) {
  setRunning(false);
  if (!report.isEmpty())
    showReport(report);
  if (exitCode != 0) {
    m_progress->setValue(0);
    // The CLI's message names the goal and what comes closest; drop its program prefix.
    QString message = errors;
    message.replace(QStringLiteral("relief-cli: compress --preset: "), QString());
    message.replace(QStringLiteral("relief-cli: "), QString());
    m_summary->setText(message.isEmpty() ? tr("The choice failed (exit code %1).").arg(exitCode)
                                         : message);
    return;
  }
  m_progress->setValue(100);
}

void ChooseForMeDialog::showReport(const QJsonObject& report) {
  m_table->setRowCount(0);
  for (const QJsonValue& map : report.value(QStringLiteral("maps")).toArray()) {
    const std::optional<core::MapSlot> slot =
        core::findMapSlot(map[QStringLiteral("slot")].toString().toStdString());
    bool first = true;
    for (const QJsonValue& candidate : map[QStringLiteral("candidates")].toArray()) {
      const int row = m_table->rowCount();
      m_table->insertRow(row);
      const bool picked = candidate[QStringLiteral("chosen")].toBool();
      const QString format = candidate[QStringLiteral("format")].toString();
      const double rdo = candidate[QStringLiteral("rdo")].toDouble();
      const QString name = rdo > 0.0 ? tr("%1 · RDO %2").arg(format).arg(rdo) : format;
      const QStringList cells = {
          first && slot ? toQString(core::mapSlotLabel(*slot)) : QString(),
          picked ? tr("%1  ✓ chosen").arg(name) : name,
          bytesText(candidate[QStringLiteral("bytes")]),
          QString::number(candidate[QStringLiteral("flip")].toDouble(), 'f', 4),
          psnrText(candidate[QStringLiteral("psnr")])};
      for (int column = 0; column < cells.size(); ++column) {
        auto* item = new QTableWidgetItem(cells[column]);
        if (picked) {
          QFont font = item->font();
          font.setBold(true);
          item->setFont(font);
        }
        m_table->setItem(row, column, item);
      }
      if (picked && slot) {
        if (const auto found = core::findTextureFormat(format.toStdString()))
          m_chosen[*slot] = Choice{*found, float(rdo)};
      }
      first = false;
    }
  }
  const QJsonObject total = report.value(QStringLiteral("total")).toObject();
  if (report.value(QStringLiteral("met")).toBool() && !total.isEmpty()) {
    m_summary->setText(tr("Chosen: %1 as shipped; rendered with all maps compressed: FLIP %2, "
                          "PSNR %3 (mean of the close, grazing and far views).")
                           .arg(bytesText(total[QStringLiteral("bytes")]))
                           .arg(total[QStringLiteral("flip")].toDouble(), 0, 'f', 4)
                           .arg(psnrText(total[QStringLiteral("psnr")])));
  }
  m_apply->setEnabled(!m_chosen.empty());
}

void ChooseForMeDialog::apply() {
  if (m_chosen.empty())
    return;
  QStringList names;
  for (const auto& [slot, choice] : m_chosen)
    names << toQString(core::textureFormatInfo(choice.format).name);
  m_document->undoStack()->beginMacro(
      tr("Choose for Me: %1").arg(names.join(QStringLiteral(", "))));
  for (const auto& [slot, choice] : m_chosen) {
    core::CompressionSettings settings =
        m_document->compression(slot).value_or(core::CompressionSettings{});
    settings.format = choice.format;
    settings.rdoLambda = choice.rdoLambda;
    settings.quality = core::CompressionQuality::Normal;  // what the chooser measured
    settings.mipmaps = true;
    settings.zstdLevel = kZstdLevel;  // the size the choice was made for
    m_document->setCompression(slot, settings);
  }
  m_document->undoStack()->endMacro();
  Q_EMIT applied();
}

void ChooseForMeDialog::reject() {
  m_process->cancel();
  QDialog::reject();
}

}  // namespace relief::ui::inline compare
