// SPDX-License-Identifier: MIT
#include "VolumeSpecs.hpp"

#include <QColor>
#include <QRegularExpression>
#include <QStringList>

#include <cmath>

namespace volpost::app {
namespace {

// Numbers separated by commas, semicolons or spaces ("0 0 0", "1, 2, 3"), as a points
// file writes them.
std::optional<std::vector<double>> numbers(const QString& text, int count) {
  static const QRegularExpression separators("\\s*[,;]\\s*|\\s+");
  const QStringList parts = text.trimmed().split(separators);
  if (parts.size() != count) return std::nullopt;
  std::vector<double> v;
  for (const QString& p : parts) {
    bool ok = false;
    v.push_back(p.trimmed().toDouble(&ok));
    if (!ok || !std::isfinite(v.back())) return std::nullopt;  // Qt reads "nan" and "inf" as numbers
  }
  return v;
}

}  // namespace

std::optional<glm::dvec3> parseColor(const QString& text) {
  if (text.contains(',')) {
    const auto c = parsePoint(text);
    if (!c) return std::nullopt;
    for (int k = 0; k < 3; ++k)
      if (!((*c)[k] >= 0.0 && (*c)[k] <= 1.0)) return std::nullopt;
    return c;
  }
  if (!QColor::isValidColorName(text.trimmed())) return std::nullopt;
  const QColor named = QColor::fromString(text.trimmed());
  return glm::dvec3(named.redF(), named.greenF(), named.blueF());
}

std::optional<glm::dvec3> parsePoint(const QString& text) {
  const auto v = numbers(text, 3);
  if (!v) return std::nullopt;
  return glm::dvec3((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<ClipPlane> parseClipPlane(const QString& text) {
  const auto v = numbers(text, 6);
  if (!v) return std::nullopt;
  const ClipPlane plane{{(*v)[0], (*v)[1], (*v)[2]}, {(*v)[3], (*v)[4], (*v)[5]}};
  if (plane.normal == glm::dvec3(0.0)) return std::nullopt;  // no side to keep (1e308 is fine: scaled first)
  return plane;
}

std::optional<ClipBox> parseClipBox(const QString& text) {
  const auto v = numbers(text, 6);
  if (!v) return std::nullopt;
  ClipBox box{};
  for (std::size_t i = 0; i < 6; ++i) box[i] = (*v)[i];
  for (std::size_t i = 0; i < 6; i += 2)
    if (!(box[i + 1] > box[i])) return std::nullopt;
  return box;
}

std::optional<optics::IsoSurface> parseIsoSurface(const QString& text) {
  const QStringList parts = text.trimmed().split(':');
  bool ok = false;
  optics::IsoSurface iso{parts[0].toDouble(&ok), glm::dvec3(1.0), 1.0};
  if (!ok || !std::isfinite(iso.value) || parts.size() > 3) return std::nullopt;
  if (parts.size() >= 2) {
    const auto rgb = numbers(parts[1], 3);
    if (!rgb) return std::nullopt;
    for (int k = 0; k < 3; ++k) {
      iso.color[k] = (*rgb)[std::size_t(k)];
      if (iso.color[k] < 0.0 || iso.color[k] > 1.0) return std::nullopt;
    }
  }
  if (parts.size() == 3) {
    iso.opacity = parts[2].toDouble(&ok);
    if (!ok || !(iso.opacity >= 0.0 && iso.opacity <= 1.0)) return std::nullopt;  // NaN too
  }
  return iso;
}

std::optional<std::vector<optics::IsoSurface>> parseIsoSurfaces(const QString& text, QString* badEntry) {
  std::vector<optics::IsoSurface> out;
  for (const QString& entry : text.split(';', Qt::SkipEmptyParts)) {
    if (entry.trimmed().isEmpty()) continue;
    const auto iso = parseIsoSurface(entry);
    if (!iso || out.size() == std::size_t(kMaxIsoSurfaces)) {
      if (badEntry) *badEntry = entry.trimmed();
      return std::nullopt;
    }
    out.push_back(*iso);
  }
  return out;
}

QString clipBoxText(const ClipBox& box) {
  QStringList parts;
  for (double v : box) parts << QString::number(v, 'g', 12);
  return parts.join(',');
}

QString clipPlaneText(const ClipPlane& plane) {
  QStringList parts;
  for (int k = 0; k < 3; ++k) parts << QString::number(plane.point[k], 'g', 12);
  for (int k = 0; k < 3; ++k) parts << QString::number(plane.normal[k], 'g', 12);
  return parts.join(',');
}

QString isoSurfacesText(const std::vector<optics::IsoSurface>& surfaces) {
  QStringList parts;
  for (const auto& s : surfaces)
    parts << QString("%1:%2,%3,%4:%5").arg(s.value, 0, 'g', 8).arg(s.color.r).arg(s.color.g).arg(s.color.b).arg(s.opacity);
  return parts.join("; ");
}

}  // namespace volpost::app
