// MuJoCo models for the export tests (Debian's libmujoco 2.2.2): loading an export, and the body
// tree as RoboCasa's XPath lookups see it.
#pragma once

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <filesystem>
#include <memory>
#include <string>

namespace sagrid::test {

using ModelPtr = std::unique_ptr<mjModel, decltype(&mj_deleteModel)>;
using DataPtr = std::unique_ptr<mjData, decltype(&mj_deleteData)>;

inline ModelPtr loadModel(const std::filesystem::path& xml) {
  char error[1000] = "";
  ModelPtr model(mj_loadXML(xml.c_str(), nullptr, error, sizeof error), &mj_deleteModel);
  EXPECT_TRUE(model) << xml << ": " << error;
  return model;
}

inline DataPtr makeData(const mjModel& model) {
  return DataPtr(mj_makeData(&model), &mj_deleteData);
}

// How deep a body lies below the world: worldbody's children are 1. RoboCasa's "./body/body/site"
// (from worldbody) is a site of a body at depth 2, "./body/body/body/joint" a joint of one at 3.
inline int bodyDepth(const mjModel& model, int body) {
  int depth = 0;
  while (body > 0) body = model.body_parentid[body], ++depth;
  return depth;
}

}  // namespace sagrid::test
