// Adding answers to a CSV (what `weft guess` does after each clip): the rows read back as they
// were written, the header is written once, and an answer given twice leaves the file as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "study/clip_manifest.h"
#include "study/fabric_guess.h"
#include "study/study_analysis.h"
#include "study/study_answers.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

namespace fs = std::filesystem;

class StudyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("weft_study_append_test_" + std::to_string(seed()));
    fs::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  static std::string read(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  fs::path root_;
};

StudyAnswer answer(const std::string& participant, Fabric truth, Fabric guess, ElasticityGroup group) {
  StudyAnswer a;
  a.participant = participant;
  a.clip = clipId(truth, false);
  a.trueFabric = truth;
  a.guessedFabric = guess;
  a.guessedGroup = group;
  return a;
}

TEST_F(StudyFiles, AppendedAnswersReadBackAndFeedTheAnalysis) {
  const std::string file = (root_ / "answers.csv").string();
  for (const std::string participant : {"p01", "p02", "p03"}) {
    for (Fabric truth : kFabrics) {
      // p01 always right, p02 always says denim, p03 swaps within the group.
      const Fabric guess = participant == "p01"   ? truth
                           : participant == "p02" ? Fabric::Denim
                           : truth == Fabric::Denim ? Fabric::Pants
                           : truth == Fabric::Pants ? Fabric::Denim
                           : truth == Fabric::TShirt ? Fabric::Swimsuit
                                                     : Fabric::TShirt;
      appendStudyAnswers(file, {answer(participant, truth, guess, groupOf(guess))});
    }
  }
  const std::string text = read(file);
  EXPECT_EQ(text.rfind("participant,clip,true_fabric,true_group,guessed_fabric,guessed_group\n", 0), 0u) << text;
  EXPECT_NE(text.find("p03,t-shirt-hidden,t-shirt,stretchy,swimsuit,stretchy\n"), std::string::npos) << text;

  const std::vector<StudyAnswer> back = readStudyAnswers(file);
  ASSERT_EQ(back.size(), 12u);
  EXPECT_EQ(back[5].participant, "p02");
  EXPECT_EQ(back[5].clip, "t-shirt-hidden");
  EXPECT_EQ(back[5].trueFabric, Fabric::TShirt);
  EXPECT_EQ(back[5].guessedFabric, Fabric::Denim);
  EXPECT_EQ(back[5].guessedGroup, ElasticityGroup::Stiff);

  const StudyAnalysis analysis = analyzeStudyFile(file);
  ASSERT_EQ(analysis.participants.size(), 3u);
  ASSERT_EQ(analysis.clips.size(), 4u);
  // p03 has the group of all four clips right (two stiff, two stretchy) and no fabric.
  EXPECT_EQ(analysis.groupCorrect[2][0], 2.0);
  EXPECT_EQ(analysis.groupCorrect[2][1], 2.0);
}

TEST_F(StudyFiles, AnAnswerGivenTwiceIsRefusedAndTheFileKept) {
  const std::string file = (root_ / "answers.csv").string();
  appendStudyAnswers(file, {answer("p01", Fabric::Pants, Fabric::Pants, ElasticityGroup::Stiff)});
  const std::string before = read(file);
  try {
    appendStudyAnswers(file, {answer("p01", Fabric::Pants, Fabric::Denim, ElasticityGroup::Stiff)});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already answered clip 'pants-hidden'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(file), before);
}

