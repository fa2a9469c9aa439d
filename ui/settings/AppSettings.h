// AppSettings: what Relief remembers between runs (QSettings, under the organisation and
// application names main() sets): recent files, last folders per purpose, the preferences,
// and the viewport's light, display, environment and mesh for new documents. Window geometry and
// dock layout are stored by MainWindow itself with saveGeometry()/saveState().
#pragma once

#include "core/view/DirectionalLight.h"
#include "core/view/DisplayTransform.h"
#include "core/view/Environment.h"

#include <QString>
#include <QStringList>

namespace relief::ui::settings {

constexpr int kMaxRecentFiles = 10;

QStringList recentFiles();  // most recent first; files that no longer exist are dropped
void addRecentFile(const QString& path);
void removeRecentFile(const QString& path);

// The folder a file dialog for `purpose` ("preset", "map", "mesh", "export", "image") opens in:
// the last one used for it, else (when `orAny`) the last one used for anything, else the
// Documents folder.
QString lastFolder(const QString& purpose, bool orAny = true);
void setLastFolder(const QString& purpose, const QString& folder);

// A dialog's last choice for one of its controls ("export/kind", ...): the text it was saved as,
// or empty.
QString dialogChoice(const QString& key);
void setDialogChoice(const QString& key, const QString& value);

// Preferences (the Preferences dialog).
int autosaveMinutes();  // 0: off. Default 2.
void setAutosaveMinutes(int minutes);
// Compressed previews go to the GPU as blocks when the driver has the format (default), or are
// always decoded by Relief (to compare the driver's decoding with Relief's).
bool nativeCompressedUploads();
void setNativeCompressedUploads(bool native);
bool openSampleOnStart();  // with no files on the command line. Default true.
void setOpenSampleOnStart(bool open);
QString defaultMesh();  // a primitive's name for new documents. Default "plane".
void setDefaultMesh(const QString& mesh);

// The viewport's light as last left, for the next run.
core::DirectionalLight viewportLight();
void setViewportLight(const core::DirectionalLight& light);
// The display (exposure, tone mapping) and the environment as last left. A remembered
// environment file that no longer exists gives the default environment (the studio).
core::DisplayTransform viewportDisplay();
void setViewportDisplay(const core::DisplayTransform& display);
core::Environment viewportEnvironment();
void setViewportEnvironment(const core::Environment& environment);

}  // namespace relief::ui::settings
