#include "support/same_labels.h"

#include <gtest/gtest.h>

#include "core/labels/labels.h"

namespace sagrid::test {

void expectSameLabels(const std::filesystem::path& a, const std::filesystem::path& b,
                      float tolerance) {
  const ObjectLabels la = readLabels(a), lb = readLabels(b);
  EXPECT_EQ(la.object.category, lb.object.category) << a;
  ASSERT_EQ(la.affordances.size(), lb.affordances.size()) << a;
  for (std::size_t i = 0; i < la.affordances.size(); ++i) {
    EXPECT_EQ(la.affordances[i].type, lb.affordances[i].type) << a;
    EXPECT_LT((la.affordances[i].position - lb.affordances[i].position).norm(), tolerance) << a;
  }
}

}  // namespace sagrid::test
