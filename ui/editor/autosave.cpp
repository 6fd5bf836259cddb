#include "editor/autosave.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "util/atomic_file.h"
#include "util/json_text.h"

namespace weft::editor {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kFormatVersion = 1;
constexpr const char* kSuffix = ".autosave.json";

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

// The one spelling of a path that names the autosave: absolute, normalised, symlinks resolved where
// they exist, so "scenes/a.json" and "/home/x/scenes/../scenes/a.json" share one autosave.
fs::path absoluteOf(const fs::path& original) {
  if (original.empty()) return {};
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(original, ec), ec);
  if (ec) resolved = fs::absolute(original, ec).lexically_normal();
  return resolved;
}

// 64-bit FNV-1a (offset basis 14695981039346656037, prime 1099511628211, as published at
// isthe.com/chongo/tech/comp/fnv): unlike std::hash it is the same in every build, so a newer editor
// still finds an older one's autosaves.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// A JSON file read as the headless readers read (util/json_text.h: no duplicate keys, bounded
// depth), or nullopt when it cannot be read or is refused. Never throws.
std::optional<json> readStrictly(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parseJsonText(text.str(), file.string());
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// An autosave file as written by write(), or nullopt for anything else: unreadable, not JSON, another
// format version, a missing or mistyped field. Never throws.
std::optional<Recovery> readAutosave(const fs::path& autosaveFile) {
  const std::optional<json> read = readStrictly(autosaveFile);
  if (!read) return std::nullopt;
  const json& j = *read;
  if (!j.is_object()) return std::nullopt;
  const auto has = [&](const char* key, bool (json::*isType)() const noexcept) {
    const auto it = j.find(key);
    return it != j.end() && ((*it).*isType)();
  };
  if (!has("weftAutosave", &json::is_number_integer) || j["weftAutosave"] != kFormatVersion) return std::nullopt;
  if (!has("original", &json::is_string) || !has("savedAt", &json::is_string) || !j.contains("document"))
    return std::nullopt;
  Recovery recovery{j["original"].get<std::string>(), autosaveFile, j["document"], {}, j["savedAt"].get<std::string>()};
  if (j.contains("toolTags")) {
    if (!j["toolTags"].is_array()) return std::nullopt;
    for (const json& entry : j["toolTags"]) {
      const auto field = [&](const char* key, bool (json::*isType)() const noexcept) {
        const auto it = entry.find(key);
        return it != entry.end() && ((*it).*isType)();
      };
      if (!entry.is_object() || !field("obstacle", &json::is_number_integer) || !field("tool", &json::is_string) ||
          !field("file", &json::is_string) || !field("inScene", &json::is_boolean) || !field("tags", &json::is_object))
        return std::nullopt;
      recovery.toolTags.push_back(UnsavedToolTags{entry["obstacle"].get<int>(), entry["tool"].get<std::string>(),
                                                  entry["file"].get<std::string>(), entry["inScene"].get<bool>(),
                                                  entry["tags"]});
    }
  }
  return recovery;
}

// A tool's recorded tags are work the disk lacks unless its tags file holds exactly them. Tags
// kept in the scene always count: the scene's document says whether they were saved.
bool toolTagsDifferFromDisk(const UnsavedToolTags& tags) {
  if (tags.inScene || tags.file.empty()) return true;
  const std::optional<json> onDisk = readStrictly(tags.file);
  return !onDisk || *onDisk != tags.tags;
}

// Whether the autosave holds anything the original does not: an untitled document, a missing or
// unparseable original, different JSON, or a tool's tags its file does not hold.
bool differsFromDisk(const Recovery& recovery) {
  if (recovery.original.empty()) return true;
  if (std::any_of(recovery.toolTags.begin(), recovery.toolTags.end(), toolTagsDifferFromDisk)) return true;
  const std::optional<json> onDisk = readStrictly(recovery.original);
  return !onDisk || *onDisk != recovery.document;
}

}  // namespace

