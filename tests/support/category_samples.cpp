#include "support/category_samples.h"

#include <utility>

namespace sagrid::test {

CategorySample categorySample(std::string id, std::string category, std::string group,
                              std::vector<float> descriptor) {
  CategorySample s;
  s.id = std::move(id);
  s.category = std::move(category);
  s.group = std::move(group);
  s.descriptor = std::move(descriptor);
  return s;
}

}  // namespace sagrid::test
