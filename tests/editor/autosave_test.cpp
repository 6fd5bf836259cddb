// Unsaved work survives a crash: what write() leaves, find() offers back, until discard(); nothing is
// offered when the file on disk already holds it, and a damaged autosave is ignored.
#include "editor/autosave.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

// An opened document with one unsaved edit.
JsonDocument editedDocument(const fs::path& file, const std::string& newName) {
  JsonDocument doc = JsonDocument::open(file);
  json next = doc.json();
  next["name"] = newName;
  doc.history().commit(next, "Rename");
  return doc;
}

TEST(Autosave, WriteThenFindOffersTheUnsavedWork) {
  const TempDir dir;
  const fs::path file = dir.write("scenes/hanging.json", R"({"name": "hanging"})");
  Autosave autosave(dir.path() / "autosave");
  const JsonDocument doc = editedDocument(file, "hanging, edited");

  autosave.write(doc);
  const std::optional<Recovery> found = autosave.find(file);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->document, doc.json());
  EXPECT_EQ(found->original, fs::canonical(file));
  EXPECT_TRUE(fs::exists(found->autosaveFile));
  EXPECT_EQ(found->autosaveFile.parent_path(), dir.path() / "autosave");
  EXPECT_EQ(found->savedAt.size(), std::string("2024-05-01T12:00:00Z").size()) << found->savedAt;
  EXPECT_EQ(found->savedAt.back(), 'Z');
}

TEST(Autosave, FindsNothingWhenThereIsNone) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  const Autosave autosave(dir.path() / "never-written");
  EXPECT_FALSE(autosave.find(file).has_value());
  EXPECT_TRUE(autosave.all().empty());
}

TEST(Autosave, DiscardRemovesIt) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(file, "b"));
  ASSERT_TRUE(autosave.find(file).has_value());
  autosave.discard(file);
  EXPECT_FALSE(autosave.find(file).has_value());
  EXPECT_TRUE(fs::is_empty(dir.path() / "autosave"));
  autosave.discard(file);  // nothing there: no error
}

TEST(Autosave, DoesNotWriteACleanDocumentAndRemovesItsOldAutosave) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  JsonDocument doc = editedDocument(file, "b");
  autosave.write(doc);
  ASSERT_TRUE(autosave.find(file).has_value());

  doc.history().undo();  // back to what the file holds
  autosave.write(doc);
  EXPECT_FALSE(fs::exists(autosave.fileFor(file)));

  autosave.write(JsonDocument::open(file));
  EXPECT_FALSE(fs::exists(autosave.fileFor(file)));
}

TEST(Autosave, TheSameStemInDifferentFoldersDoesNotCollide) {
  const TempDir dir;
  const fs::path first = dir.write("left/sheet.json", R"({"name": "left"})");
  const fs::path second = dir.write("right/sheet.json", R"({"name": "right"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(first, "left, edited"));
  autosave.write(editedDocument(second, "right, edited"));

  EXPECT_NE(autosave.fileFor(first), autosave.fileFor(second));
  EXPECT_EQ(autosave.fileFor(first).filename().string().rfind("sheet-", 0), 0u) << "the stem names it for people";
  const auto left = autosave.find(first);
  const auto right = autosave.find(second);
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->document["name"], "left, edited");
  EXPECT_EQ(right->document["name"], "right, edited");
  EXPECT_EQ(autosave.all().size(), 2u);
}

TEST(Autosave, TwoSpellingsOfOnePathShareOneAutosave) {
  const TempDir dir;
  const fs::path file = dir.write("scenes/a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(file, "b"));
  EXPECT_TRUE(autosave.find(dir.path() / "scenes" / ".." / "scenes" / "a.json").has_value());
}

TEST(Autosave, NotFoundWhenTheFileOnDiskEqualsTheAutosave) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  JsonDocument doc = editedDocument(file, "b");
  autosave.write(doc);
  doc.save();  // saved, but the editor died before discard()
  EXPECT_FALSE(autosave.find(file).has_value());
  EXPECT_TRUE(autosave.all().empty());
}

TEST(Autosave, FoundWhenTheOriginalIsGone) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(file, "b"));
  fs::remove(file);
  EXPECT_TRUE(autosave.find(file).has_value());
}

TEST(Autosave, ACorruptAutosaveIsIgnored) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(file, "b"));
  ASSERT_TRUE(autosave.find(file).has_value());

  for (const std::string& corrupt :
       {std::string("{\"weftAutosave\": 1, \"original\": \"trunc"), std::string("\0\0\0\0", 4), std::string("[1, 2]"),
        json{{"weftAutosave", 1}, {"original", 7}, {"savedAt", "x"}, {"document", {}}}.dump(),
        json{{"weftAutosave", 99}, {"original", fs::canonical(file).string()}, {"savedAt", "x"}, {"document", {}}}.dump()}) {
    std::ofstream(autosave.fileFor(file), std::ios::binary | std::ios::trunc) << corrupt;
    EXPECT_FALSE(autosave.find(file).has_value()) << corrupt;
    EXPECT_TRUE(autosave.all().empty()) << corrupt;
  }
}

