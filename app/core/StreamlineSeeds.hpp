// SPDX-License-Identifier: MIT
// Where streamlines start, written as the command line and state files write it:
//   point:X,Y,Z
//   line:X0,Y0,Z0:X1,Y1,Z1:N          N points from the first to the second (a rake)
//   disk:CX,CY,CZ:NX,NY,NZ:R:N        an N x N grid on the disk of radius R (inside it)
//   box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX:N[:SEED]   N random points (SEED: same points again)
//   boundary:CX,CY,CZ:R:N             N points on the model's boundary within R of C
#pragma once

#include "ModelSession.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

/// At most this many seeds in all (lines are traced one per seed).
inline constexpr std::size_t kMaxSeeds = 10000;

/// The seed points of a spec. Throws std::invalid_argument saying what is wrong with it.
std::vector<glm::dvec3> seedPoints(const std::string& spec, const ModelSession& session);
/// All seeds of several specs, at most kMaxSeeds.
std::vector<glm::dvec3> seedPoints(const std::vector<std::string>& specs, const ModelSession& session);

/// The written form of a rake from a to b with n points.
std::string rakeSpec(const glm::dvec3& a, const glm::dvec3& b, int n);
/// "point:X,Y,Z" for a seed, and the point of such a spec (nullopt for another kind).
std::string pointSeedSpec(const glm::dvec3& p);
std::optional<glm::dvec3> pointSeed(const std::string& spec);
/// The ends of a rake's spec (line:A:B:N); nullopt for another kind of spec.
std::optional<std::array<glm::dvec3, 2>> rakeEnds(const std::string& spec);

}  // namespace volpost::app
