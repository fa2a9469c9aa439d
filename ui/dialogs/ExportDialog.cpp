// ExportDialog; see ExportDialog.h.
#include "ui/dialogs/ExportDialog.h"

#include "ui/QtText.h"
#include "ui/settings/AppSettings.h"
#include "ui/tasks/BackgroundTask.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace relief::ui::inline dialogs {

ExportDialog::ExportDialog(core::Preset preset, core::Mesh mesh, QWidget* parent)
    : QDialog(parent),
      m_preset(std::move(preset)),
      m_mesh(std::move(mesh)),
      m_kind(new QComboBox),
      m_folder(new QLineEdit),
      m_mapFormat(new QComboBox),
      m_textures(new QComboBox),
      m_explanation(new QLabel),
      m_progress(new QProgressBar),
      m_task(new BackgroundTask(this)) {
  setWindowTitle(tr("Export"));
  setObjectName(QStringLiteral("exportDialog"));
  for (const core::ExportKindInfo& kind : core::allExportKinds())
    m_kind->addItem(toQString(kind.label), int(kind.kind));
  for (const auto& format : core::packageMapFormats())
    m_mapFormat->addItem(toQString(format.label), int(format.value));
  m_mapFormat->setToolTip(
      tr("How the normal, height, AO and roughness maps are written; the "
         "colour map is always 8-bit sRGB PNG."));
  for (const auto& choice : core::packageTextureChoices())
    m_textures->addItem(toQString(choice.label), int(choice.value));
  m_textures->setToolTip(
      tr("Maps with a format chosen in the Compress panel are also written "
         "compressed, with their quality and mipmap choice"));
  const std::string stem = core::exportStem(m_preset.material);
  // Exports go where exports went before, not beside the preset (which may be a bundled one).
  m_folder->setText(settings::lastFolder(QStringLiteral("export"), false) + QLatin1Char('/') +
                    QString::fromStdString(stem) + QStringLiteral("_export"));
  auto* browse = new QPushButton(tr("Browse…"));
  browse->setAutoDefault(false);  // Return exports
  connect(browse, &QPushButton::clicked, this, [this] {
    QString start = m_folder->text();
    while (!start.isEmpty() && !QFileInfo(start).isDir())
      start =
          QFileInfo(start).absolutePath() == start ? QString() : QFileInfo(start).absolutePath();
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export into folder"), start);
    if (!folder.isEmpty())
      m_folder->setText(folder);
  });
  auto* folderRow = new QHBoxLayout;
  folderRow->addWidget(m_folder);
  folderRow->addWidget(browse);
  m_explanation->setWordWrap(true);
  m_explanation->setMinimumWidth(420);

  auto* form = new QFormLayout;
  form->addRow(tr("Export as"), m_kind);
  form->addRow(tr("Into folder"), folderRow);
  form->addRow(tr("Data maps"), m_mapFormat);
  form->addRow(tr("Compressed textures"), m_textures);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
  m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
  m_export->setDefault(true);
  m_cancel = buttons->button(QDialogButtonBox::Cancel);
  m_cancel->setAutoDefault(false);  // Return exports
  // Cancel stops a running export (the dialog stays, to try again); otherwise it closes.
  connect(buttons, &QDialogButtonBox::rejected, this, [this] {
    if (m_task->isRunning())
      m_task->cancel();
    else
      reject();
  });
  connect(m_export, &QPushButton::clicked, this, &ExportDialog::startExport);
  connect(m_task, &BackgroundTask::cancelled, this, [this] {
    m_export->setEnabled(true);
    m_progress->setVisible(false);
    m_explanation->setText(tr("Export cancelled; the folder may hold part of it."));
    Q_EMIT exportFinished(false);
  });
  m_progress->setRange(0, 0);  // busy: the exporters report no fraction
  m_progress->setVisible(false);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_explanation);
  layout->addWidget(m_progress);
  layout->addWidget(buttons);
  connect(m_kind, &QComboBox::currentIndexChanged, this, &ExportDialog::updateForKind);
  restoreChoices();
  updateForKind();
  m_kind->setFocus();
}

