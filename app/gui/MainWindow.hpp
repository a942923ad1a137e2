// SPDX-License-Identifier: MIT
// The main window: menus, the result/step/color toolbar, the viewport, the model panel
// and plugin panels. Loading runs on a worker thread behind a cancellable progress dialog.
#pragma once

#include "../core/ModelSession.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QMainWindow>

#include <atomic>
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

class Viewport;

class MainWindow : public QMainWindow, public PanelHost {
  Q_OBJECT

 public:
  explicit MainWindow(PluginManager& plugins, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Starts loading; emits loadFinished. The current model stays until the new one is in.
  void openFile(const QString& path);
  /// Selects a quantity by its written form (e.g. "S.mises"); false if there is none.
  bool selectQuantity(const QString& key);
  std::shared_ptr<const ModelSession> session() const { return session_; }
  Viewport* viewport() const { return viewport_; }

  // PanelHost
  const Model* model() const override { return session_ ? &session_->model() : nullptr; }
  std::optional<Quantity> activeQuantity() const override;
  std::size_t activeStep() const override;
  void requestRender() override;
  TransferFunction transferFunction() const override;
  void setTransferFunction(const TransferFunction& tf) override;
  std::vector<double> activeValues() const override;
  double modelSize() const override;
  double lastTransferFunctionMs() const override;

 signals:
  void loadFinished(bool ok, const QString& message);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  /// The TF for the active result: the one a panel set for it, else the default.
  TransferFunction transferFunctionFor(const ScalarView& view) const;
  void buildActions();
  void buildToolbar();
  void buildPanels();
  void chooseFile();
  void saveImage();
  void installSession(std::shared_ptr<ModelSession> session);
  void fillQuantities();
  void fillSteps();
  void refreshScalars();
  void showModelInfo();
  void notifyPanels();
  void buildVolumeMenu(QMenu* view);
  std::unique_ptr<VolumeRenderer> createVolumeRenderer(const QString& name) const;
  void setVolumeShown(bool on);
  void chooseClipBox();
  void chooseIsoSurfaces();

  PluginManager& plugins_;
  std::shared_ptr<ModelSession> session_;
  Viewport* viewport_ = nullptr;
  QComboBox* quantityBox_ = nullptr;
  QComboBox* stepBox_ = nullptr;
  QComboBox* colorMapBox_ = nullptr;
  QTextBrowser* modelInfo_ = nullptr;
  QLabel* glLabel_ = nullptr;
  QAction* edgesAction_ = nullptr;
  QAction* volumeAction_ = nullptr;
  bool loading_ = false;
  std::map<std::string, TransferFunction> userTransferFunctions_;  ///< set by panels, per quantity key
};

}  // namespace volpost::app
