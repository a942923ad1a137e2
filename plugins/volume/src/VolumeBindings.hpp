// SPDX-License-Identifier: MIT
// Binding points shared by the volume shaders and the C++ that binds their resources:
// written once here and handed to every program as #defines (BINDING_NODES, UNIT_PSI...),
// so the two sides cannot drift apart.
#pragma once

#include <volpost/render/GL.hpp>

#include <string>

namespace volpost::volume::binding {

// Shader storage buffers.
inline constexpr GLuint kNodes = 0;          ///< vec4 per node: mesh-relative xyz, value
inline constexpr GLuint kTets = 1;           ///< uvec4 per tet
inline constexpr GLuint kNeighbors = 2;      ///< 3 words per tet, then far pairs (TetMeshGpu::neighbors)
inline constexpr GLuint kCellValues = 3;     ///< float per tet (element results)
inline constexpr GLuint kBvh = 4;            ///< boundary-face BVH nodes
inline constexpr GLuint kBoundaryFaces = 5;  ///< tet * 4 + face, BVH leaf order
inline constexpr GLuint kTfColorTau = 6;     ///< transfer function: color + extinction per point
inline constexpr GLuint kTfValues = 7;       ///< transfer function: value per point
inline constexpr GLuint kOrder = 8;          ///< cell projection: back-to-front tet list
inline constexpr GLuint kRayState = 9;       ///< ray caster: where each pixel's ray stopped (uvec4 per pixel)
inline constexpr GLuint kRayCounters = 10;   ///< ray caster: rays left unfinished, rays stopped at the step cap
inline constexpr GLuint kTfKnots = 11;       ///< transfer function: pre-integration coordinate, running extinction integral
inline constexpr GLuint kVisibleTets = 12;   ///< empty-space skipping: a bit per tet that can show something
inline constexpr GLuint kFoundFaces = 13;    ///< visible_tets.comp: the faces where the visible part ends
inline constexpr GLuint kBufferCount = 14;

// Texture units.
inline constexpr GLuint kPsiTable = 0;
inline constexpr GLuint kIsoTable = 1;
inline constexpr GLuint kPreTable = 2;
inline constexpr GLuint kSceneDepth = 3;
inline constexpr GLuint kImage = 4;          ///< the float image (composite pass, image unit 0)
inline constexpr GLuint kGrid = 5;           ///< a regular grid's values (3D texture)
inline constexpr GLuint kTf2d = 6;           ///< a 2D transfer function's table
inline constexpr GLuint kNearestEntry = 7;   ///< ray caster: each pixel's nearest entry (TetRayDispatch)
inline constexpr GLuint kFarthestEntry = 8;  ///< ray caster: each pixel's farthest entry
inline constexpr GLuint kThickPsi = 9;       ///< psi of thick pieces: optics::ThickPsiTable (1D)

/// "#define BINDING_NODES 0\n..." for every constant above, and the thick-psi table's
/// constants (THICK_PSI_MIN_DEPTH, THICK_PSI_TABLE_END).
std::string glslDefines();

}  // namespace volpost::volume::binding
