// The user study's commands as a user runs them: `weft study-videos` renders the clips (for real:
// ffmpeg is one of the packages scripts/install_deps.sh installs), `weft guess --answers-from`
// records answers in a seeded order, and `weft study-analyze` reads what it wrote.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/clip_manifest.h"
#include "study/guess_order.h"
#include "study/study_answers.h"
#include "support/shell_run.h"
#include "support/temp_dir.h"

namespace weft::study {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using Result = weft::test::ShellResult;

// Runs `command` (a shell line) in `dir`; `environment` goes before it (e.g. "PATH=/nonexistent").
Result shell(const fs::path& dir, const std::string& command, const std::string& environment = "") {
  return weft::test::runShell("cd '" + dir.string() + "' && GALLIUM_DRIVER=llvmpipe " + environment + " " + command,
                              dir / "output.txt");
}

Result weft(const fs::path& dir, const std::string& arguments, const std::string& environment = "") {
  return shell(dir, "'" + std::string(WEFT_BINARY) + "' " + arguments, environment);
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first frame of a video, decoded by ffmpeg as raw RGBA.
std::string firstFrame(const fs::path& video) {
  const fs::path raw = video.parent_path() / (video.stem().string() + ".first.rgba");
  const std::string command = "ffmpeg -loglevel error -y -i '" + video.string() +
                              "' -frames:v 1 -f rawvideo -pix_fmt rgba '" + raw.string() + "'";
  if (std::system(command.c_str()) != 0) return "";
  return read(raw);
}

// The mean absolute difference of two RGBA images' bytes (0..255); 255 for different sizes.
double meanDifference(const std::string& a, const std::string& b) {
  if (a.size() != b.size() || a.empty()) return 255.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += std::abs(static_cast<int>(static_cast<unsigned char>(a[i])) - static_cast<int>(static_cast<unsigned char>(b[i])));
  return sum / static_cast<double>(a.size());
}

// Tiny clips, rendered once for the suite: 32 x 24 pixels, 0.1 s (3 frames) per part.
class StudyVideos : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<test::TempDir>("weft_study_videos_test_");
    result_ = weft(dir_->path(), "study-videos --out clips --width 32 --height 24 --seconds-per-part 0.1");
  }
  static void TearDownTestSuite() { dir_.reset(); }

  void SetUp() override {
    if (result_.exitCode == 1 && result_.output.find("cannot start headless OpenGL") != std::string::npos)
      GTEST_SKIP() << "headless OpenGL cannot start here: " << result_.output;
    ASSERT_EQ(result_.exitCode, 0) << result_.output;
  }
  static fs::path clips() { return dir_->path() / "clips"; }

  static std::unique_ptr<test::TempDir> dir_;
  static Result result_;
};
std::unique_ptr<test::TempDir> StudyVideos::dir_;
Result StudyVideos::result_;

