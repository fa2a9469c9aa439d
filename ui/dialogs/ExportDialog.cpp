// ExportDialog; see ExportDialog.h.
#include "ui/dialogs/ExportDialog.h"

#include "core/exporters/GltfExport.h"
#include "core/exporters/GodotExport.h"
#include "core/exporters/PackageExport.h"
#include "ui/window/AppSettings.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace relief::ui::inline dialogs {
namespace {

enum Kind { Package, Gltf, Godot };

struct Outcome {
  QString error;
  QString written;
  QStringList notes;
};

}  // namespace

ExportDialog::ExportDialog(core::Preset preset, core::Mesh mesh, QWidget* parent)
    : QDialog(parent),
      m_preset(std::move(preset)),
      m_mesh(std::move(mesh)),
      m_kind(new QComboBox),
      m_folder(new QLineEdit),
      m_mapFormat(new QComboBox),
      m_textures(new QComboBox),
      m_explanation(new QLabel) {
  setWindowTitle(tr("Export"));
  setObjectName(QStringLiteral("exportDialog"));
  m_kind->addItem(tr("Package: maps and a preset in a folder"));
  m_kind->addItem(tr("glTF 2.0: mesh and material (.gltf, .bin, textures)"));
  m_kind->addItem(tr("Godot 4: StandardMaterial3D (.tres and textures)"));
  m_mapFormat->addItem(tr("16-bit PNG"));
  m_mapFormat->addItem(tr("8-bit PNG (dithered)"));
  m_mapFormat->addItem(tr("32-bit float EXR"));
  m_mapFormat->setToolTip(
      tr("How the normal, height, AO and roughness maps are written; the "
         "colour map is always 8-bit sRGB PNG."));
  m_textures->addItem(tr("KTX2"), int(core::PackageTextures::Ktx2));
  m_textures->addItem(tr("DDS for BC formats, KTX2 for the rest"),
                      int(core::PackageTextures::DdsWherePossible));
  m_textures->addItem(tr("None"), int(core::PackageTextures::None));
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
  QPushButton* exportButton = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
  exportButton->setDefault(true);
  buttons->button(QDialogButtonBox::Cancel)->setAutoDefault(false);  // Return exports
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(exportButton, &QPushButton::clicked, this, [this] {
    if (runExport())
      accept();
  });
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_explanation);
  layout->addWidget(buttons);
  connect(m_kind, &QComboBox::currentIndexChanged, this, &ExportDialog::updateForKind);
  updateForKind();
  m_kind->setFocus();
}

void ExportDialog::updateForKind() {
  const int kind = m_kind->currentIndex();
  m_mapFormat->setEnabled(kind == Package);
  m_textures->setEnabled(kind == Package);
  static const char* explanations[] = {
      QT_TR_NOOP("The maps in the chosen format and a .relief preset pointing at them: a folder "
                 "to copy into another project or hand to a colleague."),
      QT_TR_NOOP("The viewport's mesh with a metallic-roughness material (base colour, normal, "
                 "occlusion). glTF has no parallax: the height map and every Relief parameter "
                 "go into the material's extras. See docs/export.md."),
      QT_TR_NOOP("Godot's heightmap settings converted from Relief's (scale, deep parallax, "
                 "layers, flips); what Godot cannot show is listed after the export. See "
                 "docs/export.md."),
  };
  m_explanation->setText(tr(explanations[kind]));
}

bool ExportDialog::runExport() {
  const QString folder = m_folder->text().trimmed();
  if (folder.isEmpty()) {
    QMessageBox::warning(this, tr("Export"), tr("Choose a folder to export into."));
    return false;
  }
  const int kind = m_kind->currentIndex();
  const core::PackageMapFormat formats[] = {
      core::PackageMapFormat::Png16, core::PackageMapFormat::Png8, core::PackageMapFormat::Exr};
  const core::PackageMapFormat mapFormat = formats[m_mapFormat->currentIndex()];
  const auto textures = core::PackageTextures(m_textures->currentData().toInt());
  // Encoding large maps takes seconds: off the GUI thread, with a busy indicator.
  QFutureWatcher<Outcome> watcher;
  QProgressDialog progress(tr("Exporting…"), QString(), 0, 0, this);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(300);
  QEventLoop loop;
  connect(&watcher, &QFutureWatcher<Outcome>::finished, &loop, &QEventLoop::quit);
  watcher.setFuture(QtConcurrent::run(
      [preset = m_preset, mesh = m_mesh, folder, kind, mapFormat, textures]() -> Outcome {
        const std::string target = folder.toStdString();
        Outcome outcome;
        if (kind == Package) {
          auto written = core::exportPackage(preset, target, {mapFormat, textures});
          if (!written)
            outcome.error = QString::fromStdString(written.error());
          else
            outcome.written = QString::fromStdString(written.value());
        } else if (kind == Gltf) {
          auto written = core::exportGltf(preset, mesh, target);
          if (!written)
            outcome.error = QString::fromStdString(written.error());
          else
            outcome.written = QString::fromStdString(written.value());
        } else {
          auto written = core::exportGodot(preset, target);
          if (!written) {
            outcome.error = QString::fromStdString(written.error());
          } else {
            outcome.written = QString::fromStdString(written->tresPath);
            for (const std::string& note : written->notes)
              outcome.notes << QString::fromStdString(note);
          }
        }
        return outcome;
      }));
  if (!watcher.isFinished())
    loop.exec();
  progress.reset();
  const Outcome outcome = watcher.result();
  if (!outcome.error.isEmpty()) {
    QMessageBox::critical(this, tr("Export failed"), outcome.error);
    return false;
  }
  m_writtenPath = outcome.written;
  settings::setLastFolder(QStringLiteral("export"), QFileInfo(folder).absolutePath());
  QString message = tr("Wrote %1").arg(outcome.written);
  if (!outcome.notes.isEmpty()) {
    message +=
        tr("\n\nWhat Godot cannot show exactly:\n• ") + outcome.notes.join(QStringLiteral("\n• "));
  }
  QMessageBox box(QMessageBox::Information, tr("Export finished"), message, QMessageBox::Ok, this);
  box.setObjectName(QStringLiteral("exportFinished"));
  box.exec();
  return true;
}

}  // namespace relief::ui::inline dialogs
