#pragma once
// The two result pictures, drawn on a Raster.

#include "common/evaluation/experiment_record.h"
#include "common/evaluation/png_writer.h"

namespace hexplore::evaluation {

// Colour of the i-th robot (stable palette).
Rgb robot_colour(size_t index);

// Completeness (team, observable, per robot) against sim time, with axes and a legend.
Raster completeness_chart(const ExperimentRecord& record, int width = 900, int height = 540);

// Top-down view of the final map (grey by height) with each robot's trajectory in its colour.
Raster topdown_map(const ExperimentRecord& record, int width = 900, int height = 900);

}  // namespace hexplore::evaluation
