#include "headless_recorder.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "util/atomic_file.h"

namespace weft::editor {

namespace fs = std::filesystem;

namespace {

// A single-quoted shell word.
std::string quoted(const std::string& text) {
  std::string out(1, '\'');
  for (char c : text) {
    if (c == '\'') {
      out.append("'\\''");
    } else {
      out.push_back(c);
    }
  }
  out.push_back('\'');
  return out;
}

std::string lastLines(const fs::path& log, std::size_t count) {
  std::ifstream in(log);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  std::string out;
  for (std::size_t i = lines.size() > count ? lines.size() - count : 0; i < lines.size(); ++i) out += lines[i] + "\n";
  return out;
}

}  // namespace

HeadlessRecorder::~HeadlessRecorder() { wait(); }

void HeadlessRecorder::wait() {
  if (worker_.joinable()) worker_.join();
}

std::string HeadlessRecorder::lastMessage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return message_;
}

bool HeadlessRecorder::start(const nlohmann::json& scene, const fs::path& sceneFile, const fs::path& outDir, int frames,
                             bool video) {
  if (running_) return false;
  wait();  // the previous worker has finished; collect it
  std::string hidden(1, '.');
  hidden.append(sceneFile.stem().string()).append(".recording.json");
  const fs::path copy = sceneFile.parent_path() / hidden;
  try {
    nlohmann::json named = scene;
    // Unnamed scenes take their file's name, which the hidden copy's would not be.
    if (!named.contains("name")) named["name"] = sceneFile.stem().string();
    writeFileAtomically(copy, named.dump(2) + "\n");
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    message_ = std::string("cannot record: ") + e.what();
    return false;
  }
  fs::create_directories(outDir);
  const fs::path log = outDir / "record.log";
  const std::string command = quoted(weftBinary_.string()) + " run " + quoted(copy.string()) + " --out " +
                              quoted(outDir.string()) + " --frames " + std::to_string(frames) + " --png" +
                              (video ? " --video" : "") + " > " + quoted(log.string()) + " 2>&1";
  running_ = true;
  worker_ = std::thread([this, command, copy, outDir, log] {
    const int status = std::system(command.c_str());
    std::error_code ignored;
    fs::remove(copy, ignored);
    std::lock_guard<std::mutex> lock(mutex_);
    message_ = status == 0 ? "recorded " + (outDir / "frames").string() : "recording failed:\n" + lastLines(log, 3);
    running_ = false;
  });
  return true;
}

}  // namespace weft::editor
