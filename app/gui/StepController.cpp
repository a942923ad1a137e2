// SPDX-License-Identifier: MIT
#include "StepController.hpp"

#include "../core/AnimationFrames.hpp"
#include "../core/PictureFile.hpp"
#include "Viewport.hpp"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QThread>
#include <QTimer>
#include <QToolBar>

#include <cmath>

namespace volpost::app {

namespace {

enum RangeMode { EachStep = 0, AllSteps = 1, Typed = 2 };

std::optional<double> numberIn(const QLineEdit& edit) {
  bool ok = false;
  const double v = edit.text().trimmed().toDouble(&ok);
  return ok && std::isfinite(v) ? std::optional(v) : std::nullopt;
}

}  // namespace

StepController::StepController(QMainWindow& window, Viewport& viewport, QToolBar& toolbar, QComboBox& stepBox,
                               QMenu& viewMenu, QMenu& fileMenu, std::function<void()> changed)
    : QObject(&window), window_(window), viewport_(viewport), stepBox_(stepBox), changed_(std::move(changed)) {
  viewMenu.addSeparator();
  previous_ = viewMenu.addAction("Pre&vious Step", QKeySequence(Qt::Key_PageUp), this, [this] { step(-1); });
  previous_->setObjectName("previousStepAction");
  next_ = viewMenu.addAction("&Next Step", QKeySequence(Qt::Key_PageDown), this, [this] { step(+1); });
  next_->setObjectName("nextStepAction");
  play_ = viewMenu.addAction("Pla&y Steps");
  play_->setObjectName("playStepsAction");
  play_->setCheckable(true);
  play_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Space));
  connect(play_, &QAction::toggled, this, &StepController::setPlaying);
  previous_->setIcon(window.style()->standardIcon(QStyle::SP_MediaSeekBackward));
  next_->setIcon(window.style()->standardIcon(QStyle::SP_MediaSeekForward));
  play_->setIcon(window.style()->standardIcon(QStyle::SP_MediaPlay));
  toolbar.addAction(previous_);
  toolbar.addAction(next_);
  toolbar.addAction(play_);
  for (QAction* a : {previous_, next_, play_}) a->setToolTip(a->text().remove('&') + " (" + a->shortcut().toString() + ")");
  timer_ = new QTimer(this);
  timer_->setInterval(700);
  connect(timer_, &QTimer::timeout, this, [this] {
    stepBox_.setCurrentIndex((stepBox_.currentIndex() + 1) % std::max(1, stepBox_.count()));
  });

  toolbar.addWidget(new QLabel("  Range: "));
  rangeBox_ = new QComboBox(&window);
  rangeBox_->setObjectName("rangeBox");
  rangeBox_->addItems({"Each step", "All steps", "Typed"});
  rangeBox_->setToolTip("What the colors span: each step's own values, the values over every step (one scale "
                        "for an animation), or a typed minimum and maximum");
  toolbar.addWidget(rangeBox_);
  minEdit_ = new QLineEdit(&window);
  minEdit_->setObjectName("rangeMin");
  maxEdit_ = new QLineEdit(&window);
  maxEdit_->setObjectName("rangeMax");
  for (QLineEdit* e : {minEdit_, maxEdit_}) {
    e->setMaximumWidth(90);
    connect(e, &QLineEdit::returnPressed, this, &StepController::applyTypedRange);
  }
  minEdit_->setPlaceholderText("min");
  maxEdit_->setPlaceholderText("max");
  minField_ = toolbar.addWidget(minEdit_);
  maxField_ = toolbar.addWidget(maxEdit_);
  connect(rangeBox_, &QComboBox::currentIndexChanged, this, &StepController::chooseRangeMode);

  // After File > Save Image, its neighbour (or at the end of the menu).
  auto* exportAction = new QAction("Export &Animation...", &fileMenu);
  QAction* before = nullptr;
  const auto actions = fileMenu.actions();
  for (qsizetype i = 0; i + 1 < actions.size(); ++i)
    if (actions[i]->text().contains("Save &Image")) before = actions[i + 1];
  fileMenu.insertAction(before, exportAction);
  exportAction->setObjectName("exportAnimationAction");
  connect(exportAction, &QAction::triggered, this, [this] {
    QSettings settings("volpost", "volpost");
    const QString path = QFileDialog::getSaveFileName(
        &window_, "Export animation: a video, or one picture per step",
        settings.value("files/lastAnimation", "animation.mp4").toString(),
        "Videos (*.mp4 *.mkv *.webm *.avi);;PNG images, numbered (*.png);;JPEG images, numbered (*.jpg)");
    if (path.isEmpty()) return;
    double framesPerSecond = AnimationOutput::kDefaultFramesPerSecond;
    if (VideoFile::isVideoPath(path)) {
      bool ok = false;
      framesPerSecond = QInputDialog::getDouble(&window_, "Export animation", "Steps per second of video:",
                                                settings.value("files/animationRate", framesPerSecond).toDouble(), 0.1,
                                                120, 1, &ok);
      if (!ok) return;
      settings.setValue("files/animationRate", framesPerSecond);
    }
    int between = 0;
    if (stepBox_.count() > 1) {
      bool ok = false;
      between = QInputDialog::getInt(&window_, "Export animation",
                                     "Frames between steps, the values and the shape interpolated (0: one frame "
                                     "per step):",
                                     settings.value("files/animationBetween", 0).toInt(), 0, 100, 1, &ok);
      if (!ok) return;
      settings.setValue("files/animationBetween", between);
    }
    settings.setValue("files/lastAnimation", path);
    exportAnimation(path, framesPerSecond, between);
  });
  refresh();
  showRangeFields();
}

