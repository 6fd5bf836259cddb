#pragma once
// Sharp tags of a tool, edited in the editor (thesis Figure 3.3: the sharp parts of a tool cut).
// The tags live in a JSON file beside the tool's mesh (core/rigid/sharp_tags.h); the editor keeps
// that file as its own document, whose undo steps are ordered with the scene's (one Ctrl+Z for both:
// shared_undo.h), and applies each change to the running world at once, so the red highlights and
// the cutting records follow the clicks.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/json_document.h"
#include "collision/collision_mesh.h"
#include "rigid/sharp_tags.h"
#include "util/types.h"

namespace weft::editor {

// Pure edits, in canonical form (sorted, no repeats; an edge as {a, b} with a < b).
SharpTags withVertexToggled(SharpTags tags, int vertex);
SharpTags withEdgeToggled(SharpTags tags, std::array<int, 2> edge);
// The edges where the mesh's two faces meet at more than `degrees` (the angle between their
// normals): a blade's edge and tip, not its flat sides. An edge with one face (an open border) is
// included; `vertices` are the mesh's positions in any fixed frame.
std::vector<std::array<int, 2>> edgesSharperThan(const CollisionMesh& mesh, const std::vector<Vec3>& vertices,
                                                 double degrees);
SharpTags withEdgesTagged(SharpTags tags, const std::vector<std::array<int, 2>>& edges);
nlohmann::json sharpTagsJson(const SharpTags& tags);     // the file's format
SharpTags sharpTagsFromJson(const nlohmann::json& json);  // of what sharpTagsJson wrote

// The tags file of a scene obstacle: its "sharp_tags" file, or NAME.sharp.json beside its mesh;
// none for a generated shape (sphere, box...), which has no file to keep tags beside.
std::optional<std::filesystem::path> sharpTagsFileOf(const ObstacleSpec& spec);

class ToolTagEditor {
 public:
  // The tags of obstacle `obstacle` of the session's scene, read from its tags file (empty when
  // the file does not exist yet). Throws std::invalid_argument for an obstacle without a mesh file.
  ToolTagEditor(const EditorSession& session, int obstacle);

  int obstacle() const { return obstacle_; }
  const std::string& name() const { return name_; }  // the obstacle's, as the scene names it
  SharpTags tags() const { return sharpTagsFromJson(document_.json()); }
  const JsonDocument& document() const { return document_; }

  void toggleVertex(EditorSession& session, int vertex);
  void toggleEdge(EditorSession& session, std::array<int, 2> edge);
  // Tags every edge sharper than `degrees` (edgesSharperThan), as one undo step. Returns how many
  // edges were newly tagged.
  int tagEdgesSharperThan(EditorSession& session, double degrees);
  // Tags `edges` sharp (a box select), as one undo step labelled `label`. Returns how many were
  // newly tagged.
  int tagEdges(EditorSession& session, const std::vector<std::array<int, 2>>& edges, const std::string& label);
  // This document's own step back or forward (no-op when none); the status names the tool. The
  // editor's Undo and Redo go through shared_undo.h, which calls these when the tags hold the
  // latest step.
  void undo(EditorSession& session);
  void redo(EditorSession& session);
  void save() { document_.save(); }  // atomic, FILE.bak kept
  // Tags are per obstacle: two obstacles of one scene on one mesh read one tags file, and saving
  // one's tags there would change the other's unseen. So the tool's own file is written only when
  // no other obstacle of the scene reads it; else the tags go beside the scene in a file of this
  // obstacle's own, SCENE.OBSTACLE.sharp.json, and the scene points there (a scene edit, saved
  // with the scene). Returns the file written.
  std::filesystem::path saveToToolFile(EditorSession& session);
  // The name of another obstacle of the scene that reads this tool's tags file (none: no other).
  std::optional<std::string> tagsFileSharedWith(const EditorSession& session) const;
  // The file saveToToolFile would write now: the tool's tags file, or this obstacle's own beside
  // the scene when another obstacle reads that one.
  std::filesystem::path toolFileTarget(const EditorSession& session) const;
  // The file saveBesideScene would write now.
  std::filesystem::path besideSceneTarget(const EditorSession& session) const;
  // Saves the tags beside the scene instead (SCENE_FOLDER/MESH.sharp.json, or
  // SCENE.OBSTACLE.sharp.json when another obstacle of the scene reads that one) and points the
  // scene's obstacle at that file ("sharp_tags"), so a shipped tool's file is left alone and other
  // scenes and obstacles using the tool are not changed. Returns the file written.
  std::filesystem::path saveBesideScene(EditorSession& session);
  // Recovered from an autosave (autosave.h): `tags` (sharpTagsJson's format) become the tool's,
  // one undo step, unsaved. Throws std::invalid_argument (nothing changes) when they name a vertex
  // the mesh does not have, or are not tags at all.
  void recover(EditorSession& session, const nlohmann::json& tags);
  // Keeps the tags in the scene itself ("sharp_tags": {...} in the obstacle's mesh), as one
  // scene edit (saved with the scene): no file beside the mesh or the scene is written.
  void saveInScene(EditorSession& session);
  // The tags live in the scene (opened so, or saved there): Save tags edits the scene.
  bool inScene() const { return inScene_; }
  // Whether save() would write into Weft's installed assets (a shipped tool's tags).
  bool savesIntoInstalledData() const;
  // After the world was rebuilt (a reset): its obstacle has the file's tags again; puts the
  // document's (possibly unsaved) ones back. False when the obstacle at this index is no longer
  // the tool (it was removed from the scene): nothing is applied.
  bool reapply(EditorSession& session) const;

 private:
  void commit(EditorSession& session, const SharpTags& tags, const std::string& label);
  // SCENE.OBSTACLE.sharp.json (the obstacle's name made safe for a file name), a file no other
  // obstacle of the scene reads.
  std::filesystem::path ownFileName(const EditorSession& session) const;
  std::filesystem::path saveBesideSceneAs(EditorSession& session, const std::filesystem::path& name);
  void applyToWorld(EditorSession& session) const;

  friend class ToolTagEditors;  // follows the obstacle when others before it come and go
  int obstacle_;
  std::string name_;  // the obstacle's name, to notice it gone after a reset
  JsonDocument document_;
  bool inScene_ = false;
};

}  // namespace weft::editor
