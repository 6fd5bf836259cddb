#include "editor/json_document.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/json_text.h"

namespace weft::editor {

namespace fs = std::filesystem;
using Json = nlohmann::json;  // the member function json() hides the bare name inside the class

JsonDocument JsonDocument::open(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file.string(), "", "cannot read the file");
  const std::string contents = text.str();
  // The headless readers' strict parser (util/json_text.h): a duplicate key, nesting too deep, a
  // U+0000 or an out-of-range number is refused here as `weft run` refuses it, naming the key.
  try {
    return JsonDocument(parseJsonText(contents, file.string()), file);
  } catch (const InputError& strict) {
    // loadScene accepts comments; the editor must not drop them without a word on the next save.
    bool onlyComments = false;
    try {
      (void)parseJsonText(contents, file.string(), JsonTextOptions{.allowComments = true});
      onlyComments = true;
    } catch (const InputError&) {
    }
    if (onlyComments)
      throw InputError(file.string(), "", "holds comments, which saving from the editor would drop; remove them to edit it");
    throw;
  }
}

JsonDocument::JsonDocument(Json initial, fs::path file) : file_(std::move(file)), history_(std::move(initial)) {}

const fs::path& JsonDocument::file() const { return file_; }
const Json& JsonDocument::json() const { return history_.current(); }
EditHistory& JsonDocument::history() { return history_; }
const EditHistory& JsonDocument::history() const { return history_; }
bool JsonDocument::dirty() const { return history_.dirty(); }

std::string JsonDocument::pretty(const Json& value) { return value.dump(2) + "\n"; }

void JsonDocument::save() { save(std::function<void()>()); }

void JsonDocument::save(const std::function<void()>& beforeRename) {
  if (file_.empty()) throw std::runtime_error("cannot save an untitled document: choose a file (Save As)");
  const fs::path backup = fs::path(file_) += ".bak";
  const auto keepBackupThenHook = [&] {
    std::error_code ec;
    if (fs::exists(file_, ec)) {
      // Copied, not renamed: FILE must exist at every moment, in case the rename never comes.
      fs::copy_file(file_, backup, fs::copy_options::overwrite_existing, ec);
      if (ec) throw std::runtime_error("cannot keep the previous version as " + backup.string() + ": " + ec.message());
    }
    if (beforeRename) beforeRename();
  };
  try {
    writeFileAtomically(file_, pretty(history_.current()), keepBackupThenHook);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot save " + file_.string() + ": " + e.what());
  }
  history_.markSaved();
}

void JsonDocument::saveAs(const fs::path& file) {
  fs::path previous = std::exchange(file_, file);
  try {
    save();
  } catch (...) {
    file_ = std::move(previous);
    throw;
  }
}

}  // namespace weft::editor
