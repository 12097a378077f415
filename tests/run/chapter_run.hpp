// The chapter's scene and the RunOptions a RunScene test asks for, shared by run_scene_test.cpp and
// run_scene_device_test.cpp; it runs nothing itself.
#pragma once

#include "run/run_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_support.hpp"

namespace twinraster::test {

inline Scene Chapter() { return LoadScene(test::SourcePath("scenes/cgfs-transforms.json")); }

inline run::RunOptions Options(run::Backends backends, bool verify = false, bool map = false) {
  run::RunOptions options;
  options.backends = backends;
  options.verify = verify;
  options.map = map;
  return options;
}

}  // namespace twinraster::test
