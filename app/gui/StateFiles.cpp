// SPDX-License-Identifier: MIT
#include "StateFiles.hpp"

#include "../core/Scene.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace volpost::app {

StateFiles::StateFiles(QMainWindow& window, Scene& scene, QMenu& file, OpenModel openModel,
                       std::function<void()> followScene)
    : QObject(&window),
      window_(window),
      scene_(scene),
      openModel_(std::move(openModel)),
      followScene_(std::move(followScene)) {
  file.addAction("Open S&tate...", this, &StateFiles::chooseToOpen)->setObjectName("openStateAction");
  file.addAction("Save St&ate...", this, &StateFiles::chooseToSave)->setObjectName("saveStateAction");
}

bool StateFiles::save(const QString& path) {
  try {
    scene_.state().save(path.toStdString());
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage(QString("Could not save the state: %1").arg(e.what()));
    return false;
  }
  window_.statusBar()->showMessage("Saved the view to " + path + " (volpost render --state reproduces it)");
  return true;
}

void StateFiles::chooseToSave() {
  const ModelSession* session = scene_.baseSession();
  if (!session) {
    window_.statusBar()->showMessage("Open a model first: a state describes a view of one");
    return;
  }
  QSettings settings("volpost", "volpost");
  const QString suggested =
      QFileInfo(QString::fromStdString(session->model().sourcePath)).absolutePath() + "/view.json";
  const QString path = QFileDialog::getSaveFileName(
      &window_, "Save state", settings.value("files/lastState", suggested).toString(), "volpost state (*.json)");
  if (path.isEmpty()) return;
  settings.setValue("files/lastState", path);
  if (!save(path)) QMessageBox::critical(&window_, "Save state", window_.statusBar()->currentMessage());
}

void StateFiles::chooseToOpen() {
  QSettings settings("volpost", "volpost");
  const QString path = QFileDialog::getOpenFileName(
      &window_, "Open state", settings.value("files/lastState").toString(), "volpost state (*.json);;All files (*)");
  if (path.isEmpty()) return;
  settings.setValue("files/lastState", path);
  open(path);
}

// The same file (by its canonical path) read with the same options.
bool StateFiles::showsModelOf(const SceneState& state) const {
  const ModelSession* session = scene_.baseSession();
  if (!session) return false;
  const auto canonical = [](const std::string& p) { return QFileInfo(QString::fromStdString(p)).canonicalFilePath(); };
  return canonical(session->model().sourcePath) == canonical(state.modelPath) &&
         session->readerOptions() == state.readerOptions;
}

void StateFiles::open(const QString& path) {
  SceneState state;
  try {
    state = SceneState::load(path.toStdString());
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage("Could not open the state " + path);
    emit applied(false, e.what());
    QMessageBox::critical(&window_, "Cannot open state", e.what());
    return;
  }
  if (showsModelOf(state)) {
    apply(state);
    return;
  }
  const bool started = openModel_(QString::fromStdString(state.modelPath), state.readerOptions,
                                  [this, state](bool ok, const QString& e) {
                                    if (ok) apply(state);
                                    else emit applied(false, e);
                                  });
  if (!started) emit applied(false, "still loading the previous file");
}

void StateFiles::apply(const SceneState& given) {
  // A volume drawn apart (the exact reference of `volpost render`) is drawn here by the
  // window's renderer, and the status bar says so.
  SceneState state = given;
  QString drawnHere;
  if (state.volume.shown && scene_.volumeRenderers().drawsApart(state.volume.renderer)) {
    state.volume.renderer = scene_.volume().renderer;
    drawnHere = QString("; its volume (drawn by the %1 renderer with volpost render) is drawn here by %2")
                    .arg(QString::fromStdString(given.volume.renderer), QString::fromStdString(state.volume.renderer));
  }
  try {
    scene_.applyState(state);  // checks everything first: the scene keeps what it had
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage(QString("The state does not fit this model: %1").arg(e.what()));
    emit applied(false, e.what());
    QMessageBox::warning(&window_, "Cannot apply state", e.what());
    return;
  }
  followScene_();
  window_.statusBar()->showMessage("View restored from the state file" + drawnHere);
  emit applied(true, {});
}

}  // namespace volpost::app