TEST_F(StudyFiles, ClipManifestRoundTrips) {
  ClipManifest manifest;
  manifest.fps = 30;
  manifest.secondsPerPart = 0.5;
  manifest.framesPerPart = 15;
  manifest.width = 64;
  manifest.height = 48;
  manifest.parts = {"study-wind", "study-moved-by-pins", "study-ball-tear"};
  for (Fabric f : kFabrics) {
    for (bool textured : {true, false})
      manifest.clips.push_back({clipId(f, textured), f, textured, clipId(f, textured) + ".mp4", 45});
  }
  const fs::path file = root_ / "manifest.json";
  std::ofstream(file) << clipManifestJson(manifest).dump(2);
  const ClipManifest back = readClipManifest(file);
  EXPECT_EQ(back.framesPerPart, 15);
  EXPECT_EQ(back.width, 64);
  EXPECT_EQ(back.parts, manifest.parts);
  ASSERT_EQ(back.clips.size(), 8u);
  EXPECT_EQ(back.clips[3].id, "t-shirt-hidden");
  EXPECT_EQ(back.clips[3].fabric, Fabric::TShirt);
  EXPECT_FALSE(back.clips[3].textured);
  EXPECT_EQ(back.clips[3].file, "t-shirt-hidden.mp4");
}

TEST_F(StudyFiles, AClipManifestWithAnUnknownFabricNamesTheField) {
  const fs::path file = root_ / "manifest.json";
  std::ofstream(file) << R"({"format": "weft-study-clips", "version": 1, "fps": 30, "seconds_per_part": 5,
    "frames_per_part": 150, "size": [64, 48], "parts": [],
    "clips": [{"id": "x", "fabric": "silk", "textured": false, "file": "x.mp4", "frames": 1}]})";
  try {
    readClipManifest(file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/clips/0/fabric"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("silk"), std::string::npos) << e.what();
  }
}

// A field of the wrong type is named by its pointer (nlohmann's own message named only its
// error code), and a number that cannot be right is refused.
TEST_F(StudyFiles, AClipManifestWithAWrongTypedFieldNamesIt) {
  const fs::path file = root_ / "manifest.json";
  const std::string clip = R"([{"id": "x", "fabric": "denim", "textured": false, "file": "x.mp4", "frames": FRAMES}])";
  const std::vector<std::pair<std::string, std::string>> cases{
      {R"("fps": null)", "/fps"}, {R"("fps": -3)", "/fps"}, {R"("size": [64])", "/size"},
      {R"("size": "64x48")", "/size"}, {R"("fps": 30, "frames": "nine")", ""}};
  for (const auto& [change, pointer] : cases) {
    std::string fields = R"("fps": 30, "size": [64, 48])";
    std::string frames = "1";
    if (change.find("frames") != std::string::npos) {
      frames = "\"nine\"";
    } else if (change.rfind("\"fps\"", 0) == 0) {
      fields = change + R"(, "size": [64, 48])";
    } else {
      fields = R"("fps": 30, )" + change;
    }
    std::string clips = clip;
    clips.replace(clips.find("FRAMES"), 6, frames);
    std::ofstream(file) << R"({"format": "weft-study-clips", "version": 1, )" << fields
                        << R"(, "seconds_per_part": 5, "frames_per_part": 150, "parts": [], "clips": )" << clips << "}";
    try {
      readClipManifest(file);
      ADD_FAILURE() << change << ": expected InputError";
    } catch (const InputError& e) {
      const std::string expected = pointer.empty() ? "/clips/0/frames" : pointer;
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << change << ": " << e.what();
      EXPECT_EQ(std::string(e.what()).find("json.exception"), std::string::npos) << e.what();
    }
  }
}

TEST_F(StudyFiles, PreparedGuessesTakeTheFabricsGroupWhenNoneIsGiven) {
  const fs::path file = root_ / "guesses.txt";
  std::ofstream(file) << "# participant p07\npants,stretchy\n\nswimsuit\n";
  const std::vector<FabricGuess> guesses = readFabricGuesses(file.string());
  ASSERT_EQ(guesses.size(), 2u);
  EXPECT_EQ(guesses[0].fabric, Fabric::Pants);
  EXPECT_EQ(guesses[0].group, ElasticityGroup::Stretchy);
  EXPECT_EQ(guesses[1].fabric, Fabric::Swimsuit);
  EXPECT_EQ(guesses[1].group, ElasticityGroup::Stretchy);

  std::ofstream(file) << "wool\n";
  EXPECT_THROW(readFabricGuesses(file.string()), InputError);
}

}  // namespace
}  // namespace weft::study
