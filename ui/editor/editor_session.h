#pragma once
// What the editor edits and runs: the scene file as a JSON document with its undo history, the
// scene parsed from it, and the world simulating it. Panels change the document through edit();
// the session validates the result with the same strict reader `weft run` uses, then applies it
// to the running world live where that is meaningful, or says that a reset is needed. No GL and
// no ImGui here, so the whole editing model is tested without a window.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/json_document.h"
#include "editor/playback_meter.h"
#include "scene/scene.h"
#include "sim/world.h"

namespace weft::editor {

struct EditResult {
  bool accepted = false;
  std::string message;  // why an edit was refused (the reader's message, naming the field)
};

// The last edit the strict reader refused, kept until the next edit (accepted, undo or redo) so
// the panel can show it beside the field the user typed into, and the status bar can keep it.
struct Refusal {
  std::string label;    // the edit's label, which names the field ("time step", "area density")
  std::string message;  // the reader's message
};

class EditorSession {
 public:
  // Opens the scene file. Throws InputError naming the file and field when it is bad.
  explicit EditorSession(const std::filesystem::path& sceneFile);
  // Starts from a document recovered from an autosave (the file stays as it is until saved).
  EditorSession(const std::filesystem::path& sceneFile, nlohmann::json recovered);

  const JsonDocument& document() const { return document_; }
  const nlohmann::json& json() const { return document_.json(); }
  const Scene& scene() const { return scene_; }  // the document, parsed
  const World& world() const { return *world_; }
  World& world() { return *world_; }

  // Validates `next`; when it parses, it becomes the document (one undo step, merged with the
  // previous one while `mergeKey` repeats, as a slider drag does) and is applied to the world.
  EditResult edit(nlohmann::json next, const std::string& label, const std::string& mergeKey = "");
  void endMerge() { document_.history().endMerge(); }
  void undo();
  void redo();

  // An applied edit changed what only a rebuild can change (mesh, pins, obstacles...): the world
  // runs the old setup until reset().
  bool resetPending() const { return resetPending_; }
  // Rebuilds the world from the document, back to time 0.
  void reset();
  // Counts the worlds built: views holding world-side state (a tool's unsaved tags) re-apply it
  // when this changes.
  int worldGeneration() const { return worldGeneration_; }

  // Playback in real time: a displayed frame that lasted `wallSeconds` advances the simulation by
  // speed * wallSeconds (whole steps; the fraction of a step carries over), unless paused or
  // stopped on a non-finite state. A frame owes at most kMaxFrameSeconds of wall time, and steps
  // stop once they took kStepBudgetSeconds in a frame (after at least one): a heavy scene falls
  // behind the target speed (the meter says by how much) while the window keeps answering,
  // instead of taking ever longer frames to catch up.
  bool paused = false;
  double speed = 1.0;
  static constexpr double kMaxFrameSeconds = 0.1;
  static constexpr double kStepBudgetSeconds = 0.05;
  void advanceFrame(double wallSeconds);
  void stepOnce();
  bool stopped() const { return stopped_; }
  const PlaybackMeter& meter() const { return meter_; }

  void save();                                   // atomic, keeping the previous file as FILE.bak
  void saveAs(const std::filesystem::path& file);
  bool dirty() const { return document_.dirty(); }

  // Writes the autosave when there are unsaved edits (the editor calls it every few seconds).
  void autosave(Autosave& store) const { store.write(document_); }

  std::string status;  // the last message for the status bar: what was applied, refused or needs a reset
  // The last refused edit, until the next edit; none after an accepted one.
  const std::optional<Refusal>& refusal() const { return refusal_; }

 private:
  void applyDocument(const std::string& label);
  void rebuildWorld();
  void advance(long long steps, double budgetSeconds);

  JsonDocument document_;
  Scene scene_;
  std::unique_ptr<World> world_;
  bool resetPending_ = false;
  std::optional<Refusal> refusal_;
  int worldGeneration_ = 0;
  bool stopped_ = false;
  double pendingSteps_ = 0.0;  // the fraction of a step owed at slow speeds
  PlaybackMeter meter_;
};

}  // namespace weft::editor
