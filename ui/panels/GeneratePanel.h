// GeneratePanel: makes a map from the material's other maps. Pick a generator and its source
// map(s), tune its options (controls built from the generator table); a reduced preview updates
// live while dragging, then the full-size result follows in the background with a progress bar
// and Cancel. Apply puts the result into the material as one undo step; Save writes it to a
// file at full precision.
#pragma once

#include "core/generators/Generators.h"
#include "ui/Forward.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QProgressBar;
class QPushButton;

namespace relief::ui::inline panels {

class GeneratePanel : public QWidget {
  Q_OBJECT

 public:
  explicit GeneratePanel(MaterialDocument* document, QWidget* parent = nullptr);

  QComboBox* generatorBox() const { return m_generator; }
  QWidget* optionEditor(const std::string& name) const;
  QPushButton* applyButton() const { return m_apply; }
  QPushButton* saveButton() const { return m_save; }
  GeneratorRunner* runner() const { return m_runner; }
  const std::optional<core::GeneratedMap>& result() const { return m_result; }

 public Q_SLOTS:
  void setGenerator(core::GeneratorKind kind);
  void apply();
  void saveResult();

 Q_SIGNALS:
  void resultAvailable();

 private:
  void rebuild();     // controls for the current generator
  void regenerate();  // a new request with the current inputs and values
  void showSource();
  void showResult(const core::GeneratedMap& map, bool preview);
  std::vector<std::shared_ptr<const core::Image>> currentInputs(QString& problem) const;
  // Whether the result can go into one of the material's slots (a packed ORM or mask map has
  // no slot: it is saved, not applied).
  bool resultFitsASlot() const;
  // Shows the options that apply to the current choice (height compensation for pack's
  // normal-height layout only).
  void updateAdjustMaterial();

  MaterialDocument* m_document;
  GeneratorRunner* m_runner;
  core::GeneratorKind m_kind = core::GeneratorKind::Normal;
  core::GeneratorValues m_values;
  QComboBox* m_generator;
  QFormLayout* m_form;
  std::vector<QComboBox*> m_inputBoxes;
  std::vector<QWidget*> m_optionEditors;
  QComboBox* m_destination;
  QCheckBox* m_adjustMaterial;
  ImagePairView* m_view;
  QLabel* m_status;
  QProgressBar* m_progress;
  QPushButton* m_cancel;
  QPushButton* m_apply;
  QPushButton* m_save;
  std::optional<core::GeneratedMap> m_result;  // the full-size result, when ready
};

}  // namespace relief::ui::inline panels