fs::path Autosave::defaultDirectory() {
  if (const std::string dir = environment("WEFT_AUTOSAVE_DIR"); !dir.empty()) return dir;
  if (const std::string state = environment("XDG_STATE_HOME"); !state.empty()) return fs::path(state) / "weft" / "autosave";
  if (const std::string home = environment("HOME"); !home.empty())
    return fs::path(home) / ".local" / "state" / "weft" / "autosave";
  return fs::temp_directory_path() / "weft-autosave";
}

Autosave::Autosave(fs::path dir) : dir_(std::move(dir)) {}

const fs::path& Autosave::directory() const { return dir_; }

fs::path Autosave::fileFor(const fs::path& original) const {
  const fs::path absolute = absoluteOf(original);
  if (absolute.empty()) return dir_ / (std::string("untitled") + kSuffix);
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(absolute.string())));
  return dir_ / (absolute.stem().string() + "-" + hash + kSuffix);
}

void Autosave::write(const JsonDocument& doc, const std::vector<UnsavedToolTags>& toolTags) {
  write(doc, doc.json(), doc.dirty(), toolTags);
}

fs::path Autosave::strengthMapFile(const fs::path& original, const std::string& cloth) const {
  std::string name = fileFor(original).filename().string();
  name.resize(name.size() - std::string(kSuffix).size());
  return dir_ / (name + "." + cloth + ".strength.png");
}

void Autosave::write(const JsonDocument& doc, const json& kept, bool unsaved, const std::vector<UnsavedToolTags>& toolTags) {
  if (!unsaved && toolTags.empty()) {
    discard(doc.file());
    return;
  }
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw std::runtime_error("cannot create the autosave folder " + dir_.string() + ": " + ec.message());
  json record = {{"weftAutosave", kFormatVersion},
                       {"original", absoluteOf(doc.file()).string()},
                       {"savedAt", utcNow()},
                       {"document", kept},
                       {"toolTags", json::array()}};
  for (const UnsavedToolTags& tags : toolTags) {
    record["toolTags"].push_back({{"obstacle", tags.obstacle},
                                  {"tool", tags.tool},
                                  {"file", tags.file.empty() ? std::string() : absoluteOf(tags.file).string()},
                                  {"inScene", tags.inScene},
                                  {"tags", tags.tags}});
  }
  writeFileAtomically(fileFor(doc.file()), record.dump(2) + "\n");
}

std::optional<Recovery> Autosave::find(const fs::path& original) const {
  std::optional<Recovery> found = readAutosave(fileFor(original));
  // The recorded path guards against a hash collision and a file copied in from elsewhere.
  if (!found || found->original != absoluteOf(original) || !differsFromDisk(*found)) return std::nullopt;
  return found;
}

std::vector<Recovery> Autosave::all() const {
  std::vector<Recovery> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= std::string(kSuffix).size() || !name.ends_with(kSuffix)) continue;
    std::optional<Recovery> recovery = readAutosave(it->path());
    // Only files under the name find() would look for count, so discard() can always remove them.
    if (recovery && fileFor(recovery->original) == it->path() && differsFromDisk(*recovery))
      found.push_back(std::move(*recovery));
  }
  std::sort(found.begin(), found.end(), [](const Recovery& a, const Recovery& b) {
    return a.savedAt != b.savedAt ? a.savedAt < b.savedAt : a.autosaveFile < b.autosaveFile;
  });
  return found;
}

void Autosave::discard(const fs::path& original) {
  std::error_code ignored;
  fs::remove(fileFor(original), ignored);
  // Its painted strength maps (strengthMapFile) go with it.
  std::string prefix = fileFor(original).filename().string();
  prefix.resize(prefix.size() - std::string(kSuffix).size());
  prefix += ".";
  std::vector<fs::path> maps;
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with(prefix) && name.ends_with(".strength.png")) maps.push_back(it->path());
  }
  for (const fs::path& map : maps) fs::remove(map, ignored);
}

}  // namespace weft::editor
