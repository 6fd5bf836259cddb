#include "editor/edit_history.h"

#include <utility>

namespace weft::editor {

using nlohmann::json;

EditHistory::EditHistory(json initial) : saved_(initial) { steps_.push_back({std::move(initial), ""}); }

const json& EditHistory::current() const { return steps_[index_].state; }

void EditHistory::commit(json next, const std::string& label, const std::string& mergeKey) {
  if (next == current()) return;
  const bool merging = !mergeKey.empty() && mergeKey == mergeKey_ && mergeStep_ == index_;
  const std::uint64_t now = clock_->tick();
  clock_->lastCommit = now;  // what any history on the clock could redo is forgotten
  if (merging) {
    steps_[index_] = {std::move(next), label, now, 0};
    // index_ > 0 here: a merge step is always one pushed by commit().
    if (steps_[index_].state == steps_[index_ - 1].state) {
      steps_.pop_back();
      --index_;
      mergeStep_.reset();  // the key stays open: dragging on starts a fresh step
    }
  } else {
    steps_.resize(index_ + 1);  // a new edit forgets what could have been redone
    steps_.push_back({std::move(next), label, now, 0});
    ++index_;
    if (steps_.size() > kMaxUndoSteps) {
      steps_.erase(steps_.begin());
      --index_;
    }
    mergeKey_ = mergeKey;
    mergeStep_ = mergeKey.empty() ? std::nullopt : std::optional<std::size_t>(index_);
  }
  ++revision_;
}

void EditHistory::endMerge() {
  mergeKey_.clear();
  mergeStep_.reset();
}

bool EditHistory::canUndo() const { return index_ > 0; }
// A step undone before the latest commit on the clock (in this history or another) is not
// redone: that commit started a new line of edits.
bool EditHistory::canRedo() const { return index_ + 1 < steps_.size() && steps_[index_ + 1].undoneAt > clock_->lastCommit; }

void EditHistory::undo() {
  if (!canUndo()) return;
  endMerge();
  steps_[index_].undoneAt = clock_->tick();
  --index_;
  ++revision_;
}

void EditHistory::redo() {
  if (!canRedo()) return;
  endMerge();
  ++index_;
  ++revision_;
}

std::string EditHistory::undoLabel() const { return canUndo() ? steps_[index_].label : ""; }
std::string EditHistory::redoLabel() const { return canRedo() ? steps_[index_ + 1].label : ""; }

bool EditHistory::dirty() const { return current() != saved_; }
void EditHistory::markSaved() { saved_ = current(); }

std::uint64_t EditHistory::revision() const { return revision_; }

std::uint64_t EditHistory::undoTick() const { return canUndo() ? steps_[index_].committedAt : 0; }
std::uint64_t EditHistory::redoTick() const { return canRedo() ? steps_[index_ + 1].undoneAt : 0; }

}  // namespace weft::editor
