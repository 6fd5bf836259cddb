// Saving never loses work: the previous file is kept as .bak, and a save that dies before its rename
// leaves the old file byte for byte and no .tmp behind.
#include "editor/json_document.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/temp_dir.h"
#include "util/input_error.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path withSuffix(fs::path file, const char* suffix) { return file += suffix; }

// Runs `open` and returns the InputError's message; fails the test when nothing is thrown.
std::string openError(const fs::path& file) {
  try {
    JsonDocument::open(file);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << file;
  return "";
}

TEST(JsonDocument, OpensAFileAsItsCleanInitialState) {
  const TempDir dir;
  const fs::path file = dir.write("cotton.json", R"({"name": "cotton", "density": 0.2})");
  const JsonDocument doc = JsonDocument::open(file);
  EXPECT_EQ(doc.file(), file);
  EXPECT_EQ(doc.json(), (json{{"name", "cotton"}, {"density", 0.2}}));
  EXPECT_FALSE(doc.dirty());
  EXPECT_FALSE(doc.history().canUndo());
}

TEST(JsonDocument, OpenNamesAMissingFile) {
  const TempDir dir;
  const std::string what = openError(dir.path() / "missing.json");
  EXPECT_NE(what.find("missing.json"), std::string::npos) << what;
}

TEST(JsonDocument, OpenNamesTheFileLineAndColumnOfInvalidJson) {
  const TempDir dir;
  const fs::path file = dir.write("broken.json", "{\n  \"name\": \"cotton\",\n  \"density\": ,\n}\n");
  const std::string what = openError(file);
  EXPECT_NE(what.find("broken.json"), std::string::npos) << what;
  EXPECT_NE(what.find("line 3"), std::string::npos) << what;
  EXPECT_NE(what.find("column"), std::string::npos) << what;
}

TEST(JsonDocument, OpenRefusesCommentsThatSavingWouldDrop) {
  const TempDir dir;
  const fs::path file = dir.write("commented.json", "{\n  // why this density\n  \"density\": 0.2\n}\n");
  const std::string what = openError(file);
  EXPECT_NE(what.find("comments"), std::string::npos) << what;
}

// As `weft run` does (issue 19): a key written twice is refused, not read as its last value, and
// the message names the file and the key's place; so is nesting deeper than any of our formats.
TEST(JsonDocument, OpenRefusesWhatTheHeadlessReaderRefuses) {
  const TempDir dir;
  const fs::path twice = dir.write("twice.json", "{\n  \"solver\": {\"dt\": 0.01, \"dt\": 0.02}\n}\n");
  const std::string what = openError(twice);
  EXPECT_NE(what.find("twice.json"), std::string::npos) << what;
  EXPECT_NE(what.find("duplicate key \"dt\""), std::string::npos) << what;
  EXPECT_NE(what.find("/solver"), std::string::npos) << what;

  const fs::path deep = dir.write("deep.json", std::string(200, '[') + std::string(200, ']'));
  const std::string tooDeep = openError(deep);
  EXPECT_NE(tooDeep.find("deep.json"), std::string::npos) << tooDeep;
  EXPECT_NE(tooDeep.find("deep"), std::string::npos) << tooDeep;
}

TEST(JsonDocument, SaveWritesPrettyJsonAndKeepsThePreviousFileAsBak) {
  const TempDir dir;
  const std::string original = R"({"density":0.2,"name":"cotton"})";
  const fs::path file = dir.write("cotton.json", original);
  JsonDocument doc = JsonDocument::open(file);
  doc.history().commit({{"density", 0.3}, {"name", "cotton"}}, "Set density");
  ASSERT_TRUE(doc.dirty());

  doc.save();
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(readBytes(file), "{\n  \"density\": 0.3,\n  \"name\": \"cotton\"\n}\n");
  EXPECT_EQ(readBytes(withSuffix(file, ".bak")), original);
  EXPECT_FALSE(fs::exists(withSuffix(file, ".tmp")));
  EXPECT_EQ(JsonDocument::open(file).json(), doc.json());

  doc.history().commit({{"density", 0.4}, {"name", "cotton"}}, "Set density");
  doc.save();
  EXPECT_EQ(json::parse(readBytes(withSuffix(file, ".bak")))["density"], 0.3) << ".bak is the version just replaced";
}

TEST(JsonDocument, SaveAsWritesTheNewFileAndMakesItTheDocumentsFile) {
  const TempDir dir;
  const fs::path first = dir.write("a.json", R"({"name": "a"})");
  JsonDocument doc = JsonDocument::open(first);
  doc.history().commit({{"name", "b"}}, "Rename");
  const fs::path second = dir.path() / "b.json";

  doc.saveAs(second);
  EXPECT_EQ(doc.file(), second);
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(json::parse(readBytes(second)), (json{{"name", "b"}}));
  EXPECT_EQ(json::parse(readBytes(first)), (json{{"name", "a"}})) << "the old file is left alone";
  EXPECT_FALSE(fs::exists(withSuffix(second, ".bak"))) << "nothing was there to keep";
}

TEST(JsonDocument, AnUntitledDocumentSavesOnlyThroughSaveAs) {
  const TempDir dir;
  JsonDocument doc(json{{"name", "new"}}, "");
  doc.history().commit({{"name", "newer"}}, "Rename");
  EXPECT_THROW(doc.save(), std::runtime_error);
  EXPECT_TRUE(doc.dirty());
  doc.saveAs(dir.path() / "new.json");
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(json::parse(readBytes(dir.path() / "new.json"))["name"], "newer");
}

TEST(JsonDocument, AnInterruptedSaveLeavesTheOldFileByteIdenticalAndNoTmp) {
  const TempDir dir;
  const std::string original = "{ \"name\":\"cotton\",\n\"density\": 0.2 }  ";  // not as save() would write it
  const fs::path file = dir.write("cotton.json", original);
  JsonDocument doc = JsonDocument::open(file);
  doc.history().commit({{"name", "cotton"}, {"density", 0.3}}, "Set density");

  bool tmpWasComplete = false;
  try {
    doc.save([&] {
      tmpWasComplete = json::parse(readBytes(withSuffix(file, ".tmp")))["density"] == 0.3;
      throw std::runtime_error("power cut");
    });
    ADD_FAILURE() << "the interrupted save did not throw";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("power cut"), std::string::npos) << what;
  }
  EXPECT_TRUE(tmpWasComplete) << "the hook runs once the .tmp is written";
  EXPECT_EQ(readBytes(file), original);
  EXPECT_FALSE(fs::exists(withSuffix(file, ".tmp")));
  EXPECT_TRUE(doc.dirty()) << "nothing was saved";
}

TEST(JsonDocument, ASaveThatCannotKeepTheBakFailsAndLeavesTheFileAlone) {
  const TempDir dir;
  const std::string original = R"({"name": "cotton"})";
  const fs::path file = dir.write("cotton.json", original);
  fs::create_directories(withSuffix(file, ".bak") / "in-the-way");
  JsonDocument doc = JsonDocument::open(file);
  doc.history().commit({{"name", "denim"}}, "Rename");

  EXPECT_THROW(doc.save(), std::runtime_error);
  EXPECT_EQ(readBytes(file), original);
  EXPECT_FALSE(fs::exists(withSuffix(file, ".tmp")));
  EXPECT_TRUE(doc.dirty());
}

TEST(JsonDocument, AFailedSaveAsKeepsTheOldFile) {
  const TempDir dir;
  const fs::path file = dir.write("a.json", R"({"name": "a"})");
  JsonDocument doc = JsonDocument::open(file);
  doc.history().commit({{"name", "b"}}, "Rename");
  EXPECT_THROW(doc.saveAs(dir.path() / "no-such-folder" / "b.json"), std::runtime_error);
  EXPECT_EQ(doc.file(), file);
  EXPECT_TRUE(doc.dirty());
}

}  // namespace
}  // namespace weft::editor
