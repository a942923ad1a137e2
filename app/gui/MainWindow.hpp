// SPDX-License-Identifier: MIT
// The main window: menus, the result/step/color toolbar, the viewport, the model panel
// and plugin panels. Loading runs on a worker thread behind a cancellable progress dialog.
#pragma once

#include "../core/PluginRenderers.hpp"
#include "../core/ModelSession.hpp"
#include "../core/SceneState.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QMainWindow>

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QTextBrowser;
class QAction;
class QMenu;

namespace volpost {
class VolumeRenderer;
}

namespace volpost::app {

class ClipActions;
class DeformationActions;
class ProbeController;
class RendererMenu;
class Scene;
class LinePlotPanel;
class SelectionActions;
class SetsPanel;
class ModelLoader;
class SavedViews;
class StateFiles;
class StepController;
class StreamlineActions;
class Viewport;
class VolumeActions;
class DisplayActions;
class FrameRateActions;

class MainWindow : public QMainWindow, public PanelHost {
  Q_OBJECT

 public:
  /// Draws a grid's volume with the 2D transfer function in `path` (volpost-tf2d JSON);
  /// false, saying why, for a mesh model or a file that is not one (the scene keeps its own).
  bool loadTransferFunction2D(const QString& path);
  explicit MainWindow(PluginManager& plugins, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Starts loading, with the reader's options (SEG-Y header bytes ...); emits
  /// loadFinished. The current model stays until the new one is in.
  void openFile(const QString& path, const ReaderOptions& options = {});
  /// File > Reader Options...: the last file opened (or tried) again, with these options.
  /// False (said in the status bar) when no file was opened yet.
  bool reopenWithReaderOptions(const ReaderOptions& options);
  /// Selects a quantity by its written form (e.g. "S.mises"); false if there is none.
  bool selectQuantity(const QString& key);
  /// Saves the view (model, result, camera, colors, volume...) as a state file.
  /// Returns false (and says why in the status bar) when it cannot be written.
  bool saveStateFile(const QString& path);
  /// Opens a state file: its model (when another is shown), then its view. Emits
  /// stateApplied(ok, message) when done.
  void openStateFile(const QString& path);
  std::shared_ptr<const ModelSession> session() const { return session_; }
  Viewport* viewport() const { return viewport_; }

  // PanelHost
  const Model* model() const override { return session_ ? &session_->model() : nullptr; }
  std::optional<Quantity> activeQuantity() const override;
  std::size_t activeStep() const override;
  void requestRender() override;
  TransferFunction transferFunction() const override;
  void setTransferFunction(const TransferFunction& tf) override;
  SampleView activeValues() const override;
  double modelSize() const override;
  double lastTransferFunctionMs() const override;
  std::optional<TransferFunction2D> transferFunction2D() const override;
  bool setTransferFunction2D(const std::optional<TransferFunction2D>& tf) override;

 signals:
  void loadFinished(bool ok, const QString& message);
  /// The streamlines shown were traced (ok) or could not be (message says why).
  void streamlinesTraced(bool ok, const QString& message);
  void stateApplied(bool ok, const QString& message);

 protected:
  void closeEvent(QCloseEvent* event) override;
  /// A model file dropped on the window opens; a state file (.json) is applied.
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  std::optional<Quantity> chosenQuantity() const;
  void buildActions();
  void askBudget(const QString& title, const QString& prompt, const QString& key, void (*apply)(std::size_t));
  void buildToolbar();
  void buildPanels();
  void chooseFile();
  void saveImage();
  void installSession(std::shared_ptr<ModelSession> session);
  void fillQuantities();
  /// The quantity box lists the session's quantities (the selection is left to the caller).
  void listQuantities();
  void openCalculator();
  void fillSteps();
  void refreshScalars();
  void syncControlsToScene();
  /// Reads a model on a worker and shows it; `then` gets the outcome. False while another
  /// file is still being read.
  bool readModel(const QString& path, const ReaderOptions& options,
                 std::function<void(bool ok, const QString& error)> then);
  void followAppliedState();
  /// View > Grid Slices... (G): the slices dialog; on first use the three middle slices.
  void showGridSlices();
  /// Runs a change of the scene, then redraws; an error goes to the status bar.
  template <typename Change>
  bool changeScene(Change&& change);
  void showModelInfo();
  void notifyPanels();
  void buildVolumeMenu(QMenu* volume, QMenu* results);
  void chooseIsoSurfaces();
  /// Results > Glyphs...: until the layer is accepted or the dialog cancelled.
  void chooseGlyphs();
  /// Results > Threshold...: until a range is accepted, turned off or the dialog cancelled.
  void chooseThreshold();
  void chooseSurfaceOpacity();

  PluginManager& plugins_;
  /// The model as the scene holds it: as read, with the calculator's formulas' fields.
  std::shared_ptr<const ModelSession> session_;
  Viewport* viewport_ = nullptr;
  QComboBox* quantityBox_ = nullptr;
  QComboBox* stepBox_ = nullptr;
  QComboBox* colorMapBox_ = nullptr;
  QTextBrowser* modelInfo_ = nullptr;
  QLabel* glLabel_ = nullptr;
  QLabel* refiningLabel_ = nullptr;  ///< shown while the renderer refines a quick frame
  QAction* edgesAction_ = nullptr;
  QAction* orthoAction_ = nullptr;
  QAction* legendAction_ = nullptr;
  QAction* reverseColorsAction_ = nullptr;
  QAction* symmetricRangeAction_ = nullptr;
  QAction* logScaleAction_ = nullptr;
  QAction* stepTextAction_ = nullptr;
  QAction* colorBandsAction_ = nullptr;
  QAction* outOfRangeAction_ = nullptr;
  /// The color map the toolbar and View > Reverse Color Map ask for ("viridis-reversed").
  std::string chosenColorMap() const;
  void buildColorActions(QMenu* view);
  void chooseLegendText();
  /// The color actions show the scene's colors (after a state file or a change).
  void syncColorActions();
  QAction* triadAction_ = nullptr;
  StepController* steps_ = nullptr;
  QMenu* fileMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* resultsMenu_ = nullptr;
  QMenu* volumeMenu_ = nullptr;
  ProbeController* probes_ = nullptr;
  RendererMenu* rendererMenu_ = nullptr;
  StreamlineActions* streamlines_ = nullptr;
  ClipActions* clips_ = nullptr;
  DeformationActions* deformation_ = nullptr;
  ModelLoader* loader_ = nullptr;
  StateFiles* stateFiles_ = nullptr;
  VolumeActions* volume_ = nullptr;
  DisplayActions* display_ = nullptr;
  FrameRateActions* frameRate_ = nullptr;
  SavedViews* savedViews_ = nullptr;
  LinePlotPanel* linePlot_ = nullptr;
  std::map<std::string, TransferFunction> userTransferFunctions_;  ///< set by panels, per quantity key
  class GridSlicesPanel* gridSlices_ = nullptr;
  SelectionActions* selection_ = nullptr;  // Results > Select
  SetsPanel* sets_ = nullptr;              // View > Panels > Sets
  class QDockWidget* gridSlicesDock_ = nullptr;
  std::vector<class QDockWidget*> pluginDocks_;  ///< the plugins' panels, opened with the volume
  QString pendingStatePath_;
};

}  // namespace volpost::app
