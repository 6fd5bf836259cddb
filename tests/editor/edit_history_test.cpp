// Undo and redo as the editor's panels will drive them: labelled steps, a slider drag merged into one
// step, and dirty meaning "differs from what was saved", however the state got there.
#include "editor/edit_history.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace weft::editor {
namespace {

using nlohmann::json;

json withDensity(double density) { return {{"name", "cotton"}, {"density", density}}; }

TEST(EditHistory, StartsAtTheInitialStateWithNothingToUndoOrRedo) {
  const EditHistory history(withDensity(1.0));
  EXPECT_EQ(history.current(), withDensity(1.0));
  EXPECT_FALSE(history.canUndo());
  EXPECT_FALSE(history.canRedo());
  EXPECT_EQ(history.undoLabel(), "");
  EXPECT_EQ(history.redoLabel(), "");
  EXPECT_FALSE(history.dirty());
}

TEST(EditHistory, UndoAndRedoWalkTheCommitsWithTheirLabels) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "Set density");
  history.commit({{"name", "denim"}, {"density", 2.0}}, "Rename");
  EXPECT_EQ(history.undoLabel(), "Rename");

  history.undo();
  EXPECT_EQ(history.current(), withDensity(2.0));
  EXPECT_EQ(history.undoLabel(), "Set density");
  EXPECT_EQ(history.redoLabel(), "Rename");

  history.undo();
  EXPECT_EQ(history.current(), withDensity(1.0));
  EXPECT_FALSE(history.canUndo());
  EXPECT_EQ(history.redoLabel(), "Set density");

  history.redo();
  history.redo();
  EXPECT_EQ(history.current()["name"], "denim");
  EXPECT_FALSE(history.canRedo());
  EXPECT_EQ(history.redoLabel(), "");
}

TEST(EditHistory, UndoAndRedoWhenImpossibleChangeNothing) {
  EditHistory history(withDensity(1.0));
  const auto revision = history.revision();
  history.undo();
  history.redo();
  EXPECT_EQ(history.current(), withDensity(1.0));
  EXPECT_EQ(history.revision(), revision);
}

TEST(EditHistory, ANewCommitClearsRedo) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "a");
  history.undo();
  ASSERT_TRUE(history.canRedo());
  history.commit(withDensity(3.0), "b");
  EXPECT_FALSE(history.canRedo());
  history.redo();
  EXPECT_EQ(history.current(), withDensity(3.0));
  history.undo();
  EXPECT_EQ(history.current(), withDensity(1.0));
}

TEST(EditHistory, CommittingTheCurrentStateIsANoOp) {
  EditHistory history(withDensity(1.0));
  const auto revision = history.revision();
  history.commit(withDensity(1.0), "nothing");
  EXPECT_FALSE(history.canUndo());
  EXPECT_EQ(history.revision(), revision);
  EXPECT_FALSE(history.dirty());
}

TEST(EditHistory, RevisionChangesOnEveryCommitUndoAndRedo) {
  EditHistory history(withDensity(1.0));
  auto last = history.revision();
  const auto changed = [&] {
    const bool differs = history.revision() != last;
    last = history.revision();
    return differs;
  };
  history.commit(withDensity(2.0), "a");
  EXPECT_TRUE(changed());
  history.commit(withDensity(3.0), "drag", "density");
  EXPECT_TRUE(changed());
  history.commit(withDensity(4.0), "drag", "density");  // merged, but the state still changed
  EXPECT_TRUE(changed());
  history.undo();
  EXPECT_TRUE(changed());
  history.redo();
  EXPECT_TRUE(changed());
}

TEST(EditHistory, CommitsWithTheSameKeyMergeIntoOneStepUntilEndMerge) {
  EditHistory history(withDensity(1.0));
  for (double d : {1.1, 1.2, 1.3}) history.commit(withDensity(d), "Drag density", "density");
  history.undo();
  EXPECT_EQ(history.current(), withDensity(1.0)) << "the whole drag is one step";
  history.redo();
  EXPECT_EQ(history.current(), withDensity(1.3));

  history.endMerge();
  history.commit(withDensity(1.4), "Drag density", "density");
  history.undo();
  EXPECT_EQ(history.current(), withDensity(1.3)) << "after endMerge the same key starts a new step";
}

TEST(EditHistory, CommitsWithDifferentOrNoKeysDoNotMerge) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "a", "density");
  history.commit(withDensity(3.0), "b", "stiffness");
  history.commit(withDensity(4.0), "c");
  history.commit(withDensity(5.0), "d");
  int steps = 0;
  while (history.canUndo()) {
    history.undo();
    ++steps;
  }
  EXPECT_EQ(steps, 4);
}

TEST(EditHistory, UndoEndsAMerge) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "a", "density");
  history.commit(withDensity(3.0), "b", "density");
  history.undo();
  history.commit(withDensity(4.0), "c", "density");  // a new step from 1.0, not a merge into the undone one
  history.undo();
  EXPECT_EQ(history.current(), withDensity(1.0));
  EXPECT_FALSE(history.canUndo());
}

TEST(EditHistory, ADragBackToWhereItStartedLeavesNoStep) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "first edit");
  history.commit(withDensity(2.5), "Drag density", "density");
  history.commit(withDensity(2.0), "Drag density", "density");
  EXPECT_EQ(history.undoLabel(), "first edit");
  history.commit(withDensity(2.7), "Drag density", "density");  // the drag goes on: a fresh step
  history.undo();
  EXPECT_EQ(history.current(), withDensity(2.0));
  EXPECT_EQ(history.undoLabel(), "first edit");
}

TEST(EditHistory, DirtyFollowsTheSavedStateThroughUndoAndRedo) {
  EditHistory history(withDensity(1.0));
  history.commit(withDensity(2.0), "a");
  EXPECT_TRUE(history.dirty());
  history.undo();
  EXPECT_FALSE(history.dirty()) << "undone back to the saved state";

  history.redo();
  history.markSaved();
  EXPECT_FALSE(history.dirty());
  history.undo();
  EXPECT_TRUE(history.dirty()) << "the saved state is now the later one";
  history.commit(withDensity(2.0), "typed the saved value back");
  EXPECT_FALSE(history.dirty());
}

TEST(EditHistory, KeepsAtMostTheStepLimit) {
  EditHistory history(0);
  const int commits = static_cast<int>(EditHistory::kMaxUndoSteps) + 10;
  for (int i = 1; i <= commits; ++i) history.commit(i, "step");
  int steps = 0;
  while (history.canUndo()) {
    history.undo();
    ++steps;
  }
  EXPECT_EQ(steps, static_cast<int>(EditHistory::kMaxUndoSteps) - 1);
  EXPECT_EQ(history.current(), commits - static_cast<int>(EditHistory::kMaxUndoSteps) + 1);
}

}  // namespace
}  // namespace weft::editor
