// The real main window for GUI tests: shown at a given size, exposed (so GL has drawn), with a
// preset open, as a user starts. Each GUI test file derives its fixture from this one.
#pragma once

#include "renderer/ImageConversion.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace relief::test {

class MainWindowFixture : public ::testing::Test {
 protected:
  // Opens the window at width x height with `presetPath` (a sample's preset by default).
  void openWindow(int width, int height, const std::string& presetPath) {
    m_window = std::make_unique<ui::MainWindow>();
    m_window->resize(width, height);
    m_window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(m_window.get()));
    ASSERT_TRUE(m_window->openPreset(QString::fromStdString(presetPath)));
  }

  ui::MaterialDocument* document() const { return m_window->document(); }
  ui::ViewDocument* viewDocument() const { return m_window->viewDocument(); }
  ui::ViewportWidget* viewport() const { return m_window->viewport(); }
  // The centre of a slider's handle, where a user presses to drag it.
  static QPoint sliderHandle(QSlider* slider) {
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    return slider->style()
        ->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider)
        .center();
  }
  // The viewport's frame as 8-bit RGBA values 0..1.
  core::Image grabbed() const { return renderer::fromQImage(viewport()->grabFramebuffer()); }

  std::unique_ptr<ui::MainWindow> m_window;
};

}  // namespace relief::test
