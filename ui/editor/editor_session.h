#pragma once
// What the editor edits and runs: the scene file as a JSON document with its undo history, the
// scene parsed from it, and the world simulating it. Panels change the document through edit();
// the session validates the result with the same strict reader `weft run` uses, then applies it
// to the running world live where that is meaningful, or says that a reset is needed. No GL and
// no ImGui here, so the whole editing model is tested without a window.
//
// The world steps on a worker thread (step_worker.h). The window and the panels read view(), a
// snapshot taken after every step; changes to the running world go through applyToWorld(), which
// the worker carries out between steps. world() waits for the steps asked so far to finish, so
// code (and tests) that read the world itself see every step they asked for.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/frame_cache.h"
#include "editor/json_document.h"
#include "editor/playback_meter.h"
#include "editor/step_worker.h"
#include "editor/strength_painting.h"
#include "editor/world_snapshot.h"
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

// The solver threads the editor steps with for a scene asking for `requested`: at most the
// machine's hardware threads less one (and at least one). The editor draws on the same cores (with
// software GL, llvmpipe renders on all of them), and solver threads without a core of their own
// keep each other waiting: measured on 2 cores under Xvfb, a 64² sheet with 2 solver threads
// advanced 28 steps in 240 drawn frames, against 423 with 1. Results do not depend on the count.
int editorSolverThreads(int requested);

class EditorSession {
 public:
  // Opens the scene file. Throws InputError naming the file and field when it is bad.
  explicit EditorSession(const std::filesystem::path& sceneFile);
  // Starts from a document recovered from an autosave (the file stays as it is until saved).
  EditorSession(const std::filesystem::path& sceneFile, nlohmann::json recovered);

  const JsonDocument& document() const { return document_; }
  const nlohmann::json& json() const { return document_.json(); }
  const Scene& scene() const { return scene_; }  // the document, parsed
  ~EditorSession();
  EditorSession(const EditorSession&) = delete;
  EditorSession& operator=(const EditorSession&) = delete;

  // The world once the steps asked so far are done (waits for them): for a tool's tags, a reset,
  // tests. The per-frame readers use view().
  const World& world() const;
  World& world();
  // The world after the step in flight, without waiting for the other owed steps; they wait
  // until the next frame (advanceFrame). For picking on a click; changes go through applyToWorld.
  const World& worldBetweenSteps();
  // What the window draws, without waiting: the world as of the latest step or change, or the
  // cached frame the timeline shows.
  std::shared_ptr<const WorldSnapshot> view() const;
  // Changes the running world between steps: at once when no step runs, else queued for the
  // worker. Looking at an earlier frame of the timeline, the simulation first goes back there:
  // the frames after it are dropped and it continues from it with the change.
  void applyToWorld(WorldChange change);
  void applyToWorld(std::function<void(World&)> change) { applyToWorld(WorldChange{std::move(change), {}, 0}); }

  // The timeline: output frames simulated since the last reset, cached (frame_cache.h).
  // Its budget counts the worker's change log too (step_worker.h).
  const FrameCache& frames() const { return frames_; }
  void setTimelineBudget(std::size_t bytes) { frames_.setBudget(bytes); }
  // The last time an edit went back to an earlier frame: the frame, and the frame whose kept
  // world was copied and stepped forward to it (the same frame when it kept its own).
  struct Resume {
    long long frame = 0;
    long long from = 0;
  };
  const std::optional<Resume>& lastResume() const { return lastResume_; }
  std::size_t loggedChanges() const { return worker_->loggedChanges(); }  // the changes a resume may replay
  long long stepsPerFrame() const { return frameSteps_; }
  // The frame the world is at (whole frames of steps, as far as the worker got).
  long long liveFrame() const;
  // Shows cached frame `frame` (the nearest cached one) instead of the live world, and pauses;
  // the newest frame, when the world is at it, is the live world again.
  void showFrame(long long frame);
  void showLive() { shownFrame_.reset(); }
  std::optional<long long> shownFrame() const { return shownFrame_; }
  // A batch of steps is running on the worker.
  bool stepping() const { return worker_->busy(); }

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

  // Playback in real time: a displayed frame that lasted `wallSeconds` asks the worker for
  // speed * wallSeconds of simulation (whole steps; the fraction of a step carries over), unless
  // paused or stopped on a non-finite state. Returns at once: the steps run on the worker. A
  // frame owes at most kMaxFrameSeconds of wall time, and the worker is never owed more than
  // that much simulation: a heavy scene falls behind the target speed (the meter says by how
  // much; the meter counts what the worker finished) instead of owing ever more steps.
  bool paused = false;
  double speed = 1.0;
  static constexpr double kMaxFrameSeconds = 0.1;
  void advanceFrame(double wallSeconds);
  void stepOnce();  // one step, on the worker, after the batch in flight
  bool stopped() const { return stopped_; }
  // The health check's first failure since the last reset (the warning `weft run` prints);
  // playback goes on, as `weft run --keep-going` does.
  const std::optional<HealthFailure>& unhealthy() const { return unhealthy_; }
  const PlaybackMeter& meter() const { return meter_; }

