// ViewDocument; see ViewDocument.h.
#include "ui/document/ViewDocument.h"

#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "ui/QtText.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <QUndoStack>

#include <algorithm>

namespace relief::ui::inline document {
namespace {

// Undo command ids of the view's parts (MaterialCommands uses 1): a command merges only with
// one of the same id.
enum ViewCommandId { kLightCommand = 101, kEnvironmentCommand, kDisplayCommand };

// One part of the view set from one value to another; the commands of one interactive edit
// (a drag) merge into one step.
template <class Value>
class SetViewPartCommand : public QUndoCommand {
 public:
  using Apply = void (ViewDocument::*)(const Value&);
  SetViewPartCommand(ViewDocument* document, Apply apply, int commandId, Value oldValue,
                     Value newValue, int interactiveEdit, const QString& text)
      : m_document(document),
        m_apply(apply),
        m_commandId(commandId),
        m_old(std::move(oldValue)),
        m_new(std::move(newValue)),
        m_interactiveEdit(interactiveEdit) {
    setText(text);
  }
  void undo() override { (m_document->*m_apply)(m_old); }
  void redo() override { (m_document->*m_apply)(m_new); }
  int id() const override { return m_commandId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const SetViewPartCommand*>(other);
    if (m_interactiveEdit == 0 || next->m_interactiveEdit != m_interactiveEdit)
      return false;
    m_new = next->m_new;
    return true;
  }

