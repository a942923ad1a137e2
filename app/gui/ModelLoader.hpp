// SPDX-License-Identifier: MIT
// How the window reads a model: on a worker thread behind a cancellable progress dialog,
// one file at a time, the model shown staying until the new one is in. It remembers the
// last file tried and its reader options, for File > Reader Options... (read it again with
// others).
#pragma once

#include "../core/ModelSession.hpp"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>

class QMainWindow;

namespace volpost::app {

/// How a read ended: the model, or why not (cancelled, or an error naming the file).
struct ModelRead {
  std::shared_ptr<ModelSession> session;
  bool cancelled = false;
  QString error;
};

class ModelLoader : public QObject {
  Q_OBJECT

 public:
  ModelLoader(QMainWindow& window, const ReaderRegistry& readers);

  /// Starts reading `path` with the reader's `options`; `done` gets the outcome on the GUI
  /// thread. False (said in the status bar) while another file is still being read.
  bool open(const QString& path, const ReaderOptions& options, std::function<void(const ModelRead&)> done);
  bool busy() const { return busy_; }
  /// The last file opened or tried, and its options (empty before the first).
  const QString& lastPath() const { return lastPath_; }
  const ReaderOptions& lastOptions() const { return lastOptions_; }
  /// File > Reader Options...: the options of the last file's reader in a dialog; the
  /// options accepted, nullopt when cancelled or there is nothing to ask (said why).
  std::optional<ReaderOptions> askReaderOptions();

 private:
  QMainWindow& window_;
  const ReaderRegistry& readers_;
  bool busy_ = false;
  QString lastPath_;
  ReaderOptions lastOptions_;
};

}  // namespace volpost::app
