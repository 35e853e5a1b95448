#pragma once
// Start poses drawn at random, so that a bench can compare methods from many starts in one
// world instead of the world's one: strategies that draw nothing at random otherwise give the
// same run for every seed.

#include <cstdint>

#include "roomscout/core/geometry.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

/// A start pose drawn from `seed` alone (the same for every method): a raster cell of
/// `model` with at least `min_clearance_m` to anything solid, uniform among those connected
/// to the model's own start through cells with room for the robot and a margin (so the robot
/// can leave it), and a uniform heading. The model's own start when no cell qualifies.
Pose2 randomStartPose(const WorldModel& model, std::uint64_t seed, double min_clearance_m = 0.4);

}  // namespace roomscout::sim
