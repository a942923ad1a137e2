// SPDX-License-Identifier: MIT
#include "RendererMenu.hpp"

#include "../core/Scene.hpp"

#include <volpost/render/GL.hpp>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

#include <algorithm>

namespace volpost::app {
namespace {

QString modeName(IntegrationMode mode) { return QString::fromUtf8(toString(mode).data(), int(toString(mode).size())); }

}  // namespace

RendererMenu::RendererMenu(QMainWindow& window, Scene& scene, std::vector<RendererEntry> renderers, QMenu& view,
                           ChangeScene changeScene, std::function<void()> shown)
    : QObject(&window),
      window_(window),
      scene_(scene),
      renderers_(std::move(renderers)),
      changeScene_(std::move(changeScene)),
      shown_(std::move(shown)) {
  rendererMenu_ = view.addMenu("Volume &Renderer");
  rendererMenu_->setObjectName("rendererMenu");
  auto* rendererGroup = new QActionGroup(this);
  for (const RendererEntry& r : renderers_) {
    QAction* a = rendererMenu_->addAction(r.label());
    a->setObjectName("renderer:" + r.name);
    a->setCheckable(true);
    rendererGroup->addAction(a);
    connect(a, &QAction::triggered, this, [this, name = r.name] { choose(name); });
  }
  if (!renderers_.empty()) {
    scene_.setVolumeRenderer(renderers_.front().name.toStdString());
    check(renderers_.front().name);
  }
  modeMenu_ = view.addMenu("Volume &Integration");
  auto* modeGroup = new QActionGroup(this);
  for (IntegrationMode mode : allIntegrationModes()) {
    QAction* a = modeMenu_->addAction(QString::fromUtf8(describe(mode).data(), int(describe(mode).size())));
    a->setObjectName("mode:" + modeName(mode));
    a->setCheckable(true);
    a->setChecked(mode == scene_.volume().mode);
    modeGroup->addAction(a);
    connect(a, &QAction::triggered, this,
            [this, mode] { changeScene_([mode](Scene& s) { s.setIntegrationMode(mode); }); });
  }
  fitModes();
}

QAction* RendererMenu::actionOf(const QString& name) const {
  return rendererMenu_->findChild<QAction*>("renderer:" + name);
}

void RendererMenu::choose(const QString& name) {
  chosen_ = true;
  QAction* a = actionOf(name);
  const QString words = a ? a->text() : name;
  // Its first frame builds its programs and data: the window says so while it waits.
  window_.statusBar()->showMessage("Preparing " + words + "...");
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const bool ok = changeScene_([&](Scene& s) { s.setVolumeRenderer(name.toStdString()); });
  check(QString::fromStdString(scene_.volume().renderer));
  if (ok && shown_) shown_();
  QApplication::restoreOverrideCursor();
  if (ok) window_.statusBar()->showMessage("Volume renderer: " + words);
}

// The menu shows `name` as the renderer, without triggering it. Its signals are not
// blocked: the exclusive group learns of the change through them and unchecks the others
// (blocked, it kept its old choice, and the next one picked from the menu left two
// checked). Only `triggered` acts on the scene, and setChecked does not emit it.
void RendererMenu::check(const QString& name) {
  if (QAction* a = actionOf(name)) a->setChecked(true);
  fitModes();
}

// Volume Integration offers the modes the scene's renderer has; one that integrates
// exactly has none to choose.
void RendererMenu::fitModes() {
  if (!modeMenu_) return;
  const std::string current = scene_.volume().renderer;
  const auto r = std::find_if(renderers_.begin(), renderers_.end(),
                              [&](const RendererEntry& e) { return e.name.toStdString() == current; });
  for (QAction* a : modeMenu_->actions()) {
    const auto mode = integrationModeFromString(a->objectName().mid(5).toStdString());
    if (!mode) continue;
    const bool offered = r == renderers_.end() ||
                         std::find(r->traits.modes.begin(), r->traits.modes.end(), *mode) != r->traits.modes.end();
    a->setEnabled(offered);
    a->setToolTip(offered                   ? QString()
                  : r->traits.modes.empty() ? r->label() +
                                                  " integrates the transfer function exactly: it has no "
                                                  "modes to choose"
                                            : r->label() + " does not offer this mode");
  }
}

// OpenGL drawn by the CPU (no GPU, a remote desktop): the GPU renderers then run on the same
// cores several times slower than a renderer that computes on the CPU, so volume rendering
// starts with the first such renderer unless the user or a state file chose one.
void RendererMenu::preferCpuOnSoftwareGl(const QString& glDescription) {
  if (!gl::isSoftwareRasterizer(glDescription.toStdString())) return;
  const auto onCpu =
      std::find_if(renderers_.begin(), renderers_.end(), [](const RendererEntry& r) { return r.traits.runsOnCpu; });
  if (onCpu == renderers_.end()) return;
  const QString cpuName = onCpu->name;
  QAction* cpu = actionOf(cpuName);
  if (!cpu) return;
  // The fast choice first, and the slow ones say so.
  if (!rendererMenu_->actions().isEmpty() && rendererMenu_->actions().first() != cpu) {
    rendererMenu_->removeAction(cpu);
    rendererMenu_->insertAction(rendererMenu_->actions().first(), cpu);
    for (const RendererEntry& r : renderers_) {
      QAction* a = actionOf(r.name);
      if (!a || r.traits.runsOnCpu || a->text().contains("slow here")) continue;
      const QString text = a->text();
      a->setText(text.endsWith(")") ? text.chopped(1) + "; slow here: OpenGL is drawn by the CPU)"
                                    : text + " (slow here: OpenGL is drawn by the CPU)");
    }
  }
  if (chosen_ || cpu->isChecked()) return;
  if (!changeScene_([&](Scene& s) { s.setVolumeRenderer(cpuName.toStdString()); })) return;
  check(cpuName);
  window_.statusBar()->showMessage(
      "OpenGL is drawn by the CPU here: volume rendering uses " + cpu->text() + " (View > Volume Renderer to change)",
      10000);
}

void RendererMenu::fitToModel(bool grid) {
  const auto draws = [grid](const RendererEntry& r) { return r.drawsKindOf(grid); };
  // A renderer that cannot draw this kind of model is shown, but not offered (a grid's cells
  // are a mesh too: every renderer draws a grid).
  for (const RendererEntry& r : renderers_)
    if (QAction* a = actionOf(r.name)) {
      const bool offered = grid || r.traits.drawsMeshes;
      a->setEnabled(offered);
      a->setToolTip(offered ? QString() : QString("Draws regular grids (SEG-Y, image data, NRRD), not meshes"));
    }
  const std::string current = scene_.volume().renderer;
  for (const RendererEntry& r : renderers_)
    if (r.name.toStdString() == current && (draws(r) || (chosen_ && r.traits.drawsMeshes))) return;
  // The first in the menu's order that draws this kind of model.
  for (const RendererEntry& r : renderers_) {
    if (!draws(r)) continue;
    if (!changeScene_([&](Scene& s) { s.setVolumeRenderer(r.name.toStdString()); })) return;
    check(r.name);
    if (chosen_) window_.statusBar()->showMessage("Volume renderer for this model: " + r.label(), 10000);
    return;
  }
}

void RendererMenu::syncToScene() {
  chosen_ = true;  // a state names its renderer
  check(QString::fromStdString(scene_.volume().renderer));
  for (QAction* a : modeMenu_->actions())
    if (a->objectName() == "mode:" + modeName(scene_.volume().mode)) a->setChecked(true);
}

}  // namespace volpost::app
