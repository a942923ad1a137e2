// SPDX-License-Identifier: MIT
#include "ModelLoader.hpp"

#include "ReaderOptionsDialog.hpp"
#include "WorkWithProgress.hpp"

#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

namespace volpost::app {

ModelLoader::ModelLoader(QMainWindow& window, const ReaderRegistry& readers)
    : QObject(&window), window_(window), readers_(readers) {}

bool ModelLoader::open(const QString& path, const ReaderOptions& options, std::function<void(const ModelRead&)> done) {
  if (busy_) {
    window_.statusBar()->showMessage("Still loading the previous file");
    return false;
  }
  busy_ = true;
  lastPath_ = path;
  lastOptions_ = options;
  window_.statusBar()->showMessage("Reading " + path);
  const ReaderRegistry& readers = readers_;
  runWithProgress<std::shared_ptr<ModelSession>>(
      window_, "Reading " + QFileInfo(path).fileName(), 300,
      [&readers, path, options](const Progress& progress) {
        return ModelSession::load(readers, path.toStdString(), progress, ModelSession::Boundary::Now, options);
      },
      [this, done = std::move(done)](WorkOutcome<std::shared_ptr<ModelSession>> r) {
        busy_ = false;
        ModelRead read;
        if (r.value) read.session = *r.value;
        read.cancelled = r.cancelled;
        read.error = r.error;
        done(read);
      });
  return true;
}

std::optional<ReaderOptions> ModelLoader::askReaderOptions() {
  if (lastPath_.isEmpty()) {
    window_.statusBar()->showMessage("Open a model first: reader options apply to a file");
    return std::nullopt;
  }
  const MeshReader* reader = nullptr;
  try {
    reader = &readers_.choose(lastPath_.toStdString());
  } catch (const std::exception& e) {
    QMessageBox::warning(&window_, "Reader options", e.what());
    return std::nullopt;
  }
  const QString fileName = QFileInfo(lastPath_).fileName();
  if (reader->options().empty()) {
    window_.statusBar()->showMessage(
        QString("The %1 reader of %2 has no options").arg(QString::fromStdString(reader->formatName()), fileName));
    return std::nullopt;
  }
  ReaderOptionsDialog dialog(*reader, fileName, lastOptions_, &window_);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  return dialog.chosen();
}

}  // namespace volpost::app
