// Which burner each knob of a range drives, by layout: the knob row read left to right maps onto
// the burners read column by column from the left, front before rear within a column (the order
// most ranges print beside their knobs). Knobs beyond the burners drive nothing (RoboCasa's
// `knob_dummy`); burners beyond the knobs are left unpaired. Frame: z up, the front faces -y,
// left is -x (robocasa_sites.h).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

// Per knob (input order) the index of the burner it drives, or -1.
std::vector<int> pairKnobsWithBurners(const std::vector<Eigen::Vector2f>& knobs,
                                      const std::vector<Eigen::Vector2f>& burners);

}  // namespace sagrid