 private:
  ViewDocument* m_document;
  Apply m_apply;
  int m_commandId;
  Value m_old;
  Value m_new;
  int m_interactiveEdit;  // 0: never merges
};

template <class Value>
void pushEdit(QUndoStack* stack, ViewDocument* document,
              typename SetViewPartCommand<Value>::Apply apply, int commandId, const Value& oldValue,
              const Value& newValue, int interactiveEdit, const QString& text) {
  if (oldValue == newValue)
    return;  // no empty steps in the history
  stack->push(new SetViewPartCommand<Value>(document, apply, commandId, oldValue, newValue,
                                            interactiveEdit, text));
}

}  // namespace

ViewDocument::ViewDocument(QUndoStack* undoStack, QObject* parent)
    : QObject(parent),
      m_undoStack(undoStack),
      m_mesh{std::make_shared<const core::Mesh>(core::makePrimitive(core::PrimitiveShape::Plane)),
             QStringLiteral("plane")} {}

void ViewDocument::setLight(const core::DirectionalLight& light, int interactiveEdit) {
  pushEdit(m_undoStack, this, &ViewDocument::applyLight, kLightCommand, m_light, light,
           interactiveEdit, tr("Move the light"));
}

void ViewDocument::setEnvironment(const core::Environment& environment, int interactiveEdit) {
  pushEdit(m_undoStack, this, &ViewDocument::applyEnvironment, kEnvironmentCommand, m_environment,
           environment, interactiveEdit, tr("Change the environment"));
}

void ViewDocument::setDisplay(const core::DisplayTransform& display, int interactiveEdit) {
  pushEdit(m_undoStack, this, &ViewDocument::applyDisplay, kDisplayCommand, m_display, display,
           interactiveEdit, tr("Change exposure or tone mapping"));
}

core::Result<std::pair<ViewDocument::MeshChoice, QString>> ViewDocument::loadMesh(
    const QString& nameOrPath) const {
  if (const auto shape = core::findPrimitiveShape(nameOrPath.toStdString())) {
    return std::pair{MeshChoice{std::make_shared<const core::Mesh>(core::makePrimitive(*shape)),
                                toQString(core::primitiveShapeName(*shape))},
                     QString()};
  }
  core::Result<core::ImportedMesh> imported = core::importMesh(nameOrPath.toStdString());
  if (!imported)
    return core::makeError(imported.error());
  const QString summary =
      tr("%1 triangles, tangents %2")
          .arg(imported->mesh.triangleCount())
          .arg(imported->tangentsFromFile ? tr("from the file") : tr("computed"));
  return std::pair{MeshChoice{std::make_shared<const core::Mesh>(std::move(imported->mesh)),
                              QFileInfo(nameOrPath).absoluteFilePath()},
                   summary};
}

core::Result<QString> ViewDocument::showMesh(const QString& nameOrPath) {
  auto loaded = loadMesh(nameOrPath);
  if (!loaded)
    return core::makeError(loaded.error());
  auto [choice, summary] = std::move(loaded).value();
  m_undoStack->push(
      new SetViewPartCommand<MeshChoice>(this, &ViewDocument::applyMesh, -1, m_mesh, choice, 0,
                                         tr("Show %1").arg(QFileInfo(choice.source).fileName())));
  return summary;
}

void ViewDocument::setCamera(const core::OrbitCamera& camera) {
  m_camera = camera;
  m_framingPending = false;
  Q_EMIT cameraChanged();
}

void ViewDocument::frameMesh(float aspect) {
  m_camera.frame(m_mesh.mesh->bounds(), aspect);
  m_framingPending = false;
  Q_EMIT cameraChanged();
}

void ViewDocument::requestFraming() {
  m_framingPending = true;
  Q_EMIT cameraChanged();
}

void ViewDocument::setDebugView(core::DebugView view) {
  if (view == m_debugView)
    return;
  m_debugView = view;
  Q_EMIT debugViewChanged();
}

void ViewDocument::setTilePreview(int repeats, bool seams, bool hex) {
  repeats = std::max(repeats, 1);
  if (repeats == m_tileRepeats && seams == m_tileSeams && hex == m_hexTiling)
    return;
  m_tileRepeats = repeats;
  m_tileSeams = seams;
  m_hexTiling = hex;
  Q_EMIT tilePreviewChanged();
}

void ViewDocument::setViewDistance(int distance) {
  distance = std::clamp(distance, 1, kMaxViewDistance);
  if (distance == m_viewDistance)
    return;
  m_viewDistance = distance;
  Q_EMIT tilePreviewChanged();
}

void ViewDocument::setEnginePreview(std::optional<core::Engine> engine) {
  if (engine == m_enginePreview)
    return;
  m_enginePreview = engine;
  Q_EMIT enginePreviewChanged();
}

void ViewDocument::setLightBelowHorizonAllowed(bool allowed) {
  if (allowed == m_lightBelowHorizon)
    return;
  m_lightBelowHorizon = allowed;
  Q_EMIT lightBelowHorizonAllowedChanged(allowed);
}

void ViewDocument::setCompressedPreviews(std::vector<CompressedPreview> previews) {
  m_previews = std::move(previews);
  Q_EMIT compressedPreviewChanged();
}

void ViewDocument::setCompressedView(CompressedView view) {
  m_compressedView = view;
  Q_EMIT compressedPreviewChanged();
}

bool ViewDocument::showsCompressed() const {
  return m_compressedView != CompressedView::Original && !m_previews.empty();
}

core::Material ViewDocument::withCompressedPreviews(core::Material material) const {
  for (const CompressedPreview& preview : m_previews) {
    if (material.map(preview.slot).image == preview.source)
      material.setCompressedMap(preview.slot, preview.texture, preview.decoded);
  }
  return material;
}

core::ViewState ViewDocument::viewState() const {
  return {m_camera, m_light, m_mesh.source.toStdString(), m_display, m_environment};
}

core::Status ViewDocument::showViewState(const core::ViewState& state) {
  core::Status meshShown;
  const QString mesh = QString::fromStdString(state.mesh);
  if (!mesh.isEmpty() && mesh != m_mesh.source) {
    if (auto loaded = loadMesh(mesh))
      applyMesh(loaded->first);
    else
      meshShown = core::makeError(loaded.error());
  }
  if (state.camera)
    setCamera(*state.camera);
  else
    requestFraming();
  if (state.light)
    applyLight(*state.light);
  if (state.display)
    applyDisplay(*state.display);
  if (state.environment)
    applyEnvironment(*state.environment);
  return meshShown;
}

void ViewDocument::applyLight(const core::DirectionalLight& light) {
  m_light = light;
  Q_EMIT lightChanged();
}

void ViewDocument::applyEnvironment(const core::Environment& environment) {
  m_environment = environment;
  Q_EMIT environmentChanged();
}

void ViewDocument::applyDisplay(const core::DisplayTransform& display) {
  m_display = display;
  Q_EMIT displayChanged();
}

void ViewDocument::applyMesh(const MeshChoice& mesh) {
  m_mesh = mesh;
  m_framingPending = true;
  Q_EMIT meshChanged();
  Q_EMIT cameraChanged();
}

}  // namespace relief::ui::inline document
