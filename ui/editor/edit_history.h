#pragma once
// Undo and redo for one JSON document, kept as whole snapshots. Presets are a few kilobytes, so a
// snapshot per step is cheaper to get right than inverse operations and can never drift out of
// step with what the editor shows. No GL, no ImGui: the editor's panels only call commit().
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace weft::editor {

// The order of the steps of several histories that the user sees as one (the scene and a tool's
// sharp tags: one Ctrl+Z). Every commit and undo takes the next tick; a history's steps keep the
// tick they were committed and undone at, so "the latest edit" and "the edit undone last" can be
// found across documents (shared_undo.h), and a commit in any of them forgets what every one of
// them could have redone, as one linear history would.
struct EditClock {
  std::uint64_t now = 0;         // the last tick handed out
  std::uint64_t lastCommit = 0;  // the tick of the latest commit in any history on this clock
  std::uint64_t tick() { return ++now; }
};

class EditHistory {
 public:
  // Oldest steps are dropped beyond this many, so a long session cannot grow without bound.
  static constexpr std::size_t kMaxUndoSteps = 1000;

  explicit EditHistory(nlohmann::json initial);

  const nlohmann::json& current() const;

  // Records `next` as the new current state (no-op when equal to current) and clears redo. Consecutive
  // commits with the same non-empty mergeKey merge into one undo step (a slider being dragged) until
  // endMerge(), a commit with another key, or an undo/redo. A merged step that ends where it started
  // (the slider dragged back) is dropped, so undo never does nothing.
  void commit(nlohmann::json next, const std::string& label, const std::string& mergeKey = "");
  // The drag is over: the next commit starts a new undo step even with the same key.
  void endMerge();

  bool canUndo() const;
  bool canRedo() const;
  void undo();  // no-op when impossible
  void redo();  // no-op when impossible
  std::string undoLabel() const;  // the label of the step undo() would take back; "" when none
  std::string redoLabel() const;  // the label of the step redo() would replay; "" when none

  // Compares with the saved state itself, not a step number: editing a value back by hand, or undoing
  // to the saved state, is clean again.
  bool dirty() const;
  void markSaved();

  // Changes on every commit, undo and redo, so a view can tell when to re-read current().
  std::uint64_t revision() const;

  // Joins the order of other histories (EditClock). Each history starts on a clock of its own.
  void shareClock(std::shared_ptr<EditClock> clock) { clock_ = std::move(clock); }
  const std::shared_ptr<EditClock>& clock() const { return clock_; }
  // When the step undo() would take back was committed (its last merge); 0 when none.
  std::uint64_t undoTick() const;
  // When the step redo() would replay was undone; 0 when none.
  std::uint64_t redoTick() const;

 private:
  struct Step {
    nlohmann::json state;
    std::string label;  // what the commit that produced `state` did; empty for the initial state
    std::uint64_t committedAt = 0;  // clock ticks: the commit (or its latest merge)...
    std::uint64_t undoneAt = 0;     // ...and the latest undo of this step
  };

  std::vector<Step> steps_;  // steps_[0] is the oldest kept state; steps_[index_] is current
  std::size_t index_ = 0;
  nlohmann::json saved_;
  std::string mergeKey_;                  // the key of the open merge; empty when none
  std::optional<std::size_t> mergeStep_;  // the step the open merge writes into, once it has one
  std::uint64_t revision_ = 0;
  std::shared_ptr<EditClock> clock_ = std::make_shared<EditClock>();
};

}  // namespace weft::editor