  // Atomic, keeping the previous file as FILE.bak. A scene shipped with Weft (installed_data.h)
  // is not overwritten by a plain save: it throws, saying to save a copy (Save as, which may
  // name the shipped file itself: the user said so).
  void save();
  void saveAs(const std::filesystem::path& file);  // creates the folder when missing
  bool savesIntoInstalledData() const;             // a plain save() would write a shipped scene
  bool dirty() const { return document_.dirty() || !unsavedStrengthMaps().empty(); }

  // Writes the autosave when there are unsaved edits, the scene's, its tools' sharp tags or its
  // painted strength maps (those as PNGs beside the autosave, which the autosaved scene names; the
  // editor calls it every few seconds).
  void autosave(Autosave& store, const std::vector<UnsavedToolTags>& toolTags = {}) const;

  // --- The tear strength brush (strength_painting.h; these are in session_strength_maps.cpp) ---
  // Cloth `cloth`'s painting, made on first use from the map the document gives it (or a new
  // white one, newStrengthMap), its strokes undo steps on the scene's edit clock. Once a stroke
  // ends (strengthPaintingChanged) its map replaces the document's in the running world, and keeps
  // doing so through later edits, their undo, resets and rewinds of the timeline.
  StrengthPainting& strengthPainting(int cloth);
  StrengthPainting* findStrengthPainting(int cloth);  // none: not painted since the scene opened
  const StrengthPainting* findStrengthPainting(int cloth) const;
  std::vector<int> paintedCloths() const;
  // The cloth's painting changed (a stroke ended, one undone or redone): the world takes its map
  // between steps.
  void strengthPaintingChanged(int cloth);
  void undoStrengthPainting(int cloth);  // its latest stroke back (shared_undo.h decides when)
  void redoStrengthPainting(int cloth);
  // The names of the cloths whose painted map is not saved (those save() writes).
  std::vector<std::string> unsavedStrengthMaps() const;

  std::string status;  // the last message for the status bar: what was applied, refused or needs a reset
  // The last refused edit, until the next edit; none after an accepted one.
  const std::optional<Refusal>& refusal() const { return refusal_; }

 private:
  void applyDocument(const std::string& label);
  void rebuildWorld();
  void collectSteps();  // the finished batch's step times and non-finite stop
  void countChangeLog();  // the worker's change log, into the timeline's budget
  Scene withPaintedMaps(Scene scene) const;  // each painted cloth's map in place of the document's
  // What the world steps: the painted maps in place, and the solver's threads capped so one core
  // stays with the editor's drawing (editorSolverThreads).
  Scene forTheWorld(const Scene& scene) const;
  // Writes the painted maps beside `sceneFile` (all, or only the unsaved ones) and points the
  // document at them (a scene edit).
  void saveStrengthMaps(const std::filesystem::path& sceneFile, bool all);

  JsonDocument document_;
  Scene scene_;
  Scene liveScene_;  // the world's scene once the queued live edits are applied (decides resets)
  std::unique_ptr<StepWorker> worker_;  // owns the world
  FrameCache frames_;
  long long frameSteps_ = 1;
  std::optional<long long> shownFrame_;  // the timeline shows this cached frame (none: live)
  std::optional<Resume> lastResume_;
  bool rewinding_ = false;               // until the worker reports the world back at the shown frame
  double frameClock_ = 0.0;              // playing through cached frames: the fraction of a frame
  bool resetPending_ = false;
  std::optional<Refusal> refusal_;
  int worldGeneration_ = 0;
  bool stopped_ = false;
  std::optional<HealthFailure> unhealthy_;
  double pendingSteps_ = 0.0;  // the fraction of a step owed at slow speeds
  double meteredTime_ = 0.0;      // simulated time the meter has counted up to
  PlaybackMeter meter_;
  std::map<int, std::unique_ptr<StrengthPainting>> paintings_;  // by cloth index
  // The paintings of cloths an edit removed, by cloth name: back with their cloth when the
  // removal is undone.
  std::vector<std::pair<std::string, std::unique_ptr<StrengthPainting>>> asidePaintings_;
  // paintings_ re-keyed from scene_'s cloths to `next`'s, by name (session_strength_maps.cpp).
  void followClothNames(const Scene& next);
};

}  // namespace weft::editor
