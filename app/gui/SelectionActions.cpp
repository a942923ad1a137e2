// SPDX-License-Identifier: MIT
#include "SelectionActions.hpp"

#include "Viewport.hpp"

#include <QAction>
#include <QActionGroup>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

#include <algorithm>
#include <iterator>

namespace volpost::app {
namespace {

QString count(std::size_t n) { return QLocale().toString(qulonglong(n)); }

}  // namespace

SelectionActions::SelectionActions(QMainWindow& window, Viewport& viewport, QMenu& resultsMenu, ChangeScene change,
                                   std::function<void()> changed)
    : QObject(&window), window_(window), viewport_(viewport), change_(std::move(change)), changed_(std::move(changed)) {
  QMenu* menu = resultsMenu.addMenu("&Select");
  menu->setObjectName("selectMenu");
  modes_ = new QActionGroup(this);
  modes_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
  addMode(*menu, "Select &Elements", QKeySequence(Qt::Key_S), {false, SelectionDepth::Surface},
          "Drag a box (or click) over the model: the elements seen in it, on the surface and cut faces");
  addMode(*menu, "Select Elements &Through", QKeySequence(Qt::SHIFT | Qt::Key_S), {false, SelectionDepth::Through},
          "Drag a box: every element whose centre lies in it, however deep");
  addMode(*menu, "Select &Nodes", QKeySequence(Qt::Key_N), {true, SelectionDepth::Surface},
          "Drag a box (or click) over the model: the nodes seen in it, on the surface");
  addMode(*menu, "Select Nodes T&hrough", QKeySequence(Qt::SHIFT | Qt::Key_N), {true, SelectionDepth::Through},
          "Drag a box: every node of the drawn elements in it, however deep");
  menu->addSeparator();
  clear_ = menu->addAction("&Clear Selection", this, &SelectionActions::clear);
  clear_->setObjectName("clearSelectionAction");
  connect(&viewport_, &Viewport::boxSelected, this, &SelectionActions::select);
  connect(&viewport_, &Viewport::selectModeLeft, this, [this] {
    if (QAction* a = modes_->checkedAction()) a->setChecked(false);
  });
  syncToScene();
}

QAction* SelectionActions::addMode(QMenu& menu, const QString& text, const QKeySequence& key, Mode mode,
                                   const QString& tip) {
  QAction* action = menu.addAction(text);
  action->setObjectName(QString(mode.nodes ? "selectNodes" : "selectElements") +
                        (mode.depth == SelectionDepth::Through ? "Through" : ""));
  action->setCheckable(true);
  action->setShortcut(key);
  action->setStatusTip(tip);
  modes_->addAction(action);
  connect(action, &QAction::toggled, this, [this, action, mode, text](bool on) {
    if (on) {
      mode_ = mode;
      viewport_.setSelectMode(true);
      window_.statusBar()->showMessage(QString(text).remove('&') +
                                       ": drag a box or click; Ctrl adds to the selection; Escape ends");
    } else if (!modes_->checkedAction() || modes_->checkedAction() == action) {
      viewport_.setSelectMode(false);
    }
  });
  return action;
}

void SelectionActions::select(const PictureBox& box, bool add) {
  const Scene& scene = viewport_.scene();
  const ModelSession* drawn = scene.session();
  if (!drawn || !drawn->model().meshBuilt()) {
    window_.statusBar()->showMessage("Select: a regular grid has no elements or nodes to pick");
    return;
  }
  const double w = viewport_.width(), h = viewport_.height();
  const Camera camera = scene.pictureCamera(w, h);
  const bool click = box.x0 == box.x1 && box.y0 == box.y1;
  // A click takes the one element under it, or the node nearest it within a few pixels.
  const PictureBox area = click && mode_.nodes ? PictureBox{box.x0 - 6, box.y0 - 6, box.x0 + 6, box.y0 + 6} : box;
  std::vector<std::uint32_t> found = mode_.nodes ? nodesInBox(scene, camera, w, h, area, mode_.depth)
                                                 : elementsInBox(scene, camera, w, h, area, mode_.depth);
  const Mesh& mesh = drawn->model().mesh();
  if (click && mode_.nodes && found.size() > 1) {
    const auto distance = [&](std::uint32_t n) {
      const auto p = camera.projectToPicture(drawn->model().nodePosition(n), w, h);
      return p ? std::hypot(p->x - box.x0, p->y - box.y0) : 1e300;
    };
    found = {*std::min_element(found.begin(), found.end(),
                               [&](std::uint32_t a, std::uint32_t b) { return distance(a) < distance(b); })};
  }
  Selection selection = scene.selection();  // the other kind's stays
  std::vector<std::int64_t>& ids = mode_.nodes ? selection.nodes : selection.elements;
  if (!add) ids.clear();
  for (const std::uint32_t i : found) ids.push_back(mode_.nodes ? mesh.nodeId(i) : mesh.cellId(i));
  normalizeIds(ids);
  const char* setName = mode_.nodes ? kSelectedNodes : kSelectedElements;
  const bool changed = change_([&](Scene& s) {
    s.setSelection(selection);
    // The selection is marked in the picture unless a set of the file's is.
    SetVisibility v = s.setVisibility();
    const bool fileSetMarked = !v.marked.empty() && v.marked != kSelectedElements && v.marked != kSelectedNodes;
    if (!ids.empty() && !fileSetMarked && v.marked != setName) {
      v.marked = setName;
      v.numbers = false;
      s.setSetVisibility(v);
    }
  });
  if (!changed) return;
  changed_();
  const QString what = mode_.nodes ? "nodes" : "elements";
  if (ids.empty())
    window_.statusBar()->showMessage(
        QString("Nothing selected: no %1 %2 there").arg(what, mode_.depth == SelectionDepth::Surface ? "seen" : "lie"));
  else
    window_.statusBar()->showMessage(QString("%1 %2 selected (\"%3\" in the Sets panel); Ctrl adds, Escape ends")
                                         .arg(count(ids.size()), what, QString(setName)));
}

void SelectionActions::clear() {
  if (viewport_.scene().selection().empty()) return;
  if (change_([](Scene& s) { s.setSelection({}); })) {
    changed_();
    window_.statusBar()->showMessage("Selection cleared");
  }
}

void SelectionActions::syncToScene() {
  const bool mesh = viewport_.scene().session() && viewport_.scene().session()->model().meshBuilt();
  for (QAction* a : modes_->actions()) a->setEnabled(mesh);
  if (!mesh)
    if (QAction* a = modes_->checkedAction()) a->setChecked(false);
  clear_->setEnabled(!viewport_.scene().selection().empty());
}

}  // namespace volpost::app
