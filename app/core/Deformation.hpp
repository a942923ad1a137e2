// SPDX-License-Identifier: MIT
// The deformed shape: every node moved by a nodal vector field (a displacement) times a
// scale factor, as a model of its own so that the surface, section cuts, iso-surfaces,
// volume, streamlines and probing all see the deformed geometry.
#pragma once

#include "ModelSession.hpp"

#include <memory>
#include <string>

namespace volpost::app {

/// The scale at which the largest displacement of `field` at `step` is 10 % of the model's
/// size (its bounding-box diagonal); 0 when nothing moves.
double automaticDeformationScale(const ModelSession& base, const std::string& field, std::size_t step);

/// Throws std::invalid_argument unless `field` is a nodal field of three components (what
/// can move nodes), naming the fields that can.
void checkDeformationField(const ModelSession& base, const std::string& field);

/// The base model with node n moved by scale * field(step)[n] (the step clamped to the
/// field's steps); fields are shared with the base, not copied. `blend` (0..1) takes the
/// displacement that far toward the next step's (an animation's in-between frame).
std::shared_ptr<ModelSession> deformedSession(const ModelSession& base, const std::string& field, std::size_t step,
                                              double scale, double blend = 0.0);

}  // namespace volpost::app
