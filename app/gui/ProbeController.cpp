// SPDX-License-Identifier: MIT
#include "ProbeController.hpp"

#include "../core/History.hpp"
#include "../core/Probe.hpp"
#include "../core/ProbeTable.hpp"
#include "HistoryPanel.hpp"
#include "ProbePanel.hpp"

#include <volpost/core/CellShape.hpp>
#include "Viewport.hpp"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>
#include <QToolTip>

namespace volpost::app {

ProbeController::ProbeController(QMainWindow& window, Viewport& viewport, QMenu& viewMenu, SessionGetter session)
    : QObject(&window), window_(window), viewport_(viewport), session_(std::move(session)) {
  dock_ = new QDockWidget("Probe", &window);
  dock_->setObjectName("probeDock");
  panel_ = new ProbePanel(dock_);
  panel_->setObjectName("probePanel");
  dock_->setWidget(panel_);
  window.addDockWidget(Qt::RightDockWidgetArea, dock_);
  dock_->hide();  // until the first probe

  viewMenu.addSeparator();
  probeAction_ = viewMenu.addAction("&Probe");
  probeAction_->setObjectName("probeAction");
  probeAction_->setCheckable(true);
  probeAction_->setShortcut(QKeySequence(Qt::Key_I));
  probeAction_->setStatusTip("Click the model to probe it; rest the mouse on it to see the element and value");
  connect(probeAction_, &QAction::toggled, this, [this](bool on) {
    viewport_.setProbeMode(on);
    if (on) {
      dock_->show();
      dock_->raise();
      window_.statusBar()->showMessage("Probe: click the model to add a point; rest the mouse to see the value there");
    }
  });
  extremesAction_ = viewMenu.addAction("Mark Min and &Max");
  extremesAction_->setObjectName("extremesAction");
  extremesAction_->setCheckable(true);
  extremesAction_->setShortcut(QKeySequence(Qt::Key_M));
  connect(extremesAction_, &QAction::toggled, this, [this](bool on) {
    viewport_.scene().setMarkExtremes(on);
    viewport_.update();
  });

  connect(&viewport_, &Viewport::picked, this, &ProbeController::addPoint);
  connect(&viewport_, &Viewport::hovered, this, &ProbeController::showHover);
  connect(panel_, &ProbePanel::pointsChanged, this, &ProbeController::setPoints);
  connect(panel_, &ProbePanel::message, this, [this](const QString& text) { window_.statusBar()->showMessage(text); });
  connect(panel_, &ProbePanel::historyRequested, this, &ProbeController::plotHistory);
  connect(panel_, &ProbePanel::measured, this, [this](const std::vector<std::size_t>& rows) {
    if (rows == viewport_.scene().measure()) return;
    try {
      viewport_.scene().setMeasure(rows);  // drawn in the picture too
    } catch (const std::exception& e) {
      window_.statusBar()->showMessage(e.what());
      return;
    }
    viewport_.update();
  });
}

// The shown quantity against the steps at probed points. A probe on a node follows that
// node; one inside an element follows the same material point (its natural coordinates in
// the undeformed element): the deformed shape moves with the step, the point with it.
void ProbeController::plotHistory(const std::vector<std::size_t>& rows) {
  const Scene& scene = viewport_.scene();
  const ModelSession* base = scene.baseSession();
  if (!base || !scene.view()) {
    window_.statusBar()->showMessage("Plot Over Steps: probe points on a model with a result shown first");
    return;
  }
  std::vector<HistoryPlace> places;
  const auto& results = panel_->results();
  for (std::size_t row : rows) {
    if (row >= results.size() || !results[row].inside()) continue;
    const ProbeResult& r = results[row];
    if (r.nodeId) {
      places.push_back({HistoryPlace::Kind::Node, *r.nodeId, {}, {}});
    } else if (r.method == ProbeMethod::Isoparametric && base->model().meshBuilt()) {
      const Mesh& mesh = base->model().mesh();
      std::vector<glm::dvec3> corners;
      for (NodeIndex n : mesh.cellNodes(r.cell)) corners.push_back(mesh.nodes[n]);
      places.push_back({HistoryPlace::Kind::Point, 0, positionAt(r.cellType, corners, r.natural), {}});
    } else {
      places.push_back({HistoryPlace::Kind::Point, 0, r.point, {}});
    }
  }
  if (places.empty()) {
    window_.statusBar()->showMessage("Plot Over Steps: no probed point lies on the model");
    return;
  }
  if (places.size() > kMaxHistoryCurves) places.resize(kMaxHistoryCurves);
  showHistory(places);
}

void ProbeController::plotSetHistory(const std::string& set) {
  const Scene& scene = viewport_.scene();
  if (!scene.baseSession() || !scene.view()) {
    window_.statusBar()->showMessage("Plot Over Steps: show a result first");
    return;
  }
  showHistory({{HistoryPlace::Kind::SetMax, 0, {}, set}, {HistoryPlace::Kind::SetMin, 0, {}, set}});
}

void ProbeController::showHistory(const std::vector<HistoryPlace>& places) {
  const Scene& scene = viewport_.scene();
  try {
    History h = sampleHistory(*scene.baseSession(), places, {scene.view()->quantity.key()});
    if (!historyDock_) {
      historyDock_ = new QDockWidget("History", &window_);
      historyDock_->setObjectName("historyDock");
      history_ = new HistoryPanel(historyDock_);
      history_->setObjectName("historyPanel");
      historyDock_->setWidget(history_);
      window_.addDockWidget(Qt::BottomDockWidgetArea, historyDock_);
      connect(history_, &HistoryPanel::message, this,
              [this](const QString& text) { window_.statusBar()->showMessage(text); });
    }
    history_->show(std::move(h));
    historyDock_->show();
    historyDock_->raise();
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage(QString("Plot Over Steps: %1").arg(e.what()));
  }
}

void ProbeController::refresh() {
  const Scene& scene = viewport_.scene();
  panel_->setDeformed(scene.deformation().shown);
  panel_->setUnits(scene.unitsByField());
  panel_->showProbes(session_(), scene.probes(), scene.state().step, scene.view() ? scene.view()->quantity.key() : "");
  if (!scene.probes().empty() && !dock_->isVisible()) dock_->show();
}

void ProbeController::syncToScene() {
  const QSignalBlocker block(extremesAction_);
  extremesAction_->setChecked(viewport_.scene().marksExtremes());
  refresh();
}

void ProbeController::setPoints(const std::vector<glm::dvec3>& points) {
  try {
    viewport_.scene().setProbes(points);
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage(e.what());
    return;
  }
  refresh();
  viewport_.update();
}

void ProbeController::addPoint(const glm::dvec3& point) {
  std::vector<glm::dvec3> points = viewport_.scene().probes();
  points.push_back(point);
  setPoints(points);
  const auto& results = panel_->results();
  if (!results.empty() && results.back().inside())
    window_.statusBar()->showMessage(QString("Probed point %1 in element %2").arg(results.size()).arg(results.back().cellId));
}

// The tooltip of a resting mouse: the element, the nearest node and the shown value.
void ProbeController::showHover(QPoint globalPosition, bool hit, const glm::dvec3& point) {
  const auto session = session_();
  Scene& scene = viewport_.scene();
  const auto unhighlight = [&] {
    if (!scene.highlight()) return;
    scene.setHighlight(std::nullopt);
    viewport_.update();
  };
  if (!hit || !session) {
    QToolTip::hideText();
    unhighlight();
    return;
  }
  try {
    const ProbeResult r = probeAt(*session, point, scene.state().step);
    if (!r.inside()) {
      unhighlight();
      return;
    }
    // What the tooltip names is outlined in the picture.
    scene.setHighlight(Scene::Highlight{r.cell, r.nearestNode});
    viewport_.update();
    QString text = QString("element %1 (%2), nearest node %3")
                       .arg(r.cellId)
                       .arg(QString::fromStdString(std::string(cellTypeName(r.cellType))))
                       .arg(r.nearestNodeId);
    if (scene.view()) {
      const auto& view = *scene.view();
      const auto v = r.value(view.quantity.key());
      text += QString("\n%1 = %2")
                  .arg(QString::fromStdString(view.quantity.displayName()),
                       v ? QString::fromStdString(displayNumber(*v)) : QString("no value"));
      if (view.location == FieldLocation::Node && r.nearestNode < view.values.size())
        text += QString("\nat node %1: %2")
                    .arg(r.nearestNodeId)
                    .arg(QString::fromStdString(displayNumber(view.values[r.nearestNode])));
    }
    QToolTip::showText(globalPosition, text, &viewport_);
  } catch (const std::exception&) {
    QToolTip::hideText();
    unhighlight();
  }
}

}  // namespace volpost::app
