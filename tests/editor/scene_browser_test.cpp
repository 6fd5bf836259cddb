// The scene and preset browser (issue 21, item 8): each scene of the browsed folders with its
// description and a thumbnail of how it starts, rendered by the editor's renderer once (one a
// frame), cached under the user's cache folder by the scene file's content, read back from there
// next time, and drawn again only when the file changes. Headless (EGL), as the panel tests run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "editor/panels/preset_names.h"
#include "editor/scene_browser.h"
#include "editor/scene_listing_cache.h"
#include "editor/thumbnail_cache.h"
#include "png_reader.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;

class SceneBrowserTest : public test::EditorPanelsTest {
 protected:
  // The fixture's scene (a small ball-into-sheet) and a small hanging sheet beside it.
  fs::path folder() const { return scene_.parent_path(); }
  void addHangingSheet() { hangingSheet_ = test::copyScene(dir_, "hanging-sheet", 8); }
  static int readyCount(const SceneBrowser& browser) {
    int ready = 0;
    for (const BrowserScene& s : browser.scenes()) ready += s.thumbnail == BrowserScene::Thumbnail::Ready ? 1 : 0;
    return ready;
  }
  static void makeAll(SceneBrowser& browser, ui::SceneRenderer& renderer) {
    for (int i = 0; i < 10 && browser.makeNextThumbnail(renderer); ++i) {
    }
  }
  fs::path hangingSheet_;
};

TEST(ThumbnailCache, KeyFollowsTheFilesBytesAndTheFolderFollowsTheEnvironment) {
  test::TempDir dir;
  const fs::path a = dir.write("a.json", R"({"name": "a"})");
  const fs::path b = dir.write("b.json", R"({"name": "a"})");
  const fs::path c = dir.write("c.json", R"({"name": "c"})");
  EXPECT_EQ(ThumbnailCache::keyOf(a), ThumbnailCache::keyOf(b)) << "same bytes, same thumbnail";
  EXPECT_NE(ThumbnailCache::keyOf(a), ThumbnailCache::keyOf(c));
  EXPECT_FALSE(ThumbnailCache::keyOf(dir.path() / "missing.json"));
  EXPECT_EQ(fnv1aHex(""), "cbf29ce484222325") << "FNV-1a 64's offset basis";
  EXPECT_EQ(fnv1aHex("a"), "af63dc4c8601ec8c") << "the published test vector";
  setenv("WEFT_CACHE_DIR", dir.path().c_str(), 1);
  EXPECT_EQ(defaultThumbnailFolder(), dir.path() / "thumbnails");
  unsetenv("WEFT_CACHE_DIR");
}

// A scene that names presets looks different when a preset changes: the key covers the bytes of
// every file the scene loads, as the reader resolves them (here the scene folder's own copies of
// the material and the tear table, which come before the project's presets).
TEST(ThumbnailCache, KeyFollowsTheBytesOfThePresetsTheSceneLoads) {
  test::TempDir dir;
  const fs::path presets = fs::path(WEFT_SOURCE_DIR) / "presets";
  fs::create_directories(dir.path() / "materials");
  fs::create_directories(dir.path() / "tear_tables");
  const fs::path material = dir.path() / "materials" / "11oz-black-denim.json";
  const fs::path table = dir.path() / "tear_tables" / "karaoz2015-table4.1-cloth2.json";
  fs::copy_file(presets / "materials" / "11oz-black-denim.json", material);
  fs::copy_file(presets / "tear_tables" / "karaoz2015-table4.1-cloth2.json", table);
  fs::create_directories(dir.path() / "scenes");
  const fs::path scene = dir.path() / "scenes" / "sheet.json";
  fs::copy_file(presets / "scenes" / "ball-into-sheet-table4.1-cloth2.json", scene);

  const std::vector<fs::path> files = sceneInputFiles(scene);
  EXPECT_NE(std::find(files.begin(), files.end(), material.lexically_normal()), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), table.lexically_normal()), files.end());
  const std::optional<std::string> key = ThumbnailCache::keyOf(scene);
  ASSERT_TRUE(key);
  EXPECT_EQ(ThumbnailCache::keyOf(scene), key) << "nothing changed, same key";

  const auto rewrite = [](const fs::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << " in " << file;
    text.replace(at, from.size(), to);
    std::ofstream(file, std::ios::trunc) << text;
  };
  const std::string materialBytes = [&] {
    std::ifstream in(material);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  rewrite(material, "\"area_density_kg_m2\":", "\"area_density_kg_m2\":  ");  // same values, other bytes
  const std::optional<std::string> materialChanged = ThumbnailCache::keyOf(scene);
  EXPECT_NE(materialChanged, key) << "the material preset changed";
  std::ofstream(material, std::ios::trunc) << materialBytes;
  EXPECT_EQ(ThumbnailCache::keyOf(scene), key) << "back as it was, the old thumbnail is right again";

  rewrite(table, "\"strength\":", "\"strength\":  ");
  const std::optional<std::string> tableChanged = ThumbnailCache::keyOf(scene);
  EXPECT_NE(tableChanged, key) << "the tear table preset changed";
  EXPECT_NE(tableChanged, materialChanged);

  fs::remove(material);  // the project's preset of that name is found instead
  EXPECT_NE(ThumbnailCache::keyOf(scene), tableChanged) << "another file resolved";
}

