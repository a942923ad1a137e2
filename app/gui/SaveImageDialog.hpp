// SPDX-License-Identifier: MIT
// File > Save Image: where, at what size (any, not only the window's), how large the words
// are, and whether the background is transparent. The picture is drawn in full as
// `volpost render` draws it (--size, --text-scale, --transparent), without the window's handles.
#pragma once

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace volpost::app {

struct PictureRequest {
  QString path;
  int width = 0, height = 0;
  double textScale = 1.0;
  bool transparent = false;
};

class SaveImageDialog : public QDialog {
  Q_OBJECT

 public:
  /// Starts from `request` (the last path, the view's size, the scene's text scale).
  SaveImageDialog(const PictureRequest& request, QWidget* parent = nullptr);
  PictureRequest request() const;
  /// Why the request cannot be written (no file, a format without transparency), or empty.
  static QString problemWith(const PictureRequest& request);

  void accept() override;

 private:
  QLineEdit* path_;
  QSpinBox* width_;
  QSpinBox* height_;
  QDoubleSpinBox* textScale_;
  QCheckBox* transparent_;
  QLabel* problem_;
};

}  // namespace volpost::app
