// SPDX-License-Identifier: MIT
#include "SavedViews.hpp"

#include "../core/Scene.hpp"

#include <QAction>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

namespace volpost::app {

SavedViews::SavedViews(QMainWindow& window, Scene& scene, QMenu& view, ChangeScene changeScene,
                       std::function<void()> redraw)
    : QObject(&window),
      window_(window),
      scene_(scene),
      changeScene_(std::move(changeScene)),
      redraw_(std::move(redraw)) {
  QAction* previous = view.addAction("&Previous View", this, &SavedViews::previous);
  previous->setObjectName("previousViewAction");
  previous->setShortcuts({QKeySequence(Qt::Key_Backspace), QKeySequence::Back});
  previous->setToolTip("Back to the view before the last turn, zoom, standard or saved view");
  view.addAction("Sa&ve View...", this, &SavedViews::save)->setObjectName("saveViewAction");
  saved_ = view.addMenu("Saved &Views");
  saved_->setObjectName("savedViewsMenu");
  remove_ = view.addMenu("Remove a Saved View");
  remove_->setObjectName("removeViewMenu");
  syncToScene();
}

void SavedViews::save() {
  if (!scene_.session()) {
    window_.statusBar()->showMessage("Open a model first: a view is a camera on one");
    return;
  }
  QString name = QString("View %1").arg(scene_.views().size() + 1);
  for (;;) {
    bool ok = false;
    name = QInputDialog::getText(&window_, "Save view",
                                 "Name of the view (the same name replaces that view):", QLineEdit::Normal, name, &ok);
    if (!ok || saveAs(name)) return;
  }
}

bool SavedViews::saveAs(const QString& name) {
  if (!changeScene_([&](Scene& s) { s.saveView(name.toStdString()); })) return false;
  syncToScene();
  window_.statusBar()->showMessage(
      QString("Saved the view as \"%1\" (View > Saved Views; File > Save State keeps it)").arg(name));
  return true;
}

bool SavedViews::previous() {
  if (!scene_.previousView()) {
    window_.statusBar()->showMessage("No earlier view to go back to");
    return false;
  }
  redraw_();
  return true;
}

void SavedViews::syncToScene() {
  saved_->clear();
  remove_->clear();
  for (const NamedView& v : scene_.views()) {
    const QString name = QString::fromStdString(v.name);
    QAction* show = saved_->addAction(
        name, this, [this, name] { changeScene_([&](Scene& s) { s.showView(name.toStdString()); }); });
    show->setObjectName("view:" + name);
    QAction* remove = remove_->addAction(name, this, [this, name] {
      changeScene_([&](Scene& s) { s.removeView(name.toStdString()); });
      syncToScene();
    });
    remove->setObjectName("removeView:" + name);
  }
  saved_->setEnabled(!scene_.views().empty());
  remove_->setEnabled(!scene_.views().empty());
}

}  // namespace volpost::app