bool StepController::playing() const { return play_->isChecked(); }

void StepController::refresh() {
  const bool steps = stepBox_.count() > 1;
  for (QAction* a : {previous_, next_, play_}) a->setEnabled(steps);
  if (!steps && play_->isChecked()) play_->setChecked(false);
  if (rangeBox_->currentIndex() == Typed && minEdit_->text().isEmpty()) showRangeFields();
}

void StepController::quantityChanged() {
  if (rangeBox_->currentIndex() != Typed) return;
  const QSignalBlocker block(rangeBox_);
  rangeBox_->setCurrentIndex(EachStep);
  viewport_.scene().setRangeOverSteps(false);
  showRangeFields();
}

void StepController::syncToScene() {
  const auto& state = viewport_.scene().state();
  const QSignalBlocker block(rangeBox_);
  rangeBox_->setCurrentIndex(state.fixedRange ? Typed : state.rangeOverSteps ? AllSteps : EachStep);
  showRangeFields();
}

void StepController::step(int delta) {
  const int count = stepBox_.count();
  if (count < 2) return;
  stepBox_.setCurrentIndex(std::clamp(stepBox_.currentIndex() + delta, 0, count - 1));
}

void StepController::setPlaying(bool on) {
  if (on && stepBox_.count() > 1) {
    timer_->start();
    window_.statusBar()->showMessage("Playing the steps (Ctrl+Space stops)");
  } else {
    timer_->stop();
  }
}

void StepController::chooseRangeMode(int index) {
  Scene& scene = viewport_.scene();
  try {
    if (index == AllSteps) scene.setRangeOverSteps(true);
    if (index == EachStep) scene.setRangeOverSteps(false);
    if (index == Typed) scene.setFixedRange(scene.displayRange());  // start from what is shown
  } catch (const std::exception& e) {
    window_.statusBar()->showMessage(e.what());
  }
  showRangeFields();
  viewport_.update();
  changed_();
}

