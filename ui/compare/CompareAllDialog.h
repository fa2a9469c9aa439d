// CompareAllDialog: "compare all formats" for one map. Compresses it in every format that can
// hold it (in the background, with progress and cancel), then lists size and quality in a
// sortable table and plots quality against bits per pixel (QtCharts), one labelled point per
// format; under Zstandard the formats with RDO get rows at two trades (lambda 8 and 32) and the
// chart's axis is the size on disk, so each draws its size-quality curve. Choosing a row and
// "Use Format" hands the format (and its trade) back to the Compress panel. Given the material
// (setMaterial), it then renders the material with each row's map in place of the original
// (`relief-cli compare --rendered --slot` in a child process, as Choose for Me runs) and fills
// the Rendered FLIP column: the error where the artist looks, not in the texels.
#pragma once

#include "core/compression/Compressor.h"
#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"
#include "ui/tasks/CompressionRunner.h"

#include <QDialog>
#include <QJsonObject>
#include <QSize>

#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTemporaryDir;

class QChartView;

namespace relief::ui::inline compare {

class CompareAllDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CompareAllDialog(QWidget* parent = nullptr);
  ~CompareAllDialog() override;

  // The material the map belongs to (its maps, parameters and view), for the rendered error;
  // without one (std::nullopt) the Rendered FLIP column stays empty. Set before start().
  void setMaterial(std::optional<core::Preset> preset) { m_preset = std::move(preset); }
  // The CLI run and the size of its three views (default: the CLI's 320x240).
  void setCliPath(const QString& path) { m_cliPath = path; }
  void setViewSize(const QSize& size) { m_viewSize = size; }
  bool rendering() const;  // the rendered error is being measured

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
  void startRendering();  // the rendered error of every outcome, after the compression
  void showRendered(int exitCode, const QJsonObject& report, const QString& errors);

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
  std::optional<core::Preset> m_preset;
  QString m_cliPath;
  QSize m_viewSize;
  CliProcess* m_process;
  std::unique_ptr<QTemporaryDir> m_folder;  // the hand-over preset and the compressed files
  static QString rowName(const core::CompressionSettings& settings, bool shortName = false);
};

}  // namespace relief::ui::inline compare
