// SPDX-License-Identifier: MIT
#include "DisplayActions.hpp"

#include "../core/Scene.hpp"

#include <QAction>
#include <QActionGroup>
#include <QColorDialog>
#include <QInputDialog>
#include <QMenu>
#include <QSignalBlocker>

#include <cmath>

namespace volpost::app {

DisplayActions::DisplayActions(QWidget& window, Scene& scene, QMenu& view, ChangeScene changeScene)
    : QObject(&window), window_(window), scene_(scene), changeScene_(std::move(changeScene)) {
  QMenu* menu = view.addMenu("&Representation");
  menu->setObjectName("representationMenu");
  auto* group = new QActionGroup(this);
  const std::pair<SurfaceRepresentation, const char*> entries[] = {
      {SurfaceRepresentation::Surface, "&Surface"},
      {SurfaceRepresentation::Wireframe, "&Wireframe (element edges)"},
      {SurfaceRepresentation::Points, "&Points (nodes)"},
      {SurfaceRepresentation::FeatureEdges, "&Feature Edges (creases and borders)"},
      {SurfaceRepresentation::Outline, "&Outline (bounding box)"}};
  for (const auto& [r, label] : entries) {
    QAction* a = menu->addAction(label);
    a->setObjectName(QString("representation:%1").arg(QString::fromStdString(toString(r))));
    a->setCheckable(true);
    group->addAction(a);
    representations_[r] = a;
    const SurfaceRepresentation chosen = r;
    connect(a, &QAction::triggered, this, [this, chosen] {
      changeScene_([chosen](Scene& s) { s.setRepresentation(chosen); });
      syncToScene();
    });
  }
  menu->addSeparator();
  menu->addAction("Point &Size...", this, &DisplayActions::choosePointSize)->setObjectName("pointSizeAction");
  shown_ = menu->addAction("Show the &Model");
  shown_->setObjectName("modelShownAction");
  shown_->setCheckable(true);
  shown_->setToolTip("Off: only what is inside shows (sections, slices, iso-surfaces, streamlines)");
  connect(shown_, &QAction::toggled, this,
          [this](bool on) { changeScene_([on](Scene& s) { s.setSurfaceShown(on); }); });
  view.addAction("Bac&kground Color...", this, &DisplayActions::chooseBackground)->setObjectName("backgroundAction");
  syncToScene();
}

void DisplayActions::chooseBackground() {
  const glm::dvec3 now = scene_.shown().background;
  const QColor chosen =
      QColorDialog::getColor(QColor::fromRgbF(float(now.r), float(now.g), float(now.b)), &window_, "Background color");
  if (!chosen.isValid()) return;  // cancelled
  changeScene_([&](Scene& s) { s.setBackground({chosen.redF(), chosen.greenF(), chosen.blueF()}); });
}

void DisplayActions::syncToScene() {
  const auto& state = scene_.shown();
  for (auto& [r, action] : representations_) {
    const QSignalBlocker block(action);
    action->setChecked(r == state.representation);
  }
  const QSignalBlocker block(shown_);
  shown_->setChecked(state.surfaceShown);
}

void DisplayActions::choosePointSize() {
  bool ok = false;
  const double pixels =
      QInputDialog::getDouble(&window_, "Point size", "Size of the nodes' points, pixels:", scene_.shown().pointSize,
                              1.0, kMaxPointSize, 1, &ok);
  if (!ok) return;
  changeScene_([pixels](Scene& s) {
    s.setPointSize(pixels);
    s.setRepresentation(SurfaceRepresentation::Points);  // a size is asked for to see the points
  });
  syncToScene();
}

}  // namespace volpost::app
