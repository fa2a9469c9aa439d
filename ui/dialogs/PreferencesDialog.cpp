// PreferencesDialog; see PreferencesDialog.h.
#include "ui/dialogs/PreferencesDialog.h"

#include "core/mesh/MeshPrimitives.h"
#include "ui/QtText.h"
#include "ui/settings/AppSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>
#include <QVBoxLayout>

namespace relief::ui::inline dialogs {

PreferencesDialog::PreferencesDialog(QWidget* parent)
    : QDialog(parent),
      m_autosave(new QSpinBox),
      m_openSample(new QCheckBox(tr("Open the bricks sample when started without files"))),
      m_defaultMesh(new QComboBox),
      m_nativeCompressed(new QCheckBox(tr("Upload compressed maps to the GPU as blocks"))) {
  setWindowTitle(tr("Preferences"));
  m_autosave->setRange(0, 60);
  m_autosave->setSuffix(tr(" min"));
  m_autosave->setSpecialValueText(tr("Off"));
  m_autosave->setToolTip(
      tr("How often unsaved changes are written to a recovery file, offered "
         "on the next start if Relief does not close properly."));
  m_autosave->setValue(settings::autosaveMinutes());
  m_openSample->setChecked(settings::openSampleOnStart());
  for (core::PrimitiveShape shape : core::allPrimitiveShapes())
    m_defaultMesh->addItem(toQString(core::primitiveShapeName(shape)));
  m_defaultMesh->setCurrentText(settings::defaultMesh());
  m_defaultMesh->setToolTip(tr("The mesh a new material is shown on."));

  m_nativeCompressed->setChecked(settings::nativeCompressedUploads());
  m_nativeCompressed->setToolTip(
      tr("Off: compressed previews are decoded by Relief and uploaded uncompressed, to compare "
         "the driver's decoding of the same blocks with Relief's."));
  auto* form = new QFormLayout;
  form->addRow(tr("Autosave every"), m_autosave);
  form->addRow(QString(), m_openSample);
  form->addRow(tr("Mesh for new materials"), m_defaultMesh);
  form->addRow(QString(), m_nativeCompressed);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    store();
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
}

void PreferencesDialog::store() {
  settings::setAutosaveMinutes(m_autosave->value());
  settings::setOpenSampleOnStart(m_openSample->isChecked());
  settings::setDefaultMesh(m_defaultMesh->currentText());
  settings::setNativeCompressedUploads(m_nativeCompressed->isChecked());
}

}  // namespace relief::ui::inline dialogs
