// A dark, neutral theme for artists: Fusion with a grey palette, so the UI does not tint the
// judgement of colour and the viewport stays the brightest thing on screen.
#pragma once

class QApplication;

namespace relief::ui::inline window {

void applyDarkTheme(QApplication& application);

}  // namespace relief::ui::inline window