void StepController::applyTypedRange() {
  const auto min = numberIn(*minEdit_), max = numberIn(*maxEdit_);
  if (!min || !max || !(*max > *min)) {
    window_.statusBar()->showMessage(QString("The range needs two numbers, min < max (not '%1' and '%2')")
                                         .arg(minEdit_->text(), maxEdit_->text()));
    showRangeFields();  // back to what is in force
    return;
  }
  viewport_.scene().setFixedRange(DisplayRange{*min, *max});
  {
    const QSignalBlocker block(rangeBox_);
    rangeBox_->setCurrentIndex(Typed);
  }
  showRangeFields();
  viewport_.update();
  changed_();
}

void StepController::showRangeFields() {
  const bool typed = rangeBox_->currentIndex() == Typed;
  minField_->setVisible(typed);
  maxField_->setVisible(typed);
  const DisplayRange r = viewport_.scene().displayRange();
  minEdit_->setText(QString::number(r.min, 'g', 10));
  maxEdit_->setText(QString::number(r.max, 'g', 10));
}

int StepController::exportAnimation(const QString& path, double framesPerSecond, int between) {
  const int count = stepBox_.count();
  if (count < 1 || !viewport_.scene().view()) {
    window_.statusBar()->showMessage("Export Animation needs a result shown (choose one in the toolbar)");
    return 0;
  }
  const bool wasPlaying = play_->isChecked();
  play_->setChecked(false);
  const int kept = stepBox_.currentIndex();
  between = std::clamp(between, 0, 100);
  const int frames = count + (count - 1) * between;  // each step, and `between` after all but the last
  AnimationOutput output(path, std::size_t(frames), framesPerSecond);
  QProgressDialog progress(output.isVideo() ? "Writing a video..." : "Writing the pictures...", "Cancel", 0, frames,
                           &window_);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(300);
  QString error, written;
  for (int i = 0, frame = 0; i < count && !progress.wasCanceled() && error.isEmpty(); ++i) {
    stepBox_.setCurrentIndex(i);
    for (int k = 0; k <= (i + 1 < count ? between : 0) && !progress.wasCanceled(); ++k, ++frame) {
      progress.setValue(frame);
      viewport_.scene().setStepBlend(double(k) / double(between + 1));  // an in-between frame
      // What is still being prepared for this frame (transfer-function tables, streamlines)
      // is waited for, so each picture is complete.
      QElapsedTimer waited;
      waited.start();
      while ((viewport_.drawing().hasPendingWork() || viewport_.scene().streamlinesNeedTracing()) &&
             waited.elapsed() < 60000 && !progress.wasCanceled()) {
        QApplication::processEvents(QEventLoop::AllEvents, 50);
        QThread::msleep(10);
      }
      try {
        output.add(viewport_.grabFramebuffer());
      } catch (const std::exception& e) {
        error = e.what();
        break;
      }
    }
  }
  viewport_.scene().setStepBlend(0.0);
  const bool cancelled = progress.wasCanceled();
  // A cancelled video is not written at all (half a video is of no use); the pictures
  // written before a cancel stay.
  if (error.isEmpty() && !(cancelled && output.isVideo())) try {
      written = output.finish();
    } catch (const std::exception& e) {
      error = e.what();
    }
  progress.setValue(frames);
  stepBox_.setCurrentIndex(kept);
  if (wasPlaying) play_->setChecked(true);
  if (!error.isEmpty()) {
    QMessageBox::warning(&window_, "Export animation", error);
    return output.isVideo() ? 0 : int(output.added());
  }
  if (output.isVideo()) {
    window_.statusBar()->showMessage(written.isEmpty() ? QString("Cancelled: no video written")
                                                       : QString("Wrote a video of %1 frames at %2 per second: %3")
                                                             .arg(output.added())
                                                             .arg(framesPerSecond)
                                                             .arg(written));
    return written.isEmpty() ? 0 : int(output.added());
  }
  window_.statusBar()->showMessage(QString("Wrote %1 of %2 pictures: %3 ...")
                                       .arg(output.added())
                                       .arg(frames)
                                       .arg(framePath(path, 0, std::size_t(frames))));
  return int(output.added());
}

}  // namespace volpost::app
