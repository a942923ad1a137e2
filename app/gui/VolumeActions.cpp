// SPDX-License-Identifier: MIT
#include "VolumeActions.hpp"

#include "../core/ReferenceVolumeImage.hpp"
#include "../core/RefinedElementVolume.hpp"
#include "../core/Scene.hpp"

#include "host/TextFile.hpp"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QStatusBar>

namespace volpost::app {

VolumeActions::VolumeActions(QMainWindow& window, Scene& scene, QMenu& view, bool renderersLoaded,
                             ChangeScene changeScene, Followers followers)
    : QObject(&window),
      window_(window),
      scene_(scene),
      changeScene_(std::move(changeScene)),
      followers_(std::move(followers)) {
  volume_ = view.addAction("&Volume Rendering");
  volume_->setObjectName("volumeAction");
  volume_->setCheckable(true);
  volume_->setShortcut(QKeySequence(Qt::Key_V));
  volume_->setEnabled(renderersLoaded);
  if (!renderersLoaded) volume_->setToolTip("No volume renderer plugin is loaded");
  connect(volume_, &QAction::toggled, this, &VolumeActions::show);

  shading_ = view.addAction("&Shade the Volume by Its Gradient (grids)");
  shading_->setObjectName("shadingAction");
  shading_->setCheckable(true);
  shading_->setShortcut(QKeySequence(Qt::Key_L));
  shading_->setToolTip("Light a regular grid's volume (a seismic cube) with the light at the eye");
  connect(shading_, &QAction::toggled, this, [this](bool on) {
    changeScene_([on](Scene& s) { s.setShading(on); });  // a mesh: the message says why
    syncToScene();
  });

  interpolation_ = view.addAction("Cells' Own &Interpolation (trilinear, quadratic)");
  interpolation_->setObjectName("elementInterpolationAction");
  interpolation_->setCheckable(true);
  interpolation_->setToolTip(
      "Draw the field as the solver defines it in each cell (trilinear in a hexahedron, quadratic in a "
      "10-node tetrahedron) in the volume, the boundary surface, sections, slices, iso-surfaces and streamlines, "
      "and draw the surface and sections in the cells' own curved shapes; off: linear on the tetrahedra the cells "
      "are split into, the faces flat through their nodes");
  connect(interpolation_, &QAction::toggled, this, &VolumeActions::drawCellsOwnField);
  tolerance_ = view.addAction(QString());  // the text shows the value (syncToScene)
  tolerance_->setObjectName("elementToleranceAction");
  tolerance_->setToolTip(
      "How far each pixel's color or opacity may stray from the exact picture of the cells' own field: a "
      "bound the pictures stay well under; 0 draws it exactly (slower). The reference renderer always "
      "draws it exactly. The boundary, sections and iso-surfaces follow the cells' shapes and field to a "
      "tenth of it");
  connect(tolerance_, &QAction::triggered, this, &VolumeActions::askElementTolerance);

  edges_ = view.addAction("Element &Edges over the Volume");
  edges_->setObjectName("volumeEdgesAction");
  edges_->setCheckable(true);
  edges_->setToolTip("The boundary's element edges drawn over the volume; they hide what lies behind them");
  connect(edges_, &QAction::toggled, this, [this](bool on) { changeScene_([on](Scene& s) { s.setVolumeEdges(on); }); });
  outline_ = view.addAction("Model &Outline over the Volume");
  outline_->setObjectName("volumeOutlineAction");
  outline_->setCheckable(true);
  outline_->setToolTip("The model's creases and borders (its feature edges) drawn over the volume");
  connect(outline_, &QAction::toggled, this,
          [this](bool on) { changeScene_([on](Scene& s) { s.setVolumeOutline(on); }); });

  QAction* load2d = view.addAction("Load a 2D Transfer Function (grids)...");
  load2d->setObjectName("load2dAction");
  load2d->setToolTip(
      "Color and opacity over the value and its gradient magnitude (volpost-tf2d JSON): boundaries "
      "apart from the insides of the same value");
  connect(load2d, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(&window_, "Load a 2D transfer function", QString(),
                                                      "2D transfer functions (*.json);;All files (*)");
    if (!path.isEmpty()) loadTransferFunction2D(path);
  });
  QAction* clear2d = view.addAction("Use the 1D Transfer Function");
  clear2d->setObjectName("clear2dAction");
  connect(clear2d, &QAction::triggered, this, [this] {
    if (setTransferFunction2D(std::nullopt))
      window_.statusBar()->showMessage("Volume colors from the 1D transfer function");
  });
  syncToScene();
}

