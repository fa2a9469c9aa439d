// CompareAllDialog: "compare all formats" for one map. Compresses it in every format that can
// hold it (in the background, with progress and cancel), then lists size and quality in a
// sortable table and plots quality against bits per pixel (QtCharts), one labelled point per
// format; under Zstandard the formats with RDO get rows at two trades (lambda 8 and 32) and the
// chart's axis is the size on disk, so each draws its size-quality curve. Choosing a row and
// "Use Format" hands the format (and its trade) back to the Compress panel.
#pragma once

#include "core/compression/Compressor.h"
#include "ui/tasks/CompressionRunner.h"

#include <QDialog>

#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

class QChartView;

namespace relief::ui::inline compare {

class CompareAllDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CompareAllDialog(QWidget* parent = nullptr);

  // Starts the comparison of `map` (in `slot`) at `quality`; the size on disk is that of a
  // KTX2 file with a full mip chain or level 0 alone (`mipmaps`, as the Compress panel's choice,
  // so both count the same bytes), supercompressed at `zstdLevel` (0: none). Quality is
  // measured on level 0.
  void start(core::MapSlot slot, std::shared_ptr<const core::Image> map,
             core::CompressionQuality quality, bool mipmaps, int zstdLevel, double heightScale);

  QTableWidget* table() const { return m_table; }
  CompressionRunner* runner() const { return m_runner; }
  QChartView* chartView() const { return m_chartView; }
  const std::vector<core::CompressionOutcome>& outcomes() const { return m_outcomes; }
  std::optional<core::TextureFormat> selectedFormat() const;
  float selectedRdoLambda() const;  // the selected row's RDO trade; 0 without
  // The format Choose for Me picked for this map (ChooseForMeDialog), marked in its row; set
  // before start().
  void setMaterialChoice(std::optional<core::TextureFormat> format, float rdoLambda = 0.0f) {
    m_materialChoice = format;
    m_materialChoiceRdo = rdoLambda;
  }

 Q_SIGNALS:
  void formatChosen(relief::core::MapSlot slot, relief::core::TextureFormat format,
                    float rdoLambda);

 protected:
  void reject() override;  // Close also cancels

 private:
  void addRow(const core::CompressionOutcome& outcome);
  void updateChart();

  CompressionRunner* m_runner;
  QTableWidget* m_table;
  QChartView* m_chartView;
  QProgressBar* m_progress;
  QLabel* m_status;
  QPushButton* m_cancel;
  QPushButton* m_use;
  double onDiskBitsPerTexel(const core::CompressionOutcome& outcome) const;

  core::MapSlot m_slot = core::MapSlot::Color;
  double m_texels = 0.0;  // of the map compared
  std::vector<core::CompressionOutcome> m_outcomes;
  std::optional<core::TextureFormat> m_materialChoice;
  float m_materialChoiceRdo = 0.0f;
  int m_zstdLevel = 0;
  static QString rowName(const core::CompressionSettings& settings, bool shortName = false);
};

}  // namespace relief::ui::inline compare
