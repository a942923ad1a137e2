// SPDX-License-Identifier: MIT
#include "StreamlineActions.hpp"

#include "SeeThroughSurface.hpp"
#include "StreamlineDialog.hpp"
#include "WorkWithProgress.hpp"

#include "../core/Scene.hpp"
#include "../core/StreamlineSeeds.hpp"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QStatusBar>

namespace volpost::app {
namespace {

std::string firstNodalVectorField(const Model& model) {
  for (const auto& f : model.fields)
    if (f->components() == 3 && f->location() == FieldLocation::Node) return f->name();
  return {};
}

// "12 streamlines, 3400 points, traced in 41 ms (2 seeds outside the mesh)"
QString describeTrace(const StreamlineResult& result) {
  std::size_t points = 0, spent = 0;
  for (const auto& l : result.lines) {
    points += l.points.size();
    spent += l.forwardStop == StreamlineStop::PointBudget || l.backwardStop == StreamlineStop::PointBudget;
  }
  return QString("%1 streamlines, %2 points, traced in %3 ms%4%5")
      .arg(result.lines.size())
      .arg(points)
      .arg(result.milliseconds, 0, 'f', 0)
      .arg(result.outside ? QString(" (%1 seeds outside the mesh)").arg(result.outside) : QString())
      .arg(spent ? QString("; %1 %2").arg(spent).arg(describe(StreamlineStop::PointBudget)) : QString());
}

}  // namespace

StreamlineActions::StreamlineActions(QMainWindow& window, Scene& scene, QMenu& results, ChangeScene changeScene,
                                     std::function<void()> startRake, std::function<void()> redraw)
    : QObject(&window),
      window_(window),
      scene_(scene),
      changeScene_(std::move(changeScene)),
      redraw_(std::move(redraw)) {
  QMenu* lines = results.addMenu("&Streamlines");
  lines->addAction("&Streamlines...", this, &StreamlineActions::choose);
  QAction* rake =
      lines->addAction("Place a &Rake", QKeySequence(Qt::Key_R), this, [this, startRake = std::move(startRake)] {
        if (!scene_.session()) return;
        startRake();
        window_.statusBar()->showMessage(
            "Drag across the model to place a rake of 20 seeds (each end halfway through the model "
            "under it); Esc cancels. View > Streamlines > Streamlines... edits it");
      });
  rake->setObjectName("placeRake");
  shown_ = lines->addAction("Show Streamlines");
  shown_->setObjectName("streamlinesAction");
  shown_->setCheckable(true);
  connect(shown_, &QAction::toggled, this, [this](bool on) {
    StreamlineLayer layer = scene_.streamlines();
    if (on && (layer.field.empty() || layer.seeds.empty())) {  // nothing to show yet: ask
      syncToScene();
      choose();
      return;
    }
    layer.shown = on;
    if (changeScene_([&](Scene& s) { s.setStreamlines(layer); }) && on) trace();
    syncToScene();
  });
}

void StreamlineActions::syncToScene() {
  const QSignalBlocker block(shown_);
  shown_->setChecked(scene_.streamlines().shown);
}

void StreamlineActions::choose() {
  const ModelSession* session = scene_.session();
  if (!session) {
    window_.statusBar()->showMessage("Open a model first");
    return;
  }
  bool hasVectors = false;
  for (const auto& f : session->model().fields) hasVectors = hasVectors || f->components() == 3;
  if (!hasVectors) {
    QMessageBox::information(&window_, "Streamlines", "This model has no vector field to follow.");
    return;
  }
  StreamlineDialog dialog(*session, scene_.streamlines(), &window_);
  for (;;) {
    if (dialog.exec() != QDialog::Accepted) return;
    if (show(dialog.layer())) return;
    QMessageBox::warning(&window_, "Streamlines", window_.statusBar()->currentMessage());
  }
}

void StreamlineActions::placeRake(const std::vector<glm::dvec3>& seeds) {
  if (!scene_.session()) return;
  StreamlineLayer layer = scene_.streamlines();
  if (layer.field.empty()) layer.field = firstNodalVectorField(scene_.session()->model());
  if (layer.field.empty()) {
    window_.statusBar()->showMessage("This model has no nodal vector field to follow");
    return;
  }
  layer.shown = true;
  layer.seeds.clear();
  for (const glm::dvec3& p : seeds) layer.seeds.push_back(pointSeedSpec(p));
  show(layer);
}

bool StreamlineActions::show(const StreamlineLayer& layer) {
  const bool ok = changeScene_([&](Scene& s) {
    s.setStreamlines(layer);
    seeThroughSurface(window_, s, "the streamlines inside");
  });
  syncToScene();
  if (ok) trace();
  return ok;
}

void StreamlineActions::trace() {
  if (!scene_.streamlinesNeedTracing()) {
    redraw_();
    emit traced(true, {});
    return;
  }
  if (tracing_) return;  // the running trace's end traces again if the layer changed meanwhile
  tracing_ = true;
  // The model as drawn: the scene keeps lines traced in the model it draws.
  const std::shared_ptr<const ModelSession> session = scene_.sharedSession();
  const StreamlineLayer layer = scene_.streamlines();
  const std::size_t step = scene_.step();
  const FieldInterpolation interpolation = scene_.volume().interpolation;
  runWithProgress<std::shared_ptr<const StreamlineResult>>(
      window_, "Tracing streamlines", 500,
      [session, layer, step, interpolation](const Progress& progress) {
        return traceStreamlineLayer(*session, layer, step, interpolation, progress);
      },
      [this](WorkOutcome<std::shared_ptr<const StreamlineResult>> t) {
        tracing_ = false;
        if (!t.value) {
          const QString error = t.cancelled ? QString("cancelled") : t.error;
          window_.statusBar()->showMessage("Streamlines: " + error);
          emit traced(false, error);
          return;
        }
        scene_.setStreamlineResult(*t.value);
        if (scene_.streamlinesNeedTracing()) {  // changed while tracing: trace the latest
          trace();
          return;
        }
        redraw_();
        window_.statusBar()->showMessage(describeTrace(**t.value));
        emit traced(true, {});
      });
}

}  // namespace volpost::app