ExportDialog::~ExportDialog() = default;  // m_task, a child, cancels and waits

bool ExportDialog::isExporting() const {
  return m_task->isRunning();
}

core::ExportKind ExportDialog::currentKind() const {
  return core::ExportKind(m_kind->currentData().toInt());
}

void ExportDialog::updateForKind() {
  const core::ExportKindInfo& kind = core::exportKindInfo(currentKind());
  m_mapFormat->setEnabled(kind.usesPackageOptions);
  m_textures->setEnabled(kind.usesPackageOptions);
  m_explanation->setText(toQString(kind.description));
}

// The last export's target and options: an artist exports to the same engine again and again.
// The target is stored by its CLI name, the options by their values, so a reordered list keeps
// them.
void ExportDialog::restoreChoices() {
  const QString kind = settings::dialogChoice(QStringLiteral("export/kind"));
  for (const core::ExportKindInfo& info : core::allExportKinds()) {
    if (toQString(info.name) == kind)
      m_kind->setCurrentIndex(m_kind->findData(int(info.kind)));
  }
  const auto restore = [](QComboBox* box, const QString& key) {
    bool ok = false;
    const int value = settings::dialogChoice(key).toInt(&ok);
    if (ok && box->findData(value) >= 0)
      box->setCurrentIndex(box->findData(value));
  };
  restore(m_mapFormat, QStringLiteral("export/mapFormat"));
  restore(m_textures, QStringLiteral("export/textures"));
}

void ExportDialog::saveChoices() const {
  settings::setDialogChoice(QStringLiteral("export/kind"),
                            toQString(core::exportKindInfo(currentKind()).name));
  settings::setDialogChoice(QStringLiteral("export/mapFormat"),
                            QString::number(m_mapFormat->currentData().toInt()));
  settings::setDialogChoice(QStringLiteral("export/textures"),
                            QString::number(m_textures->currentData().toInt()));
}

bool ExportDialog::startExport() {
  const QString folder = m_folder->text().trimmed();
  if (folder.isEmpty()) {
    QMessageBox::warning(this, tr("Export"), tr("Choose a folder to export into."));
    return false;
  }
  core::ExportRequest request;
  request.kind = currentKind();
  request.preset = m_preset;
  if (core::exportKindInfo(request.kind).usesMesh)
    request.mesh = m_mesh;
  request.folder = folder.toStdString();
  request.package = {core::PackageMapFormat(m_mapFormat->currentData().toInt()),
                     core::PackageTextures(m_textures->currentData().toInt())};
  saveChoices();
  m_export->setEnabled(false);
  m_progress->setVisible(true);
  m_explanation->setText(tr("Exporting…"));
  using Outcome = core::Result<core::ExportResult>;
  m_task->run<Outcome>(
      [request = std::move(request)](const core::WorkControl& control) {
        return core::exportMaterial(request, control);
      },
      [this, folder](Outcome&& result) { finishExport(std::move(result), folder); });
  return true;
}

void ExportDialog::finishExport(core::Result<core::ExportResult>&& result, const QString& folder) {
  m_export->setEnabled(true);
  m_progress->setVisible(false);
  updateForKind();
  if (!result) {
    QMessageBox::critical(this, tr("Export failed"), QString::fromStdString(result.error()));
    Q_EMIT exportFinished(false);
    return;
  }
  m_writtenPath = QString::fromStdString(result->writtenPath);
  settings::setLastFolder(QStringLiteral("export"), QFileInfo(folder).absolutePath());
  QString message = tr("Wrote %1").arg(m_writtenPath);
  if (!result->notes.empty()) {
    QStringList notes;
    for (const std::string& note : result->notes)
      notes << QString::fromStdString(note);
    message +=
        tr("\n\nWhat the engine cannot show exactly:\n• ") + notes.join(QStringLiteral("\n• "));
  }
  QMessageBox box(QMessageBox::Information, tr("Export finished"), message, QMessageBox::Ok, this);
  box.setObjectName(QStringLiteral("exportFinished"));
  box.exec();
  Q_EMIT exportFinished(true);
  accept();
}

}  // namespace relief::ui::dialogs
