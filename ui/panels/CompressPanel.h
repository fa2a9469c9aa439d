// CompressPanel: compressing the material's maps into GPU formats to judge them. A format and
// quality per map (kept in the document, so presets save them, one undo step per change), full
// mip chains optional; Compress runs in the background with progress and Cancel and never
// touches the maps themselves. The results (size, rate, PSNR/SSIM, angular error for normals,
// parallax shift for heights) are listed; the viewport shows the original, the compressed maps
// or a wipe between them; a row opens the 2D compare view, "compare all formats", or is saved
// as DDS or KTX2.
#pragma once

#include "core/material/MapSlot.h"
#include "ui/Forward.h"
#include "ui/tasks/CompressionRunner.h"

#include <QWidget>

#include <array>
#include <map>
#include <optional>

class QCheckBox;
class QGridLayout;
class QSlider;
class QSpinBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace relief::ui::inline panels {

class CompressPanel : public QWidget {
  Q_OBJECT

 public:
  CompressPanel(MaterialDocument* document, ViewDocument* view, QWidget* parent = nullptr);
  ~CompressPanel() override;

  QComboBox* formatBox(core::MapSlot slot) const { return m_rows[std::size_t(slot)].format; }
  QComboBox* qualityBox(core::MapSlot slot) const { return m_rows[std::size_t(slot)].quality; }
  QComboBox* viewBox() const { return m_view; }
  QCheckBox* mipmapsBox() const { return m_mipmaps; }
  QComboBox* mipFilterBox() const { return m_mipFilter; }
  QCheckBox* roughnessFoldBox() const { return m_roughnessFold; }
  QSlider* rdoSlider() const { return m_rdo; }
  // The RDO lambda the slider stands at (0: off), and the step that shows a lambda.
  double rdoLambda() const;
  static int rdoStep(double lambda);
  QPushButton* compressButton() const { return m_compress; }
  QPushButton* cancelButton() const { return m_cancel; }
  QTableWidget* resultsTable() const { return m_results; }
  CompressionRunner* runner() const { return m_runner; }
  const std::map<core::MapSlot, core::CompressionOutcome>& outcomes() const { return m_outcomes; }
  CompareDialog* compareDialog();
  CompareAllDialog* compareAllDialog();
  ChooseForMeDialog* chooseForMeDialog();
  QPushButton* chooseForMeButton() const { return m_chooseForMeButton; }

 public Q_SLOTS:
  void compress();
  void cancel();
  void openCompare();
  void openCompareAll();
  void openChooseForMe();
  void saveSelected();

 Q_SIGNALS:
  void statusMessage(const QString& message);

 private:
  struct Row {
    QLabel* label = nullptr;
    QComboBox* format = nullptr;
    QComboBox* quality = nullptr;
  };
  // The constructor's parts, in order.
  QGridLayout* formatGrid();
  void createOptionsAndActions();
  void createResults();
  void layOut(QGridLayout* formats);
  void connectSignals();

  void showFinished(const std::vector<core::CompressionOutcome>& outcomes);
  void syncFromDocument();
  void enableFloatFormats(QComboBox* box, const std::shared_ptr<const core::Image>& map,
                          core::MapSlot slot);
  void writeChoice(core::MapSlot slot);
  void writeMipChain();
  void writeRdo();
  void showRdoValue();
  void dropStalePreviews();
  void showOutcomes();
  void showPreviews();  // the results as the view document's compressed previews
  std::optional<core::MapSlot> selectedSlot() const;

  MaterialDocument* m_document;
  ViewDocument* m_viewDocument;
  CompressionRunner* m_runner;
  std::array<Row, core::kMapSlotCount> m_rows;
  QCheckBox* m_mipmaps;
  QComboBox* m_mipFilter;
  QCheckBox* m_roughnessFold;
  QSpinBox* m_zstd;
  QSlider* m_rdo;
  QLabel* m_rdoLabel;
  static constexpr int kRdoSteps = 20;      // lambda 0.5 .. 768 (CompressPanel.cpp's table)
  static constexpr int kRdoZstdLevel = 19;  // what RDO turns on when Zstandard is off
  QPushButton* m_compress;
  QPushButton* m_cancel;
  QProgressBar* m_progress;
  QLabel* m_status;
  QComboBox* m_view;
  QTableWidget* m_results;
  QPushButton* m_compareButton;
  QPushButton* m_compareAllButton;
  QPushButton* m_saveButton;
  QPushButton* m_chooseForMeButton;
  CompareDialog* m_compareDialog = nullptr;
  CompareAllDialog* m_compareAllDialog = nullptr;
  ChooseForMeDialog* m_chooseForMeDialog = nullptr;
  bool m_wipeWhenCompressed = false;  // Choose for Me's Apply: show the wipe once compressed
  std::map<core::MapSlot, core::CompressionOutcome> m_outcomes;
  bool m_syncing = false;
};

}  // namespace relief::ui::inline panels
