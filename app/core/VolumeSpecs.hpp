// SPDX-License-Identifier: MIT
// The written forms of clip planes, clip boxes and iso-surfaces, shared by the command
// line (--clip, --clip-box, --iso) and the window's dialogs.
#pragma once

#include "SceneState.hpp"

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/optics/IsoTables.hpp>

#include <QString>

#include <optional>
#include <vector>

namespace volpost::app {

/// "x,y,z": a point (model units).
std::optional<glm::dvec3> parsePoint(const QString& text);
/// A color: "r,g,b" (each 0..1), "#rrggbb" or a name ("white", "black", "navy").
std::optional<glm::dvec3> parseColor(const QString& text);
/// "px,py,pz,nx,ny,nz": a point on the plane and the normal toward the kept side.
std::optional<ClipPlane> parseClipPlane(const QString& text);
/// The written form parseClipPlane reads back (full precision).
QString clipPlaneText(const ClipPlane& plane);
/// "xmin,xmax,ymin,ymax,zmin,zmax" with min < max on every axis.
std::optional<ClipBox> parseClipBox(const QString& text);
QString clipBoxText(const ClipBox& box);
/// "VALUE[:r,g,b[:opacity]]", colors and opacity 0..1 (default opaque white).
std::optional<optics::IsoSurface> parseIsoSurface(const QString& text);
/// Several iso-surfaces separated by ';' (empty text: none). On a bad entry, nullopt and
/// `badEntry` names it.
std::optional<std::vector<optics::IsoSurface>> parseIsoSurfaces(const QString& text, QString* badEntry = nullptr);
QString isoSurfacesText(const std::vector<optics::IsoSurface>& surfaces);

}  // namespace volpost::app
