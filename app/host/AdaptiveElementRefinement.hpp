// SPDX-License-Identifier: MIT
// The cells' own field for a volume, refined where the picture would show the difference:
// the split's tetrahedra are bisected along their longest edge (Rivara's conforming
// longest-edge bisection: a tetrahedron is cut only across an edge that every tetrahedron
// sharing it is cut across too, so no piece ends at a point in the middle of a neighbour's
// face and the ray caster's walk from face to face stays whole), worst first, until the
// change of a pixel that each piece's straight edges and linear values cause (estimated to
// first order along the piece) is within the tolerance, or the budget of pieces is spent.
// How much a pixel changes with the field comes from the transfer function: a piece whose
// values the transfer function leaves transparent, or where it is flat, needs no cuts
// (docs/methods/element_field.md).
#pragma once

#include "host/ElementRefinement.hpp"

#include <volpost/core/Progress.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace volpost {

/// What a volume of the cells' own field is refined to.
struct VolumeRefinementGoal {
  /// The most a pixel's channel (0..1) may change by one piece, estimated to first order; above 0.
  double perChannel = 0.01;
  /// The transfer function the volume is drawn with; none: a color map over the values'
  /// range with channels changing by at most 10 per unit of the range (then the field
  /// within a tenth of the tolerance, relative to its range, as surfaces are refined).
  const TransferFunction* transferFunction = nullptr;
  std::size_t maxTetrahedra = 4'000'000;  ///< the bisection stops at this many pieces
};

/// How much a pixel's channel may change per unit of field error along a unit of ray
/// through values between lo and hi, by `tf`: the largest |d color/dv| x extinction +
/// |d extinction/dv| over the transfer function's pieces there, a bound on the change of
/// the emission color x extinction and of the absorption (0 where it is flat or
/// transparent: nothing there shows the error).
double pixelChangePerValue(const TransferFunction& tf, double lo, double hi);

/// The tetrahedra `chosen` (indices into field.split()) bisected in their cells of
/// field.mesh() toward `goal`. The result's deviation is the largest estimated change of a
/// pixel's channel left (in the goal's units), its bisections the most times one piece of
/// the split was halved (its level stays 1). Throws volpost::Cancelled when `progress` cancels.
RefinedTetrahedra refineVolumeAdaptively(const optics::ElementField& field, std::span<const std::uint32_t> chosen,
                                         const VolumeRefinementGoal& goal, const Progress& progress = {});

}  // namespace volpost
