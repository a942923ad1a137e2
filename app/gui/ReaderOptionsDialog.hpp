// SPDX-License-Identifier: MIT
// File > Reader Options...: a field per option of the reader of a file (SEG-Y header
// bytes, sample format ...), filled with the options it was last read with; empty fields
// keep the reader's defaults.
#pragma once

#include <volpost/core/MeshReader.hpp>

#include <QDialog>
#include <QString>

#include <string>
#include <utility>
#include <vector>

class QLineEdit;

namespace volpost::app {

class ReaderOptionsDialog : public QDialog {
  Q_OBJECT

 public:
  /// `reader` has at least one option; `fileName` is what the title names.
  ReaderOptionsDialog(const MeshReader& reader, const QString& fileName, const ReaderOptions& current,
                      QWidget* parent = nullptr);
  /// The options typed (the empty fields left out).
  ReaderOptions chosen() const;

 private:
  std::vector<std::pair<std::string, QLineEdit*>> fields_;
};

}  // namespace volpost::app
