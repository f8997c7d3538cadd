// Category classifier samples with only what the classifier reads (id, category, group,
// descriptor): no mesh, so the evidence gate is never asked about them.
#pragma once

#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"

namespace sagrid::test {

CategorySample categorySample(std::string id, std::string category, std::string group,
                              std::vector<float> descriptor);

}  // namespace sagrid::test