TEST_F(StudyVideos, WritesATexturedAndAHiddenClipPerFabricAndAManifest) {
  const ClipManifest manifest = readClipManifest(clips() / "manifest.json");
  EXPECT_EQ(manifest.framesPerPart, 3);
  EXPECT_EQ(manifest.width, 32);
  EXPECT_EQ(manifest.height, 24);
  EXPECT_EQ(manifest.parts, (std::vector<std::string>{"study-wind", "study-moved-by-pins", "study-ball-tear"}));
  ASSERT_EQ(manifest.clips.size(), 8u);
  for (std::size_t f = 0; f < kFabrics.size(); ++f) {
    for (bool textured : {true, false}) {
      const StudyClip& clip = manifest.clips[2 * f + (textured ? 0 : 1)];
      SCOPED_TRACE(clip.id);
      EXPECT_EQ(clip.fabric, kFabrics[f]);
      EXPECT_EQ(clip.textured, textured);
      EXPECT_EQ(clip.file, clipId(kFabrics[f], textured) + ".mp4");
      EXPECT_EQ(clip.frames, 9);
      // ffprobe counts the frames ffmpeg really wrote.
      const Result probe = shell(clips(), "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                          "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" + clip.file + "'");
      EXPECT_EQ(probe.exitCode, 0) << probe.output;
      EXPECT_EQ(probe.output, "h264,32,24,9\n");
    }
  }
  // Nothing half-written is left behind.
  for (const auto& entry : fs::directory_iterator(clips()))
    EXPECT_NE(entry.path().extension(), ".partial") << entry.path();
  // The manifest's own JSON names each fabric's material preset.
  const json j = json::parse(read(clips() / "manifest.json"));
  EXPECT_EQ(j["clips"][0]["material"], "11oz-black-denim");
  EXPECT_EQ(j["clips"][7]["material"], "white-swim-solid");
}

TEST_F(StudyVideos, HiddenClipsStartAlikeAndTexturedOnesDoNot) {
  // At t = 0 every fabric hangs at rest in the same place: with the texture hidden the pictures
  // are the same up to the encoder (x264 sets a frame's quantizers looking at the frames after it,
  // which differ), with it shown the colours tell the fabrics apart.
  const std::string denimHidden = firstFrame(clips() / "denim-hidden.mp4");
  ASSERT_EQ(denimHidden.size(), 32u * 24u * 4u);
  EXPECT_LT(meanDifference(firstFrame(clips() / "swimsuit-hidden.mp4"), denimHidden), 2.0);
  EXPECT_LT(meanDifference(firstFrame(clips() / "t-shirt-hidden.mp4"), denimHidden), 2.0);
  EXPECT_GT(meanDifference(firstFrame(clips() / "denim-textured.mp4"), firstFrame(clips() / "swimsuit-textured.mp4")),
            10.0);
  EXPECT_GT(meanDifference(firstFrame(clips() / "denim-textured.mp4"), denimHidden), 10.0);
}

TEST_F(StudyVideos, TheSameCommandWritesTheSameBytes) {
  test::TempDir again("weft_study_videos_again_");
  const Result r = weft(again.path(), "study-videos --out clips --width 32 --height 24 --seconds-per-part 0.1 -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "");
  for (const char* file : {"manifest.json", "denim-textured.mp4", "pants-hidden.mp4", "swimsuit-hidden.mp4"}) {
    EXPECT_TRUE(read(again.path() / "clips" / file) == read(clips() / file)) << file << " differs";
  }
}

TEST_F(StudyVideos, GuessingTheRenderedClipsFeedsStudyAnalyze) {
  test::TempDir work("weft_study_guess_e2e_");
  const fs::path answers = work.path() / "answers.csv";
  // Three participants: one always right, one always "denim", one who swaps within each group.
  const std::vector<std::pair<std::string, std::string>> guesses{
      {"p01", "right"}, {"p02", "denim"}, {"p03", "swap"}};
  const ClipManifest manifest = readClipManifest(clips() / "manifest.json");
  std::vector<StudyClip> hidden;
  for (const StudyClip& clip : manifest.clips)
    if (!clip.textured) hidden.push_back(clip);
  for (const auto& [participant, style] : guesses) {
    std::string lines;
    for (int i : shuffledOrder(4, seedOfParticipant(participant))) {
      const Fabric truth = hidden[static_cast<std::size_t>(i)].fabric;
      const Fabric guess = style == "right"              ? truth
                           : style == "denim"            ? Fabric::Denim
                           : truth == Fabric::Denim      ? Fabric::Pants
                           : truth == Fabric::Pants      ? Fabric::Denim
                           : truth == Fabric::TShirt     ? Fabric::Swimsuit
                                                         : Fabric::TShirt;
      lines += std::string(fabricName(guess)) + "\n";
    }
    const fs::path script = work.write(participant + ".txt", lines);
    const Result r = weft(work.path(), "guess --clips '" + clips().string() + "' --answers answers.csv --participant " +
                                           participant + " --answers-from '" + script.string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("recorded 4 answer(s) of participant " + participant), std::string::npos) << r.output;
  }
  const std::vector<StudyAnswer> rows = readStudyAnswers(answers.string());
  ASSERT_EQ(rows.size(), 12u);
  const Result analysis = weft(work.path(), "study-analyze answers.csv --json report.json");
  EXPECT_EQ(analysis.exitCode, 0) << analysis.output;
  const json report = json::parse(read(work.path() / "report.json"));
  EXPECT_FALSE(report.empty());
}

TEST_F(StudyVideos, GuessWindowRecordsTheAnswersClickedInIt) {
  // The window under Xvfb, driven by xdotool: each round clicks Play, then "pants", "stretchy" and
  // "Next clip" where ImGui 1.86 lays them out in the window's top-left corner. Every click
  // lands harmlessly in a phase that lacks its widget, so rounds repeat until the answers file
  // holds a row per clip, however slowly the machine draws (RESOURCE_LOCK xvfb in CMake).
  if (std::system("command -v xvfb-run > /dev/null && command -v xdotool > /dev/null") != 0)
    GTEST_SKIP() << "xvfb-run or xdotool is not installed (scripts/install_deps.sh installs them)";
  test::TempDir work("weft_study_guess_window_");
  const fs::path driver = work.write("drive.sh", R"(
"$WEFT" guess --clips "$CLIPS" --answers answers.csv --participant w01 > guess.log 2>&1 &
pid=$!
xdotool search --sync --name "guess the fabric" > /dev/null
for round in $(seq 1 120); do
  rows=$(grep -c '^w01,' answers.csv 2> /dev/null)
  [ "${rows:-0}" -ge 4 ] && break
  kill -0 $pid 2> /dev/null || break
  xdotool mousemove 88 78 click 1; sleep 0.6
  xdotool mousemove 165 55 click 1; sleep 0.1
  xdotool mousemove 218 99 click 1; sleep 0.1
  xdotool mousemove 88 137 click 1; sleep 0.3
done
wait $pid
)");
  const Result r = shell(work.path(),
                         "WEFT='" + std::string(WEFT_BINARY) + "' CLIPS='" + clips().string() +
                             "' LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s '-screen 0 1280x1000x24' sh '" +
                             driver.string() + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output << read(work.path() / "guess.log");
  EXPECT_NE(read(work.path() / "guess.log").find("recorded 4 answer(s) of participant w01"), std::string::npos)
      << read(work.path() / "guess.log");
  const std::vector<StudyAnswer> rows = readStudyAnswers((work.path() / "answers.csv").string());
  ASSERT_EQ(rows.size(), 4u);
  const ClipManifest manifest = readClipManifest(clips() / "manifest.json");
  std::vector<std::string> hidden;
  for (const StudyClip& clip : manifest.clips)
    if (!clip.textured) hidden.push_back(clip.id);
  const std::vector<int> order = shuffledOrder(4, seedOfParticipant("w01"));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k].clip, hidden[static_cast<std::size_t>(order[k])]);
    EXPECT_EQ(rows[k].guessedFabric, Fabric::Pants);
    EXPECT_EQ(rows[k].guessedGroup, ElasticityGroup::Stretchy);
  }
}

