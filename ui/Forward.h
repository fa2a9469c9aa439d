// Forward declarations of the ui classes, each in its folder's namespace, for headers that only
// point at them. A class declared in plain relief::ui would be another class than the one in its
// folder's inline namespace, so headers include this instead of declaring their own.
#pragma once

namespace relief::ui::inline compare {
class ChooseForMeDialog;
class CompareAllDialog;
class CompareDialog;
class CompareView;
class ImagePairView;
}  // namespace relief::ui::compare

namespace relief::ui::inline dialogs {
class ExportDialog;
class PreferencesDialog;
class ShortcutsDialog;
}  // namespace relief::ui::dialogs

namespace relief::ui::inline document {
class DocumentFiles;
class MaterialDocument;
class PresetLibrary;
struct RecoverableWork;
class RecoveryStore;
class SetAllParametersCommand;
class SetCompressionCommand;
class SetMapCommand;
class SetParameterCommand;
class SetTechniqueCommand;
class ViewDocument;
}  // namespace relief::ui::document

namespace relief::ui::inline panels {
class CompressPanel;
class GeneratePanel;
class EnvironmentPanel;
class LightPanel;
class MapsPanel;
struct OptionEdit;
class ParameterPanel;
class ParameterSlider;
}  // namespace relief::ui::panels

namespace relief::ui::inline tasks {
class BackgroundTask;
class CliProcess;
class CompressionRunner;
class GeneratorRunner;
}  // namespace relief::ui::tasks

namespace relief::ui::inline viewport {
class ConeMapBuilder;
class ErrorViewTrace;
class InteractionMonitor;
class ViewportWidget;
}  // namespace relief::ui::viewport

namespace relief::ui::inline window {
class CostTableWindow;
class EngineGridWindow;
class MainWindow;
class MapFileLoader;
class ViewToolBar;
class ViewportImageExport;
class ViewportStatus;
}  // namespace relief::ui::window