// Opening the browser again rescans its folders without reading unchanged files again: a scene's
// description and key (which read the scene and every file it loads) and a preset's source are
// kept with the size and time of the files they came from. A changed scene, a changed file it
// loads, and a preset added to a folder it searches first are read again; nothing else is.
TEST(SceneListingCache, AnUnchangedFileIsNotReadAgainAChangedOneIs) {
  test::TempDir dir;
  const fs::path presets = fs::path(WEFT_SOURCE_DIR) / "presets";
  fs::create_directories(dir.path() / "tear_tables");
  const fs::path table = dir.path() / "tear_tables" / "karaoz2015-table4.1-cloth2.json";
  fs::copy_file(presets / "tear_tables" / "karaoz2015-table4.1-cloth2.json", table);
  fs::create_directories(dir.path() / "scenes");
  const fs::path sheet = dir.path() / "scenes" / "sheet.json";
  const fs::path hanging = dir.path() / "scenes" / "hanging.json";
  fs::copy_file(presets / "scenes" / "ball-into-sheet-table4.1-cloth2.json", sheet);
  fs::copy_file(presets / "scenes" / "hanging-sheet.json", hanging);
  const fs::path material = presets / "materials" / "11oz-black-denim.json";

  SceneListingCache cache;
  const SceneListing first = cache.scene(sheet);
  EXPECT_EQ(first.key, ThumbnailCache::keyOf(sheet).value_or("")) << "the thumbnail key, as keyOf makes it";
  EXPECT_FALSE(first.description.empty());
  (void)cache.scene(hanging);
  const std::string source = cache.presetSource(material);
  EXPECT_FALSE(source.empty());
  ASSERT_EQ(cache.reads(), 3);

  for (int reopen = 0; reopen < 3; ++reopen) {
    EXPECT_EQ(cache.scene(sheet).key, first.key);
    EXPECT_EQ(cache.scene(hanging).description, sceneDescription(hanging));
    EXPECT_EQ(cache.presetSource(material), source);
  }
  EXPECT_EQ(cache.reads(), 3) << "unchanged files are not read again";

  const auto append = [](const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::app) << text;  // other size: seen even within one clock tick
  };
  append(hanging, "\n");
  EXPECT_EQ(cache.scene(hanging).key, ThumbnailCache::keyOf(hanging).value_or(""));
  EXPECT_EQ(cache.scene(sheet).key, first.key);
  EXPECT_EQ(cache.reads(), 4) << "the changed scene, and only it, is read again";

  append(table, "\n");  // a file the sheet loads
  const SceneListing tableChanged = cache.scene(sheet);
  EXPECT_EQ(cache.reads(), 5);
  EXPECT_NE(tableChanged.key, first.key);
  EXPECT_EQ(tableChanged.key, ThumbnailCache::keyOf(sheet).value_or(""));

  fs::create_directories(dir.path() / "materials");  // a preset of the same name, found first now
  fs::copy_file(material, dir.path() / "materials" / "11oz-black-denim.json");
  append(dir.path() / "materials" / "11oz-black-denim.json", " ");
  const SceneListing shadowed = cache.scene(sheet);
  EXPECT_EQ(cache.reads(), 6) << "a folder the scene searches changed";
  EXPECT_NE(shadowed.key, tableChanged.key);
  EXPECT_EQ(shadowed.key, ThumbnailCache::keyOf(sheet).value_or(""));
}