TEST(Autosave, AnAutosaveOfAnotherFileUnderThisNameIsIgnored) {
  const TempDir dir;
  const fs::path a = dir.write("a.json", R"({"name": "a"})");
  const fs::path b = dir.write("b.json", R"({"name": "b"})");
  Autosave autosave(dir.path() / "autosave");
  autosave.write(editedDocument(b, "b, edited"));
  fs::copy_file(autosave.fileFor(b), autosave.fileFor(a));
  EXPECT_FALSE(autosave.find(a).has_value());
}

TEST(Autosave, AnUntitledDocumentAutosavesUnderUntitled) {
  const TempDir dir;
  Autosave autosave(dir.path() / "autosave");
  JsonDocument doc(json{{"name", "new"}}, "");
  doc.history().commit({{"name", "new, edited"}}, "Rename");
  autosave.write(doc);
  EXPECT_EQ(autosave.fileFor("").filename().string().rfind("untitled", 0), 0u);
  const auto found = autosave.find("");
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(found->original.empty());
  EXPECT_EQ(found->document["name"], "new, edited");
}

TEST(Autosave, DefaultDirectoryFollowsTheEnvironment) {
  // Restores the variables it changes, so the other tests see the environment they started with.
  struct SavedVariable {
    const char* name;
    std::optional<std::string> value;
    explicit SavedVariable(const char* n) : name(n) {
      if (const char* v = std::getenv(n)) value = v;
    }
    ~SavedVariable() { value ? setenv(name, value->c_str(), 1) : unsetenv(name); }
  };
  const SavedVariable weft("WEFT_AUTOSAVE_DIR"), xdg("XDG_STATE_HOME"), home("HOME");

  setenv("WEFT_AUTOSAVE_DIR", "/tmp/weft-here", 1);
  setenv("XDG_STATE_HOME", "/xdg", 1);
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(Autosave::defaultDirectory(), fs::path("/tmp/weft-here"));
  unsetenv("WEFT_AUTOSAVE_DIR");
  EXPECT_EQ(Autosave::defaultDirectory(), fs::path("/xdg/weft/autosave"));
  setenv("XDG_STATE_HOME", "", 1);
  EXPECT_EQ(Autosave::defaultDirectory(), fs::path("/home/someone/.local/state/weft/autosave"));
}

}  // namespace
}  // namespace weft::editor

// A scene with no unsaved edit of its own but a tool's unsaved sharp tags is autosaved, and the
// tags come back with it; once the tags file holds them (saved), nothing is offered.
namespace weft::editor {
namespace {

TEST(Autosave, AToolsUnsavedTagsAloneAreKeptAndOfferedUntilTheirFileHoldsThem) {
  const TempDir dir;
  const fs::path file = dir.write("scenes/tools.json", R"({"name": "tools"})");
  const fs::path tagsFile = dir.path() / "scenes" / "sword.sharp.json";
  Autosave autosave(dir.path() / "autosave");
  const JsonDocument clean = JsonDocument::open(file);
  const json tags = {{"sharp_edges", json::array({json::array({0, 1})})}, {"sharp_vertices", json::array({3})}};
  autosave.write(clean, {UnsavedToolTags{0, "sword", tagsFile, false, tags},
                         UnsavedToolTags{1, "hammer", {}, true, json{{"sharp_edges", json::array()}, {"sharp_vertices", json::array()}}}});

  std::optional<Recovery> found = autosave.find(file);
  ASSERT_TRUE(found.has_value()) << "unsaved tags alone are unsaved work";
  ASSERT_EQ(found->toolTags.size(), 2u);
  EXPECT_EQ(found->toolTags[0].obstacle, 0);
  EXPECT_EQ(found->toolTags[0].tool, "sword");
  EXPECT_EQ(found->toolTags[0].file, fs::weakly_canonical(tagsFile));
  EXPECT_FALSE(found->toolTags[0].inScene);
  EXPECT_EQ(found->toolTags[0].tags, tags);
  EXPECT_TRUE(found->toolTags[1].inScene);
  EXPECT_EQ(autosave.all().size(), 1u);

  // Only the sword's, saved since: its file holds them, so nothing is left to offer.
  autosave.write(clean, {UnsavedToolTags{0, "sword", tagsFile, false, tags}});
  std::ofstream(tagsFile) << tags.dump();
  EXPECT_FALSE(autosave.find(file).has_value());

  // With nothing unsaved at all, a write removes the autosave.
  autosave.write(clean);
  EXPECT_FALSE(fs::exists(autosave.fileFor(file)));
}

TEST(Autosave, AnAutosaveWithoutToolTagsIsReadWithNone) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  Autosave autosave(dir.path() / "autosave");
  const json older = {{"weftAutosave", 1}, {"original", fs::weakly_canonical(file).string()},
                      {"savedAt", "2024-05-01T12:00:00Z"}, {"document", {{"name", "a, edited"}}}};
  fs::create_directories(autosave.directory());
  std::ofstream(autosave.fileFor(file)) << older.dump();
  const std::optional<Recovery> found = autosave.find(file);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(found->toolTags.empty());
}

}  // namespace
}  // namespace weft::editor