void VolumeActions::syncToScene() {
  const QSignalBlocker a(volume_), b(shading_), c(edges_), d(outline_), e(interpolation_);
  volume_->setChecked(scene_.volumeShown());
  interpolation_->setChecked(scene_.volume().interpolation == FieldInterpolation::Element);
  const double tolerance = scene_.volume().elementTolerance;
  tolerance_->setText(tolerance == 0.0 ? QString("Tolerance of the Cells' Own Field: exact...")
                                       : QString("Tolerance of the Cells' Own Field: %1...").arg(tolerance, 0, 'g', 3));
  shading_->setChecked(scene_.volume().shading);
  edges_->setChecked(scene_.volume().edges);
  outline_->setChecked(scene_.volume().outline);
}

void VolumeActions::drawCellsOwnField(bool on) {
  const std::string renderer = scene_.volume().renderer;
  const auto traits = scene_.volumeRenderers().traitsOf(renderer);
  if (on && traits && !traits->elementInterpolation && scene_.volumeRenderers().drawsApart(renderer)) {
    const std::string drawing =
        scene_.volumeRenderers().namesWhere([](const VolumeRendererTraits& t) { return t.elementInterpolation; });
    window_.statusBar()->showMessage(
        QString::fromStdString("The volume renderer " + renderer + " draws the field linear on the tetrahedra; " +
                               (drawing.empty() ? std::string("no loaded renderer draws the cells' own interpolation")
                                                : "choose " + drawing + " in Volume Renderer to draw the cells' own")));
  } else if (changeScene_([on](Scene& s) {
               s.setInterpolation(on ? FieldInterpolation::Element : FieldInterpolation::Tetrahedra);
             })) {
    QString message = on ? "The volume, sections, iso-surfaces and streamlines show each cell's own interpolation "
                           "of the node values"
                         : "The volume, sections, iso-surfaces and streamlines show the field linear on the "
                           "tetrahedra the cells are split into";
    const bool pieces = traits && scene_.session() && scene_.view() &&
                        drawsCellsFieldOnPieces(*traits, FieldInterpolation::Element, scene_.view()->location,
                                                scene_.session()->model());
    if (on && pieces)
      message += QString("; %1 draws it on tetrahedra refined to the tolerance")
                     .arg(QString::fromStdString(traits->label.empty() ? renderer : traits->label));
    if (on)
      for (const std::string& note : cellsDrawnBySplit(pieces ? BentCells::Followed : BentCells::Flat))
        message += "; " + QString::fromStdString(note);
    window_.statusBar()->showMessage(message);
  }
  syncToScene();
}

bool VolumeActions::setElementTolerance(double tolerance) {
  const auto traits = scene_.volumeRenderers().traitsOf(scene_.volume().renderer);
  if (tolerance == 0.0 && scene_.volumeShown() && traits && scene_.session() && scene_.view() &&
      drawsCellsFieldOnPieces(*traits, scene_.volume().interpolation, scene_.view()->location,
                              scene_.session()->model())) {
    window_.statusBar()->showMessage(QString::fromStdString(
        traits->label +
        " draws the cells' own field on tetrahedra refined to a tolerance "
        "above 0; to draw it exactly choose " +
        scene_.volumeRenderers().namesWhere([](const VolumeRendererTraits& t) { return t.elementInterpolation; }) +
        " in Volume Renderer"));
    syncToScene();
    return false;
  }
  const bool changed = changeScene_([tolerance](Scene& s) { s.setElementTolerance(tolerance); });
  if (changed)
    window_.statusBar()->showMessage(
        tolerance == 0.0 ? QString("The cells' own field is drawn exactly")
                         : QString("The cells' own field is drawn within %1 of its exact picture per pixel channel")
                               .arg(tolerance, 0, 'g', 3));
  syncToScene();
  return changed;
}

