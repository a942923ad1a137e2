// SPDX-License-Identifier: MIT
// Probing in the window: View > Probe (I) turns clicks on the model into probed points
// (listed in the Probe panel, marked in the view), hovering shows the element, the nearest
// node and the shown value in a tooltip; View > Mark Min and Max (M) marks where the shown
// quantity is smallest and largest.
#pragma once

#include "../core/History.hpp"
#include "../core/ModelSession.hpp"

#include <QObject>

#include <glm/vec3.hpp>

#include <functional>
#include <memory>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;

namespace volpost::app {

class HistoryPanel;
class ProbePanel;
class Viewport;

class ProbeController : public QObject {
  Q_OBJECT

 public:
  using SessionGetter = std::function<std::shared_ptr<const ModelSession>()>;
  ProbeController(QMainWindow& window, Viewport& viewport, QMenu& viewMenu, SessionGetter session);

  /// The model, step, result or the scene's points changed: the panel shows them again.
  void refresh();
  /// The checkable actions follow the scene (after a state file is opened).
  void syncToScene();
  QDockWidget* dock() const { return dock_; }
  ProbePanel* panel() const { return panel_; }
  HistoryPanel* historyPanel() const { return history_; }
  /// The shown result's largest and smallest values over a set against the steps, in the
  /// History panel (the Sets panel's Plot Over Steps).
  void plotSetHistory(const std::string& set);

 private:
  void addPoint(const glm::dvec3& point);
  void setPoints(const std::vector<glm::dvec3>& points);
  void showHover(QPoint globalPosition, bool hit, const glm::dvec3& point);
  void plotHistory(const std::vector<std::size_t>& rows);
  void showHistory(const std::vector<HistoryPlace>& places);

  QMainWindow& window_;
  Viewport& viewport_;
  SessionGetter session_;
  QDockWidget* dock_ = nullptr;
  ProbePanel* panel_ = nullptr;
  QDockWidget* historyDock_ = nullptr;
  HistoryPanel* history_ = nullptr;
  QAction* probeAction_ = nullptr;
  QAction* extremesAction_ = nullptr;
};

}  // namespace volpost::app
