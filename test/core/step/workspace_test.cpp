// The workspace (src/core/workspace.cpp): how a stage splits over the
// threads it asks for, and a workspace moved keeps working.
#include "rigid_body_sim/core/step/workspace.h"

#include <gtest/gtest.h>

#include "../../test_util.h"
#include "rigid_body_sim/core/step/step.h"
#include "step/scratch.h"

namespace rigid_body_sim::test {
namespace {

TEST(Workspace, AStageSplitsIntoTheThreadsAskedForWhenThereIsWorkEnough) {
  core::Workspace ws;
  ws.min_parallel_work = 32;
  ws.threads = 12;  // more than this machine's cores, and more than the old hidden cap of 8
  EXPECT_EQ(core::detail::partsFor(ws, 31), 1);
  EXPECT_EQ(core::detail::partsFor(ws, 32), 12);
  EXPECT_EQ(ws.scratch->pool->threads(), 12);
  EXPECT_GE(ws.scratch->parts.size(), 12u);
  ws.threads = 1;
  EXPECT_EQ(core::detail::partsFor(ws, 1000), 1);
}

TEST(Workspace, AMovedWorkspaceStepsAsTheOriginalWould) {
  const core::Model model(onGround(boxBody(Vec3(0.2, 0.1, 0.05)), core::ContactSettings{}));
  core::LinkState link;
  link.p_WL = Vec3(0, 0, 0.3);
  core::State a = stateOf(model, link), b = a;
  core::Workspace wa, wb;
  for (int k = 0; k < 300; ++k) {
    core::step(model, a, {}, &wa);
    core::step(model, b, {}, &wb);
  }
  core::Workspace moved = std::move(wb);
  for (int k = 0; k < 300; ++k) {
    core::step(model, a, {}, &wa);
    core::step(model, b, {}, &moved);
  }
  EXPECT_TRUE(bitIdentical(a, b));
}

}  // namespace
}  // namespace rigid_body_sim::test
