// SPDX-License-Identifier: MIT
#include "ClipActions.hpp"

#include "../core/Scene.hpp"
#include "../core/VolumeSpecs.hpp"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

#include <cmath>

namespace volpost::app {
namespace {

// A point as a user reads it: 4 significant digits, and a coordinate below a billionth of
// `size` (the rounding of a plane through the centre) shown as 0, not 4.737e-15.
QString roundedPoint(const glm::dvec3& p, double size) {
  const auto c = [size](double x) { return std::abs(x) < 1e-9 * size ? 0.0 : x; };
  return QString("(%1, %2, %3)").arg(c(p.x), 0, 'g', 4).arg(c(p.y), 0, 'g', 4).arg(c(p.z), 0, 'g', 4);
}

// The planes typed one per line (px,py,pz,nx,ny,nz; blank lines skipped); `bad` gets the
// first line that is not one.
std::vector<ClipPlane> planesOfLines(const QString& text, QString& bad) {
  std::vector<ClipPlane> planes;
  for (const QString& line : text.split('\n', Qt::SkipEmptyParts)) {
    if (line.trimmed().isEmpty()) continue;
    if (const auto plane = parseClipPlane(line.trimmed())) planes.push_back(*plane);
    else if (bad.isEmpty()) bad = line.trimmed();
  }
  return planes;
}

}  // namespace

ClipActions::ClipActions(QMainWindow& window, Scene& scene, QMenu& results, ChangeScene changeScene,
                         std::function<void()> redraw, std::function<std::size_t()> drawNow)
    : QObject(&window),
      window_(window),
      scene_(scene),
      changeScene_(std::move(changeScene)),
      redraw_(std::move(redraw)),
      drawNow_(std::move(drawNow)) {
  menu_ = results.addMenu("&Clip Plane");
  auto* group = new QActionGroup(this);
  // A plane typed or turned to another normal checks none of the axis entries.
  group->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
  const char* axes[] = {"Off", "Normal +X", "Normal +Y", "Normal +Z"};
  for (int i = 0; i < 4; ++i) {
    QAction* a = menu_->addAction(axes[i]);
    a->setObjectName(QString("clip:%1").arg(i - 1));
    a->setCheckable(true);
    a->setChecked(i == 0);
    group->addAction(a);
    axisActions_[std::size_t(i)] = a;
    connect(a, &QAction::triggered, this, [this, i] {
      setAxis(i - 1);
      if (i > 0)
        window_.statusBar()->showMessage(
            "Drag the handle's knob to turn the clip plane, its shaft (or Ctrl+drag) to move it");
    });
  }
  menu_->addAction("&Type Planes...", this, &ClipActions::typePlane)->setObjectName("typeClipPlane");
  QAction* handles = menu_->addAction("Show Plane and Box &Handles");
  handles->setObjectName("planeHandle");
  handles->setCheckable(true);
  handles->setChecked(true);
  scene_.setPlaneWidgetShown(true);
  scene_.setBoxWidgetShown(true);
  connect(handles, &QAction::toggled, this, [this](bool on) {
    scene_.setPlaneWidgetShown(on);
    scene_.setBoxWidgetShown(on);
    redraw_();
  });
  menu_->addAction("&Invert Plane", this, &ClipActions::invertPlane)->setObjectName("invertClipPlane");
  menu_->addSeparator();
  menu_->addAction("Clip &Box...", this, &ClipActions::typeBox)->setObjectName("clipBoxAction");
  menu_->addSeparator();
  QAction* toSlice = menu_->addAction("&Slice Here", this, &ClipActions::planeToSlice);
  toSlice->setObjectName("planeToSlice");
  toSlice->setToolTip("The clip plane becomes a slice: its section is drawn and nothing is cut away");
  menu_->addAction("S&lices...", this, &ClipActions::typeSlices)->setObjectName("typeSlices");
}

void ClipActions::invertPlane() {
  std::vector<ClipPlane> planes = scene_.volume().clipPlanes;
  if (planes.empty()) {
    window_.statusBar()->showMessage("No clip plane to invert: choose one in View > Clip Plane first");
    return;
  }
  // The plane last dragged (the first until one is): each plane can be turned around.
  const std::size_t i = activePlane_ < planes.size() ? activePlane_ : 0;
  planes[i].normal = -planes[i].normal;
  if (!changeScene_([&](Scene& s) { s.setClipPlanes(planes); })) return;
  syncToScene();
  if (planes.size() > 1)
    window_.statusBar()->showMessage(
        QString("Clip plane %1 of %2 inverted (drag another plane's handle to invert that one)")
            .arg(i + 1)
            .arg(planes.size()));
}

void ClipActions::planeToSlice() {
  std::vector<ClipPlane> planes = scene_.volume().clipPlanes;
  if (planes.empty()) {
    window_.statusBar()->showMessage("No clip plane to slice at: choose one in View > Clip Plane first");
    return;
  }
  std::vector<ClipPlane> slices = scene_.shown().slicePlanes;
  slices.push_back(planes.front());
  planes.erase(planes.begin());
  if (!changeScene_([&](Scene& s) {
        s.setSlicePlanes(slices);  // first: over the limit it throws, nothing changed
        s.setClipPlanes(planes);
      }))
    return;
  syncToScene();
  window_.statusBar()->showMessage(QString("%1 slice%2 (View > Clip Plane > Slices to type or remove them); "
                                           "View > Surface Opacity or Representation shows them inside")
                                       .arg(slices.size())
                                       .arg(slices.size() == 1 ? "" : "s"));
}

void ClipActions::typeSlices() {
  if (!scene_.session()) return;
  QStringList lines;
  for (const ClipPlane& p : scene_.shown().slicePlanes) lines << clipPlaneText(p);
  QString text = lines.join('\n');
  for (;;) {
    bool ok = false;
    text = QInputDialog::getMultiLineText(&window_, "Slices",
                                          QString("One plane per line, a point and the normal px,py,pz,nx,ny,nz "
                                                  "(at most %1; empty: none):")
                                              .arg(kMaxSlicePlanes),
                                          text, &ok);
    if (!ok) return;
    QString bad;
    const std::vector<ClipPlane> planes = planesOfLines(text, bad);
    if (bad.isEmpty() && planes.size() <= kMaxSlicePlanes) {
      changeScene_([&](Scene& s) { s.setSlicePlanes(planes); });
      return;
    }
    QMessageBox::warning(&window_, "Slices",
                         bad.isEmpty()
                             ? QString("%1 planes; at most %2").arg(planes.size()).arg(kMaxSlicePlanes)
                             : QString("'%1' is not six numbers px,py,pz,nx,ny,nz with a non-zero normal").arg(bad));
  }
}

void ClipActions::setAxis(int axis) {
  const ModelSession* session = scene_.session();
  if (axis < 0 || !session) {
    changeScene_([](Scene& s) { s.setClipPlanes({}); });
    syncToScene();
    return;
  }
  glm::dvec3 n(0.0);
  n[axis] = 1.0;
  const ClipPlane plane{session->model().bounds().center(), n};
  changeScene_([&](Scene& s) { s.setClipPlanes({plane}); });
  syncToScene();
}

void ClipActions::syncToScene() {
  const auto& planes = scene_.volume().clipPlanes;
  checkAxisOf(planes.empty() ? nullptr : &planes.front());
}

// The entry whose normal the plane has (+X, +Y, +Z), Off for none, or no entry for a
// typed or turned plane (a -Y plane left "Normal +Y" checked).
void ClipActions::checkAxisOf(const ClipPlane* plane) {
  int axis = -1;  // off
  if (plane) {
    const glm::dvec3 n = glm::normalize(plane->normal);
    axis = -2;  // none of the entries
    for (int a = 0; a < 3; ++a)
      if (n[a] > 1.0 - 1e-12) axis = a;
  }
  for (int i = -1; i < 3; ++i)
    axisActions_[std::size_t(i + 1)]->setChecked(i == axis);  // signals on, for the group (they act on `triggered`)
}

void ClipActions::planeDragged(const ClipPlane& plane) {
  const double size = scene_.session() ? scene_.session()->bounds().diagonal() : 1.0;
  const std::vector<ClipPlane>& planes = scene_.volume().clipPlanes;
  const auto at = std::find(planes.begin(), planes.end(), plane);
  if (at != planes.end()) activePlane_ = std::size_t(at - planes.begin());
  const QString which = planes.size() > 1 ? QString("Clip plane %1 of %2").arg(activePlane_ + 1).arg(planes.size())
                                          : QString("Clip plane");
  window_.statusBar()->showMessage(which + " through " + roundedPoint(plane.point, size) + ", normal " +
                                   roundedPoint(glm::normalize(plane.normal), 1.0) +
                                   " (View > Clip Plane > Type Planes to type them)");
  checkAxisOf(planes.size() == 1 ? &plane : nullptr);
}

void ClipActions::typePlane() {
  const ModelSession* session = scene_.session();
  if (!session) return;
  // Every free plane, one per line: several cut the model together, each with its handle.
  const std::vector<ClipPlane> planes = scene_.volume().clipPlanes;
  QStringList lines;
  for (const ClipPlane& p : planes) lines << clipPlaneText(p);
  if (lines.isEmpty()) lines << clipPlaneText(ClipPlane{session->bounds().center(), {1.0, 0.0, 0.0}});
  QString text = lines.join('\n');
  for (;;) {
    bool ok = false;
    text = QInputDialog::getMultiLineText(&window_, "Clip planes",
                                          "One plane per line, a point on it and the normal toward the kept side, "
                                          "px,py,pz,nx,ny,nz (empty: none):",
                                          text, &ok);
    if (!ok) return;
    QString bad;
    const std::vector<ClipPlane> next = planesOfLines(text, bad);
    if (bad.isEmpty()) {
      if (!changeScene_([&](Scene& s) { s.setClipPlanes(next); })) {  // too many: say why, and ask again
        QMessageBox::warning(&window_, "Clip planes", window_.statusBar()->currentMessage());
        continue;
      }
      activePlane_ = 0;
      syncToScene();
      return;
    }
    QMessageBox::warning(&window_, "Clip planes",
                         QString("'%1' is not six numbers px,py,pz,nx,ny,nz with a non-zero normal").arg(bad));
  }
}

void ClipActions::applyBox(const ClipBox& box) {
  const ModelSession* session = scene_.session();
  if (!session || !changeScene_([&](Scene& s) { s.setClipBox(box); })) return;
  const std::size_t held = drawNow_();  // uploads now, so the message is about this box
  QString message = "Clip box " + clipBoxText(box) + " (drag a face's knob to move it)";
  if (scene_.volumeShown())
    message += QString("; the GPU holds %1 of the %2 tets").arg(held).arg(session->tetrahedra().mesh.cellCount());
  window_.statusBar()->showMessage(message);
}

void ClipActions::typeBox() {
  const ModelSession* session = scene_.session();
  if (!session) return;
  const Bounds b = session->model().bounds();
  const auto current = scene_.volume().clipBox;
  QString text = current ? clipBoxText(*current) : clipBoxText({b.min.x, b.max.x, b.min.y, b.max.y, b.min.z, b.max.z});
  for (;;) {
    bool ok = false;
    text = QInputDialog::getText(&window_, "Clip box",
                                 "Keep inside xmin,xmax,ymin,ymax,zmin,zmax (empty: no box):", QLineEdit::Normal, text,
                                 &ok);
    if (!ok) return;
    if (text.trimmed().isEmpty()) {
      changeScene_([](Scene& s) { s.setClipBox(std::nullopt); });
      return;
    }
    if (const auto box = parseClipBox(text)) {
      applyBox(*box);
      return;
    }
    QMessageBox::warning(&window_, "Clip box",
                         QString("'%1' is not six numbers xmin,xmax,ymin,ymax,zmin,zmax with min < max").arg(text));
  }
}

}  // namespace volpost::app
