// SPDX-License-Identifier: MIT
// Pictures (what the window or `volpost render` shows) written whole or not at all.
#pragma once

#include <QImage>
#include <QString>

#include <string>

namespace volpost::app {

/// Encodes by the file's extension (.png; .jpg and what else Qt writes) and writes through
/// AtomicFile. Throws WriteError naming the file (unknown extension, folder missing, disk
/// full); the previous file stays as it was.
void savePicture(const QImage& image, const QString& path);
/// The picture encoded as `path`'s extension asks (what savePicture writes); WriteError
/// for an extension that is no picture format.
std::string pictureBytes(const QImage& image, const QString& path);

/// The format savePicture would use for `path`; throws std::invalid_argument listing the
/// formats when there is none.
QByteArray pictureFormatOf(const QString& path);

}  // namespace volpost::app
