#pragma once
// The editor's panels, one function each (one file each). A panel reads the session's parsed
// scene and world, and changes only the scene document, through EditorSession::edit with the
// pure edits of scene_edits.h: never the solver's internals.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <imgui.h>

#include "editor/editor_session.h"
#include "editor/editor_settings.h"
#include "editor/headless_recorder.h"
#include "editor/sharp_tag_edits.h"
#include "editor/tool_tag_editors.h"

namespace weft::editor {

class SceneBrowser;

// Where each named widget was last drawn, for tests that drive the panels with simulated input
// (ImGui 1.86 has no test engine). Panels record into it only when the state carries one.
struct WidgetProbe {
  std::map<std::string, ImVec4> rects;  // id -> (min x, min y, max x, max y) in pixels
  std::map<std::string, std::string> texts;  // id -> the text drawn (what a dialog says)
  ImVec2 centre(const std::string& id) const {
    const ImVec4& r = rects.at(id);
    return ImVec2(0.5f * (r.x + r.z), 0.5f * (r.y + r.w));
  }
};

struct PanelState {
  int cloth = 0;                 // the cloth the material, tear table and weft panels edit
  int obstacle = -1;             // the obstacle selected in the scene panel (-1: none)
  char saveAsPath[256] = "";     // the scene panel's "save as" file
  char openPath[256] = "";       // the scene panel's "open" file
  WidgetProbe* probe = nullptr;  // tests only
  char newPresetName[64] = "";   // the material panel's "save as preset" name
  char presetFolder[512] = "";   // ... and folder, filled from settings when its dialog opens
  bool presetDialog = false;     // the "save as preset" dialog is open
  bool writeInstalled = false;   // the user agreed to write into Weft's installed presets/assets
  EditorSettings settings;       // remembered between runs (the app loads and saves them)
  bool tagsDialog = false;       // the tools panel asks where the tags of a shipped tool go
  double sharperThanDeg = 60.0;  // the tools panel's "tag edges sharper than" angle
  ToolTagEditors tools;               // the tools' sharp tags; current() is the one the tools panel edits
  bool tagMode = false;               // clicks on the tool in the viewport toggle sharp tags
  bool paintMode = false;             // a left drag on a cloth paints its tear strength (material panel)
  StrengthBrush brush;                // the material panel's tear strength brush
  bool throwBallRequested = false;    // the app throws one from the camera this frame
  HeadlessRecorder* recorder = nullptr;  // playback's "record" (owned by the app; none: no recording)
  int recordFrames = 120;
  bool recordVideo = true;
  std::filesystem::path openRequest;  // a scene the user chose to open (the editor asks about unsaved edits first)
  SceneBrowser* browser = nullptr;    // the browser's scenes and thumbnails (owned by the app; none: no browser)
  bool browserOpen = false;           // File > Browse scenes and presets
  bool saveAsRequested = false;       // Save on a shipped scene: the "Save scene as" dialog opens
};

// Save (the Scene panel's button, File > Save, Ctrl+S). A scene shipped with Weft is not written
// over: the "Save scene as" dialog opens instead, a copy in ~/weft/scenes suggested.
void saveScene(EditorSession& session, PanelState& state);

// Records the last drawn item under `id` when a probe is attached.
void recordWidget(PanelState& state, const std::string& id);
// Draws `text` wrapped and records it under `id` when a probe is attached.
void wrappedText(PanelState& state, const std::string& id, const std::string& text);

// A number the user types: selected whole on click, taken when Enter is pressed, and only when
// finite. True when a new value is in `value` (each panel still checks its own range).
bool numberField(const char* label, double& value, const char* format, float width);

// Under the field just drawn, in red: the reader's message when the last refused edit was the one
// labelled `label` (until the next edit). Every field that can be refused calls it. True when shown.
bool showRefusal(const EditorSession& session, const std::string& label);
extern const ImVec4 kRefusedColour;

void drawScenePanel(EditorSession& session, PanelState& state);
void drawMaterialPanel(EditorSession& session, PanelState& state);
// The Material panel's "Paint tear strength" section (strength_brush_section.cpp): the mode, the
// brush's radius, strength and erase, what the picked cloth's map holds.
void drawStrengthBrushSection(EditorSession& session, PanelState& state);
void drawTearTablePanel(EditorSession& session, PanelState& state);
void drawWeftPanel(EditorSession& session, PanelState& state);
void drawSolverPanel(EditorSession& session, PanelState& state);
void drawPlaybackPanel(EditorSession& session, PanelState& state);
void drawToolsPanel(EditorSession& session, PanelState& state);
void drawBrowserPanel(EditorSession& session, PanelState& state);

}  // namespace weft::editor
