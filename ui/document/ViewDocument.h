// ViewDocument: what the viewport shows besides the material (the mesh, the camera, the light,
// the environment, the display transform and the debug view), beside MaterialDocument. The
// viewport renders it and turns input into edits; panels and file handling read and change it
// here, never through the GL widget.
//
// A preset saves the light, the environment, the display transform and the mesh, so changing one
// is an edit of the document: an undo step on the material document's stack (one history, one
// Ctrl+Z), a drag merged into one step as a slider drag is. The camera and the debug view are
// navigation: signalled and saved, never undone (as in Blender's or Substance's viewports).
#pragma once

#include "core/base/Result.h"
#include "core/exporters/EnginePreview.h"
#include "core/image/Image.h"
#include "core/material/MapSlot.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"
#include "core/view/DebugView.h"
#include "core/view/ViewState.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QUndoStack;

namespace relief::core::inline compression {
struct CompressedTexture;
}

namespace relief::ui::inline document {

class ViewDocument : public QObject {
  Q_OBJECT

 public:
  // The mesh shown and where it comes from (a primitive's name or a mesh file's absolute path).
  struct MeshChoice {
    std::shared_ptr<const core::Mesh> mesh;
    QString source;
  };

  // The Compress panel's previews: per slot, a compressed texture of the map the material held
  // when it was made (a slot whose map changed since is shown uncompressed). The view shows the
  // original maps, the compressed ones, or a wipe with the original left of the divider. Not
  // saved and not undone: they follow the panel's results.
  struct CompressedPreview {
    core::MapSlot slot;
    std::shared_ptr<const core::Image> source;  // the material's map it was made from
    std::shared_ptr<const core::CompressedTexture> texture;
    std::shared_ptr<const core::Image> decoded;
  };
  enum class CompressedView { Original, Compressed, Wipe };

  // Edits go on `undoStack` (the material document's).
  explicit ViewDocument(QUndoStack* undoStack, QObject* parent = nullptr);

  const core::OrbitCamera& camera() const { return m_camera; }
  const core::DirectionalLight& light() const { return m_light; }
  const core::Environment& environment() const { return m_environment; }
  const core::DisplayTransform& display() const { return m_display; }
  core::DebugView debugView() const { return m_debugView; }
  const core::Mesh& mesh() const { return *m_mesh.mesh; }
  const QString& meshSource() const { return m_mesh.source; }
  // Whether the light may go below the horizon (the Light panel's choice); Ctrl+drag in the
  // viewport stops at the horizon otherwise.
  bool lightBelowHorizonAllowed() const { return m_lightBelowHorizon; }
  // The camera is to be framed on the mesh (a new mesh, a preset without a camera); the
  // viewport does it at its next frame, when it knows its aspect ratio.
  bool framingPending() const { return m_framingPending; }

  // Starts an interactive edit (a light drag, a slider drag): every edit with the returned id
  // and of the same part merges into one undo step.
  int beginInteractiveEdit() { return ++m_lastInteractiveEdit; }
  void setLight(const core::DirectionalLight& light, int interactiveEdit = 0);
  void setEnvironment(const core::Environment& environment, int interactiveEdit = 0);
  void setDisplay(const core::DisplayTransform& display, int interactiveEdit = 0);
  // Shows a primitive by name or imports a mesh file (Assimp), as one undo step; the camera is
  // framed on it. On success returns what to tell the user about an imported file ("N
  // triangles, tangents from the file"), empty for a primitive; the error names the file.
  core::Result<QString> showMesh(const QString& nameOrPath);
  void setCamera(const core::OrbitCamera& camera);
  void frameMesh(float aspect);  // the camera framed on the mesh now
  void requestFraming();         // ... at the viewport's next frame
  void setDebugView(core::DebugView view);
  // The tile preview, navigation like the debug view: the material repeated `repeats` times more
  // in each direction than its tiling says (the material is not changed), lines where the map's
  // edges meet, and hex-tiling against visible repetition (renderer/FrameSettings.h), to judge a
  // tileable map's seams and repetition.
  int tileRepeats() const { return m_tileRepeats; }
  bool tileSeams() const { return m_tileSeams; }
  bool hexTiling() const { return m_hexTiling; }
  void setTilePreview(int repeats, bool seams, bool hex);
  // The view distance, navigation too: the material looked at as from `distance` times farther
  // (renderer/FrameSettings.h, TilePreview::distance), so the mip levels an engine samples there
  // are what the viewport shows; 1 to kMaxViewDistance. Signalled as tilePreviewChanged.
  static constexpr int kMaxViewDistance = 64;
  int viewDistance() const { return m_viewDistance; }
  void setViewDistance(int distance);
  // The engine preview, navigation too: the relief traced as that engine's exported material
  // traces it (core/exporters/EnginePreview.h); none: Relief's own technique.
  std::optional<core::Engine> enginePreview() const { return m_enginePreview; }
  void setEnginePreview(std::optional<core::Engine> engine);
  void setLightBelowHorizonAllowed(bool allowed);
  const std::vector<CompressedPreview>& compressedPreviews() const { return m_previews; }
  CompressedView compressedView() const { return m_compressedView; }
  void setCompressedPreviews(std::vector<CompressedPreview> previews);
  void setCompressedView(CompressedView view);
  // Whether the view shows compressed maps (a preview exists and is chosen).
  bool showsCompressed() const;
  // `material` with every current preview substituted.
  core::Material withCompressedPreviews(core::Material material) const;

  // The mesh, camera, light, environment and display, as a preset stores them.
  core::ViewState viewState() const;
  // Shows a preset's view, not as an undo step (opening a preset starts a new history): its
  // mesh when it names one other than the one shown, its camera (or the mesh framed), light,
  // display and environment. A mesh that cannot be loaded is the error; the rest is applied.
  core::Status showViewState(const core::ViewState& state);

  // Used by the undo commands: change the view and notify, without pushing anything.
  void applyLight(const core::DirectionalLight& light);
  void applyEnvironment(const core::Environment& environment);
  void applyDisplay(const core::DisplayTransform& display);
  void applyMesh(const MeshChoice& mesh);

 Q_SIGNALS:
  void cameraChanged();
  void lightChanged();
  void environmentChanged();
  void displayChanged();
  void meshChanged();  // the mesh and its source; the camera is framed on it
  void debugViewChanged();
  void tilePreviewChanged();
  void enginePreviewChanged();
  void lightBelowHorizonAllowedChanged(bool allowed);
  void compressedPreviewChanged();  // the previews or the choice of what is shown

 private:
  // A primitive or an imported file, loaded; the error names the file.
  core::Result<std::pair<MeshChoice, QString>> loadMesh(const QString& nameOrPath) const;

  QUndoStack* m_undoStack;
  core::OrbitCamera m_camera;
  core::DirectionalLight m_light;
  core::Environment m_environment;
  core::DisplayTransform m_display;
  core::DebugView m_debugView = core::DebugView::Shading;
  int m_tileRepeats = 1;
  int m_viewDistance = 1;
  bool m_tileSeams = false;
  bool m_hexTiling = false;
  std::optional<core::Engine> m_enginePreview;
  MeshChoice m_mesh;
  std::vector<CompressedPreview> m_previews;
  CompressedView m_compressedView = CompressedView::Original;
  bool m_lightBelowHorizon = false;
  bool m_framingPending = true;
  int m_lastInteractiveEdit = 0;
};

}  // namespace relief::ui::inline document
