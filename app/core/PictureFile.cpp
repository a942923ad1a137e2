// SPDX-License-Identifier: MIT
#include "PictureFile.hpp"

#include "host/AtomicFile.hpp"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>

#include <stdexcept>

namespace volpost::app {

QByteArray pictureFormatOf(const QString& path) {
  const QByteArray suffix = QFileInfo(path).suffix().toLower().toLatin1();
  const QByteArray format = suffix == "jpeg" ? QByteArray("jpg") : suffix;
  if (format.isEmpty() || !QImageWriter::supportedImageFormats().contains(format))
    throw std::invalid_argument(QString("%1: pictures are written as .png (or %2), by the file's extension")
                                    .arg(path, QString(QImageWriter::supportedImageFormats().join(", ")))
                                    .toStdString());
  return format;
}

std::string pictureBytes(const QImage& image, const QString& path) {
  QByteArray format;
  try {
    format = pictureFormatOf(path);
  } catch (const std::invalid_argument& e) {
    throw WriteError(QFile::encodeName(path).toStdString(), e.what());
  }
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, format.constData()))
    throw WriteError(QFile::encodeName(path).toStdString(), "could not encode the picture as " + format.toStdString());
  return std::string(bytes.constData(), std::size_t(bytes.size()));
}

void savePicture(const QImage& image, const QString& path) {
  writeFileAtomically(QFile::encodeName(path).toStdString(), pictureBytes(image, path));
}

}  // namespace volpost::app
