// ChooseForMeDialog: "Choose for Me" in the Compress panel. Given a size budget for all the
// material's maps as shipped (KTX2 after Zstandard) or a rendered quality target (FLIP or PSNR of
// the lit, parallax-mapped material), it picks every map's format, judged on the rendered
// material (renderer/CompressionChooser.h). The work runs in `relief-cli compress --preset`
// as a child process: it renders with a GL context of its own, off the editor's GUI thread,
// and a crash there cannot take the editor down. The material is handed over as a preset in
// a temporary folder (maps the editor made are written there too). The table lists every
// candidate, its bytes and its error alone; Apply writes the choices into the document (one
// undo step) for the panel to compress and show in the 3D wipe.
#pragma once

#include "core/compression/TextureFormat.h"
#include "core/material/MapSlot.h"
#include "ui/Forward.h"

#include <QDialog>
#include <QJsonObject>
#include <QSize>

#include <map>
#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTemporaryDir;

namespace relief::ui::inline compare {

class ChooseForMeDialog : public QDialog {
  Q_OBJECT

 public:
  ChooseForMeDialog(MaterialDocument* document, ViewDocument* view, QWidget* parent = nullptr);
  ~ChooseForMeDialog() override;

  // The relief-cli run: beside the editor's executable (where both are installed and built).
  void setCliPath(const QString& path) { m_cliPath = path; }
  // The size the CLI renders its three views at (`--size`); empty: the CLI's default, 320x240.
  // Smaller is coarser and quicker (the GUI tests choose on 128x96 views).
  void setViewSize(const QSize& size) { m_viewSize = size; }

  QComboBox* goalBox() const { return m_goal; }
  QDoubleSpinBox* valueBox() const { return m_value; }
  QComboBox* deviceBox() const { return m_device; }
  QPushButton* chooseButton() const { return m_choose; }
  QPushButton* applyButton() const { return m_apply; }
  QTableWidget* table() const { return m_table; }
  QLabel* summary() const { return m_summary; }
  bool running() const;
  // The last finished run's choice: a format and an RDO trade (0: none) per map; empty when
  // nothing was chosen.
  struct Choice {
    core::TextureFormat format;
    float rdoLambda = 0.0f;
  };
  const std::map<core::MapSlot, Choice>& chosen() const { return m_chosen; }

 public Q_SLOTS:
  void choose();  // starts a run, or cancels the running one
  void apply();

 Q_SIGNALS:
  // The choices are in the document; the panel compresses them and shows the wipe.
  void applied();

 protected:
  void reject() override;  // Close also cancels

 private:
  enum class Goal { Budget, Flip, Psnr };
  void goalChanged();
  void finished(int exitCode, const QJsonObject& report, const QString& errors);
  void showReport(const QJsonObject& report);
  void setRunning(bool running);

  MaterialDocument* m_document;
  ViewDocument* m_view;
  QString m_cliPath;
  QSize m_viewSize;
  QComboBox* m_goal;
  QDoubleSpinBox* m_value;
  QComboBox* m_device;
  QPushButton* m_choose;
  QPushButton* m_apply;
  QProgressBar* m_progress;
  QLabel* m_summary;
  QTableWidget* m_table;
  CliProcess* m_process;
  std::unique_ptr<QTemporaryDir> m_folder;
  std::map<core::MapSlot, Choice> m_chosen;
};

}  // namespace relief::ui::inline compare