// What size and time alone would miss (scene_listing_cache.h): a same-size edit whose old
// modification time was put back (cp -p, tar, touch -d), in place and by replacing the file as
// `git checkout` and save-by-rename editors do. Both are read again.
TEST(SceneListingCache, ASameSizeEditWithItsOldTimePutBackIsReadAgain) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "scenes");
  const fs::path scene = dir.path() / "scenes" / "sheet.json";
  fs::copy_file(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "hanging-sheet.json", scene);
  const auto described = [](const std::string& text) {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "hanging-sheet.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["description"] = text;
    return j.dump(2);
  };
  std::ofstream(scene, std::ios::trunc) << described("AAAA");
  const fs::file_time_type oldTime = fs::last_write_time(scene);
  SceneListingCache cache;
  ASSERT_EQ(cache.scene(scene).description, "AAAA");
  ASSERT_EQ(cache.reads(), 1);
  // Past the kernel's timestamp tick, as an artist's next edit always is.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));

  {  // in place: same size, old time
    std::ofstream(scene, std::ios::in | std::ios::out) << described("BBBB");
    fs::last_write_time(scene, oldTime);
  }
  ASSERT_EQ(fs::file_size(scene), described("AAAA").size());
  EXPECT_EQ(cache.scene(scene).description, "BBBB") << "an in-place same-size edit with its old time put back";
  EXPECT_EQ(cache.reads(), 2);
  EXPECT_EQ(cache.scene(scene).description, "BBBB");
  EXPECT_EQ(cache.reads(), 2) << "and then not again";

  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  {  // replaced, as git checkout does: a new file of the same size and old time renamed over it
    const fs::path temporary = dir.path() / "scenes" / "sheet.json.tmp";
    std::ofstream(temporary) << described("CCCC");
    fs::last_write_time(temporary, oldTime);
    fs::rename(temporary, scene);
  }
  EXPECT_EQ(cache.scene(scene).description, "CCCC") << "a replaced file of the same size and time";
  EXPECT_EQ(cache.reads(), 3);
}

TEST_F(SceneBrowserTest, ReopeningTheBrowserReadsOnlyTheFilesThatChanged) {
  addHangingSheet();
  SceneBrowser browser({folder()}, ThumbnailCache(dir_.path() / "cache"));
  const int listed = browser.listings().reads();
  ASSERT_GE(listed, 2) << "two scenes and the material presets";
  browser.rescan();
  browser.rescan();
  EXPECT_EQ(browser.listings().reads(), listed) << "nothing changed, nothing read";
  std::ofstream(hangingSheet_, std::ios::app) << "\n";
  browser.rescan();
  EXPECT_EQ(browser.listings().reads(), listed + 1) << "the changed scene only";
}

TEST_F(SceneBrowserTest, AThumbnailIsRenderedOnceAndCachedByTheSceneFilesContent) {
  addHangingSheet();
  const ThumbnailCache cache(dir_.path() / "cache");
  ui::SceneRenderer renderer;
  {
    SceneBrowser browser({folder()}, cache);
    ASSERT_EQ(browser.scenes().size(), 2u);
    EXPECT_EQ(readyCount(browser), 0) << "nothing is drawn until asked";
    EXPECT_TRUE(browser.makeNextThumbnail(renderer));
    EXPECT_EQ(readyCount(browser), 1) << "one a call (a frame)";
    makeAll(browser, renderer);
    EXPECT_FALSE(browser.pending());
    EXPECT_EQ(browser.rendered(), 2);
    EXPECT_EQ(browser.fromCache(), 0);
    for (const BrowserScene& scene : browser.scenes()) {
      EXPECT_EQ(scene.thumbnail, BrowserScene::Thumbnail::Ready) << scene.name << ": " << scene.problem;
      EXPECT_FALSE(scene.description.empty()) << scene.name;
      const fs::path png = cache.pathFor(scene.key);
      ASSERT_TRUE(fs::exists(png)) << png;
      const std::optional<ui::RgbaImage> image = ui::readPng(png);
      ASSERT_TRUE(image);
      EXPECT_EQ(image->width, kThumbnailWidth);
      EXPECT_EQ(image->height, kThumbnailHeight);
      // A picture of the scene: the cloth covers part of it, not only the background's colour
      // (the top-left corner's).
      std::size_t drawn = 0;
      for (std::size_t i = 0; i + 3 < image->rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
          if (std::abs(image->rgba[i + c] - image->rgba[c]) > 24) {
            ++drawn;
            break;
          }
        }
      }
      EXPECT_GT(drawn, image->rgba.size() / 4 / 50) << scene.name << ": under 2% of the pixels drawn";
      if (const char* keep = std::getenv("WEFT_KEEP_THUMBNAILS"); keep != nullptr && *keep != '\0') {
        fs::create_directories(keep);
        fs::copy_file(png, fs::path(keep) / (scene.name + ".png"), fs::copy_options::overwrite_existing);
      }
    }
  }
  // Next time (a new browser, as at the next start): read back, none drawn.
  SceneBrowser again({folder()}, cache);
  makeAll(again, renderer);
  EXPECT_EQ(again.rendered(), 0);
  EXPECT_EQ(again.fromCache(), 2);
  EXPECT_EQ(readyCount(again), 2);

  // A changed scene file is drawn again; the other stays cached.
  std::ofstream(hangingSheet_, std::ios::app) << "\n";
  SceneBrowser changed({folder()}, cache);
  makeAll(changed, renderer);
  EXPECT_EQ(changed.rendered(), 1);
  EXPECT_EQ(changed.fromCache(), 1);
}

