// Which burner each knob of a range drives, by layout: the knob row read left to right maps onto
// the burners read column by column from the left, front before rear within a column (the order
// most ranges print beside their knobs). Knobs beyond the burners drive nothing (RoboCasa's
// `knob_dummy`); burners beyond the knobs are left unpaired. Frame: z up, the front faces -y,
// left is -x (robocasa_sites.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/labels/labels.h"
#include "core/mesh/mesh.h"

namespace sagrid {

// Per knob (input order) the index of the burner it drives, or -1.
std::vector<int> pairKnobsWithBurners(const std::vector<Eigen::Vector2f>& knobs,
                                      const std::vector<Eigen::Vector2f>& burners);

// The same for labelled points (file frame, `fileUp`): per toggle button point, in their order,
// the index among the heat source points of the one it drives, or -1; empty where there is no
// heat source (a sink: nothing to pair).
std::vector<int> pairToggleButtonsWithHeatSources(const std::vector<AffordancePoint>& points,
                                                  UpAxis fileUp);

}  // namespace sagrid
