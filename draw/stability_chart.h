// The regularized law's stability map as a chart: each (threshold speed, step) cell coloured by
// what a block launched on flat ground does there (settles, chatters, diverges), with linear
// theory's boundary drawn over it. The bench draws it for each integrator; the window draws
// Box2D's (semi-implicit Euler) with the lesson's own step and thresholds marked on it.
#pragma once

#include <string>
#include <vector>

#include "draw/chart.h"
#include "physics/stability.h"

namespace frictionlab::draw {

Chart stability_map_chart(const std::string& title, const std::vector<StabilityCell>& cells, const FrictionPair& pair,
                          double gravity, Integrator integrator, const std::vector<double>& epsilons);

}  // namespace frictionlab::draw