TEST_F(SceneBrowserTest, ASceneThatDoesNotLoadSaysWhyInsteadOfAPicture) {
  dir_.write("scenes/broken.json", R"({"name": "broken", "description": "a typo", "clothes": []})");
  ui::SceneRenderer renderer;
  SceneBrowser browser({folder()}, ThumbnailCache(dir_.path() / "cache"));
  makeAll(browser, renderer);
  const auto broken = std::find_if(browser.scenes().begin(), browser.scenes().end(),
                                   [](const BrowserScene& s) { return s.name == "broken"; });
  ASSERT_NE(broken, browser.scenes().end());
  EXPECT_EQ(broken->thumbnail, BrowserScene::Thumbnail::Failed);
  EXPECT_NE(broken->problem.find("clothes"), std::string::npos) << broken->problem;
  EXPECT_FALSE(fs::exists(dir_.path() / "cache" / (broken->key + ".png")));
}

// The panel: thumbnails with names and descriptions; a click on one asks to open that scene.
TEST_F(SceneBrowserTest, ThePanelShowsEachSceneAndAClickOpensIt) {
  addHangingSheet();
  ui::SceneRenderer renderer;
  SceneBrowser browser({folder()}, ThumbnailCache(dir_.path() / "cache"));
  ui_.panels.browser = &browser;
  ui_.panels.browserOpen = true;
  for (int frame = 0; frame < 4; ++frame) {  // as the app does: one thumbnail before each frame
    browser.makeNextThumbnail(renderer);
    imgui_->frame(drawUi());
  }
  EXPECT_FALSE(browser.pending());
  ASSERT_TRUE(probe_.rects.count("browser/hanging-sheet")) << "the browser draws every scene";
  ASSERT_TRUE(probe_.rects.count("browser/ball-into-sheet-table4.1-cloth2"));
  if (const char* keep = std::getenv("WEFT_KEEP_THUMBNAILS"); keep != nullptr && *keep != '\0') {
    fs::create_directories(keep);
    test::writePng(fs::path(keep) / "browser_panel.png", imgui_->image());
  }
  imgui_->click(probe_.centre("browser/hanging-sheet"), drawUi());
  EXPECT_EQ(ui_.panels.openRequest, hangingSheet_);
  EXPECT_FALSE(ui_.panels.browserOpen) << "the browser closes once a scene is chosen";
}

// The Materials tab: each preset of the scene's search path with its source, listed once (not
// read every frame); a click gives the selected cloth that material.
TEST_F(SceneBrowserTest, TheMaterialsTabListsPresetsWithTheirSourceAndAClickUsesOne) {
  SceneBrowser browser({folder()}, ThumbnailCache(dir_.path() / "cache"));
  ui_.panels.browser = &browser;
  ui_.panels.browserOpen = true;
  for (int frame = 0; frame < 2; ++frame) imgui_->frame(drawUi());  // a tab bar lays its tabs out in its second frame
  imgui_->click(probe_.centre("browser/materials-tab"), drawUi());
  imgui_->frame(drawUi());  // a tab chosen in one frame shows its contents from the next
  if (const char* keep = std::getenv("WEFT_KEEP_THUMBNAILS"); keep != nullptr && *keep != '\0') {
    fs::create_directories(keep);
    test::writePng(fs::path(keep) / "materials_tab.png", imgui_->image());
  }
  ASSERT_FALSE(browser.materials().empty());
  const auto royal = std::find_if(browser.materials().begin(), browser.materials().end(),
                                  [](const BrowserPreset& p) { return p.name == "royal-target"; });
  ASSERT_NE(royal, browser.materials().end());
  EXPECT_FALSE(royal->source.empty()) << "its source is shown";
  ASSERT_TRUE(probe_.rects.count("browser/material/royal-target"));
  ASSERT_NE(session_->scene().cloths[0].materialName, "royal-target");
  imgui_->click(probe_.centre("browser/material/royal-target"), drawUi());
  EXPECT_EQ(session_->scene().cloths[0].materialName, "royal-target") << session_->status;
}

}  // namespace
}  // namespace weft::editor