TEST(StudyVideosCommand, WithoutFfmpegFailsBeforeWritingAnything) {
  test::TempDir work("weft_study_videos_noffmpeg_");
  const Result r = weft(work.path(), "study-videos --out clips --width 32 --height 24 --seconds-per-part 0.1",
                        "PATH=/nonexistent");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("ffmpeg is not installed"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work.path() / "clips"));
}

// `weft guess` on a hand-made clip folder: a manifest and four empty "videos" (the prepared
// answers never play them), so these tests need neither ffmpeg nor OpenGL.
class Guess : public ::testing::Test {
 protected:
  void SetUp() override {
    ClipManifest manifest;
    manifest.parts = {"study-wind", "study-moved-by-pins", "study-ball-tear"};
    for (Fabric f : kFabrics) {
      for (bool textured : {true, false}) {
        manifest.clips.push_back({clipId(f, textured), f, textured, clipId(f, textured) + ".mp4", 450});
        dir_.write("clips/" + clipId(f, textured) + ".mp4", "");
      }
      hidden_.push_back(clipId(f, false));
    }
    dir_.write("clips/manifest.json", clipManifestJson(manifest).dump(2));
  }

  Result guess(const std::string& participant, const std::string& answerLines, const std::string& more = "") const {
    const fs::path script = dir_.write("answers-" + participant + ".txt", answerLines);
    return weft(dir_.path(), "guess --clips clips --answers answers.csv --participant " + participant +
                                 " --answers-from '" + script.string() + "' " + more);
  }
  // The clips of `participant`'s rows in answers.csv, in file order.
  std::vector<std::string> clipsAnswered(const std::string& participant) const {
    std::vector<std::string> clips;
    for (const StudyAnswer& a : readStudyAnswers((dir_.path() / "answers.csv").string()))
      if (a.participant == participant) clips.push_back(a.clip);
    return clips;
  }
  std::vector<std::string> expectedOrder(std::uint64_t seed) const {
    std::vector<std::string> clips;
    for (int i : shuffledOrder(4, seed)) clips.push_back(hidden_[static_cast<std::size_t>(i)]);
    return clips;
  }

  test::TempDir dir_{"weft_guess_test_"};
  std::vector<std::string> hidden_;  // in manifest order: denim, t-shirt, pants, swimsuit
};