void VolumeActions::askElementTolerance() {
  bool ok = false;
  const double tolerance = QInputDialog::getDouble(
      &window_, "Tolerance of the cells' own field",
      QString("Most a pixel's color or opacity may differ from the exact picture\n(0: exact; otherwise %1 to %2):")
          .arg(kLeastElementTolerance, 0, 'g')
          .arg(kMostElementTolerance, 0, 'g'),
      scene_.volume().elementTolerance, 0.0, kMostElementTolerance, 5, &ok);
  if (ok) setElementTolerance(tolerance);
}

std::vector<std::string> VolumeActions::cellsDrawnBySplit(BentCells bent) const {
  const ModelSession* session = scene_.session();
  const std::optional<ScalarView>& view = scene_.view();
  if (!session || !view || view->location != FieldLocation::Node || session->model().grid) return {};
  std::vector<double> converted;
  const TetMesh& split = session->tetrahedra();
  const optics::ElementField field(session->model().mesh(), view->values.doubles(converted), split, glm::dvec3(0.0));
  return elementFieldNotes(field, session->model().mesh(), bent);
}

void VolumeActions::show(bool on) {
  if (!on || !scene_.session()) {
    changeScene_([](Scene& s) { s.setVolumeShown(false); });
    syncToScene();
    followers_.viewChanged();  // the color controls follow the view back
    return;
  }
  if (!scene_.view()) {
    window_.statusBar()->showMessage("Choose a result to render as a volume");
    syncToScene();
    return;
  }
  const bool ok = changeScene_([](Scene& s) { s.setVolumeShown(true); });
  syncToScene();
  if (!ok) return;
  followers_.shown();
  QString message = QString("Volume rendering of %1: colors and opacity in the Transfer Function panel")
                        .arg(QString::fromStdString(scene_.view()->quantity.displayName()));
  const VolumeLayer& volume = scene_.volume();
  if (!volume.isoSurfaces.empty() && !volume.isoQuantity.empty() && volume.isoQuantity != scene_.view()->quantity.key())
    message += QString("; the iso-surfaces of %1 show in the surface view (a volume contours what it renders)")
                   .arg(QString::fromStdString(volume.isoQuantity));
  window_.statusBar()->showMessage(message);
  followers_.viewChanged();
}

bool VolumeActions::setTransferFunction2D(const std::optional<TransferFunction2D>& tf) {
  if (tf && (!scene_.session() || !scene_.session()->model().grid)) {
    window_.statusBar()->showMessage(
        "2D transfer functions (over the value and its gradient) are drawn on regular "
        "grids (SEG-Y, image data); open one first");
    return false;
  }
  const bool wasSet = scene_.volume().transferFunction2D.has_value();
  if (!changeScene_([&](Scene& s) { s.setTransferFunction2D(tf); })) return false;
  // Switched on or off: the 1D editor says whether its function is the one drawn.
  if (wasSet != tf.has_value()) followers_.tablesChanged();
  return true;
}

bool VolumeActions::loadTransferFunction2D(const QString& path) {
  const std::string file = path.toStdString();
  std::optional<TransferFunction2D> tf;
  try {
    tf = TransferFunction2D::fromJson(readTextFile(file, 16u << 20));
  } catch (const std::exception& e) {
    QMessageBox::warning(&window_, "2D transfer function", QString::fromStdString(file + ": " + e.what()));
    return false;
  }
  if (!setTransferFunction2D(tf)) return false;
  followers_.tablesChanged();  // the editor shows the new one
  window_.statusBar()->showMessage("Volume colors from the 2D transfer function " + QFileInfo(path).fileName() +
                                   " (value x gradient magnitude)");
  return true;
}

}  // namespace volpost::app
