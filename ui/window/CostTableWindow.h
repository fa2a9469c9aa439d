// CostTableWindow: View > Cost Table. For the current material at the viewport's view, each
// technique's frame time and UV error against the exact trace (renderer/CostTable.h), the
// cheapest within the error bound the artist sets marked; Apply puts the chosen row's technique
// and sample counts on the material as one undo step. Frames are timed offscreen on the GUI
// thread (seconds, a wait cursor: other work would disturb the timing), the exact trace runs in
// the background.
#pragma once

#include "renderer/CostTable.h"
#include "ui/Forward.h"

#include <QDialog>

#include <optional>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace relief::ui::inline window {

class CostTableWindow : public QDialog {
  Q_OBJECT

 public:
  CostTableWindow(MaterialDocument* document, ViewDocument* view, ViewportWidget* viewport,
                  QWidget* parent = nullptr);
  ~CostTableWindow() override;

  void measure();
  void waitForTable();  // blocks until the errors are measured (tests)
  const renderer::CostTable& table() const { return m_table; }
  QDoubleSpinBox* errorBound() const { return m_bound; }
  QTableWidget* tableWidget() const { return m_rows; }
  // Applies the selected row, or the cheapest within the bound when none is selected.
  void applyChoice();

 Q_SIGNALS:
  void tableReady();

 private:
  void showTable();
  std::optional<std::size_t> chosenRow() const;

  MaterialDocument* m_document;
  ViewDocument* m_view;
  ViewportWidget* m_viewport;
  BackgroundTask* m_task;
  QDoubleSpinBox* m_bound;
  QTableWidget* m_rows;
  QLabel* m_status;
  QPushButton* m_apply;
  renderer::CostTable m_table;
};

}  // namespace relief::ui::inline window