TEST_F(Guess, WritesOneRowPerHiddenClipInTheParticipantsSeededOrder) {
  const Result r = guess("p01", "denim,stiff\npants\nswimsuit,stiff\nt-shirt\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(clipsAnswered("p01"), expectedOrder(seedOfParticipant("p01")));
  const std::vector<StudyAnswer> rows = readStudyAnswers((dir_.path() / "answers.csv").string());
  ASSERT_EQ(rows.size(), 4u);
  // Each answer lands on the clip played at its position, with the clip's true fabric.
  EXPECT_EQ(rows[2].guessedFabric, Fabric::Swimsuit);
  EXPECT_EQ(rows[2].guessedGroup, ElasticityGroup::Stiff);
  EXPECT_EQ(rows[1].guessedGroup, ElasticityGroup::Stiff);  // pants, no group given: its own
  for (const StudyAnswer& row : rows) EXPECT_EQ(row.clip, clipId(row.trueFabric, false));
  // Only the hidden clips are guessed.
  for (const StudyAnswer& row : rows) EXPECT_EQ(row.clip.find("textured"), std::string::npos);
}

TEST_F(Guess, TheSeedFixesTheOrderWhoeverTheParticipant) {
  ASSERT_EQ(guess("p01", "denim\ndenim\ndenim\ndenim\n", "--seed 7").exitCode, 0);
  ASSERT_EQ(guess("p02", "denim\ndenim\ndenim\ndenim\n", "--seed 7").exitCode, 0);
  EXPECT_EQ(clipsAnswered("p01"), expectedOrder(7));
  EXPECT_EQ(clipsAnswered("p02"), expectedOrder(7));
}

TEST_F(Guess, ContinuesWithTheClipsNotYetAnsweredInTheSameOrder) {
  const std::vector<std::string> order = expectedOrder(seedOfParticipant("p05"));
  // p05 answered the first clip of their order, then stopped.
  StudyAnswer first;
  first.participant = "p05";
  first.clip = order[0];
  first.trueFabric = *parseFabric(order[0].substr(0, order[0].size() - std::string("-hidden").size()));
  first.guessedFabric = Fabric::Denim;
  first.guessedGroup = ElasticityGroup::Stiff;
  dir_.write("answers.csv", studyAnswersHeader() + "\n" + studyAnswerRow(first) + "\n");
  const Result r = guess("p05", "pants\npants\npants\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(clipsAnswered("p05"), order);

  const Result again = guess("p05", "pants\n");
  EXPECT_EQ(again.exitCode, 2) << again.output;
  EXPECT_NE(again.output.find("has already answered all 4 clips"), std::string::npos) << again.output;
}

TEST_F(Guess, AWrongNumberOfPreparedAnswersWritesNothing) {
  const Result r = guess("p01", "denim\npants\n");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("2 answer(s) for 4 clip(s)"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_.path() / "answers.csv"));
}

TEST_F(Guess, AnUnknownFabricNamesTheLine) {
  const Result r = guess("p01", "denim\npants\nsilk\ndenim\n");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("line 3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("silk"), std::string::npos) << r.output;
}

TEST_F(Guess, AParticipantIdWithACommaIsRefused) {
  const fs::path script = dir_.write("answers.txt", "denim\ndenim\ndenim\ndenim\n");
  const Result r = weft(dir_.path(), "guess --clips clips --answers answers.csv --participant p,01 --answers-from '" +
                                         script.string() + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--participant"), std::string::npos) << r.output;
}

TEST_F(Guess, AParticipantIdLongerThan64CharactersIsRefusedAndNotEchoedInFull) {
  const fs::path script = dir_.write("answers.txt", "denim\ndenim\ndenim\ndenim\n");
  const std::string id(300, 'x');
  const Result r = weft(dir_.path(), "guess --clips clips --answers answers.csv --participant " + id +
                                         " --answers-from '" + script.string() + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("1 to 64 characters"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(id), std::string::npos) << "the id is echoed capped";
  EXPECT_FALSE(fs::exists(dir_.path() / "answers.csv"));
}

TEST_F(Guess, WithoutADisplayOrAnswersFileSaysHowToAnswer) {
  const Result r = weft(dir_.path(), "guess --clips clips --answers answers.csv --participant p01", "env -u DISPLAY");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("--answers-from"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_.path() / "answers.csv"));
}

}  // namespace
}  // namespace weft::study
