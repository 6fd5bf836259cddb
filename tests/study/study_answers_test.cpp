// Answer files end to end: a CSV written here goes through analyzeStudyFile (what `weft
// study-analyze` runs) and the command itself; mistakes name the file, line and field.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

#include "study/study_analysis.h"
#include "study/thesis_tables.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

namespace fs = std::filesystem;

class StudyAnswersFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("weft_study_test_" + std::to_string(seed()));
    fs::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = root_ / name;
    std::ofstream(file) << text;
    return file;
  }
  fs::path root_;
};

// The thesis' six clips (Table 4.10: clips 1 and 6 denim, 2 and 5 t-shirt, 3 pants, 4 swimsuit).
struct ThesisClip {
  const char* id;
  Fabric fabric;
};
constexpr ThesisClip kThesisClips[] = {{"cloth1", Fabric::Denim},  {"cloth2", Fabric::TShirt},
                                       {"cloth3", Fabric::Pants},  {"cloth4", Fabric::Swimsuit},
                                       {"cloth5", Fabric::TShirt}, {"cloth6", Fabric::Denim}};

// An answers file whose scores are Tables 4.11 and 4.17. Of each participant's clips of a fabric,
// the first (fabric score × clips) are guessed right; the next ones until (group score × clips)
// get the other fabric of the same group; the rest a fabric of the other group. The thesis' own
// per-clip answers are not printed (Table 4.10 only counts them), so this is one file consistent
// with its tables; guessed_group is left empty, as the thesis scored groups from fabric guesses.
std::string answersFromTables4_11And4_17() {
  std::ostringstream csv;
  csv << "# Built from thesis Tables 4.11 and "
         "4.17\nparticipant,clip,true_fabric,true_group,guessed_fabric,guessed_group\n";
  for (std::size_t p = 0; p < kTable4_11.size(); ++p) {
    for (Fabric fabric : kFabrics) {
      const auto f = static_cast<std::size_t>(indexOf(fabric));
      const int clips = fabric == Fabric::Denim || fabric == Fabric::TShirt ? 2 : 1;
      const int fabricRight = static_cast<int>(kTable4_11[p][f] * clips);
      const int groupRight = static_cast<int>(kTable4_17[p][f] * clips);
      int seen = 0;
      for (const ThesisClip& clip : kThesisClips) {
        if (clip.fabric != fabric) continue;
        const Fabric sameGroupOther = fabric == Fabric::Denim    ? Fabric::Pants
                                      : fabric == Fabric::Pants  ? Fabric::Denim
                                      : fabric == Fabric::TShirt ? Fabric::Swimsuit
                                                                 : Fabric::TShirt;
        const Fabric otherGroup = groupOf(fabric) == ElasticityGroup::Stiff ? Fabric::Swimsuit : Fabric::Denim;
        const Fabric guess = seen < fabricRight ? fabric : seen < groupRight ? sameGroupOther : otherGroup;
        csv << "s" << (p + 1) << "," << clip.id << "," << fabricName(fabric) << "," << groupName(groupOf(fabric)) << ","
            << fabricName(guess) << ",\n";
        ++seen;
      }
    }
  }
  return csv.str();
}

TEST_F(StudyAnswersFile, ThesisTablesThroughTheCsvReproduceTheThesisResults) {
  const fs::path file = write("answers.csv", answersFromTables4_11And4_17());
  const StudyAnalysis analysis = analyzeStudyFile(file.string());
  ASSERT_EQ(analysis.participants.size(), 14u);
  ASSERT_EQ(analysis.clips.size(), 6u);
  for (std::size_t p = 0; p < 14; ++p) {
    for (std::size_t f = 0; f < 4; ++f) {
      EXPECT_EQ(analysis.fabricScores[p][f], kTable4_11[p][f]) << "participant " << p + 1 << ", fabric " << f;
      EXPECT_EQ(analysis.groupScores[p][f], kTable4_17[p][f]) << "participant " << p + 1 << ", fabric " << f;
    }
  }
  // Table 4.10's right guesses per fabric: denim 5 + 6, t-shirt 6 + 6, pants 7, swimsuit 8.
  std::array<int, 4> right{};
  for (const ClipGuesses& clip : analysis.clips)
    right[indexOf(clip.trueFabric)] += clip.guesses[indexOf(clip.trueFabric)];
  EXPECT_EQ(right, (std::array<int, 4>{11, 12, 7, 8}));
  // Table 4.13.
  EXPECT_EQ(analysis.fabricFriedman.blocks, 14);
  EXPECT_NEAR(analysis.fabricFriedman.statistic, 1.366, 0.0005);
  EXPECT_NEAR(analysis.fabricFriedman.asymptoticP, 0.714, 0.0005);
  // Tables 4.21, 4.23, 4.25, 4.27: W+ and p.
  const std::array<std::pair<double, double>, 4> printed{{{28.0, 0.008}, {21.0, 0.024}, {10.0, 0.046}, {6.0, 0.083}}};
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_EQ(analysis.fabricVsGroup[f].positiveRankSum, printed[f].first) << "fabric " << f;
    EXPECT_NEAR(analysis.fabricVsGroup[f].asymptoticP, printed[f].second, 0.0005) << "fabric " << f;
  }
}

std::string withoutComments(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    if (!line.empty() && line.front() != '#') out += line + "\n";
  }
  return out;
}

// The example in docs/ (linked from docs/study.md) is this same file: regenerate it by this rule.
TEST_F(StudyAnswersFile, DocsExampleIsTheFileBuiltFromTheThesisTables) {
  std::stringstream docs;
  docs << std::ifstream(fs::path(WEFT_SOURCE_DIR) / "docs" / "study" / "thesis-answers.csv").rdbuf();
  EXPECT_EQ(withoutComments(docs.str()), withoutComments(answersFromTables4_11And4_17()));
}

TEST_F(StudyAnswersFile, GuessedGroupColumnIsScoredWhenGiven) {
  // One participant who names the wrong fabrics but the right groups, columns in another order.
  const fs::path file = write("answers.csv",
                              "guessed_group,participant,clip,true_fabric,true_group,guessed_fabric\n"
                              "stiff,a,c1,denim,stiff,swimsuit\n"
                              "stretchy,a,c2,t-shirt,stretchy,pants\n"
                              "stiff,a,c3,pants,stiff,t-shirt\n"
                              "stretchy,a,c4,swimsuit,stretchy,denim\n");
  const StudyAnalysis analysis = analyzeStudyFile(file.string());
  EXPECT_EQ(analysis.fabricScores[0], (std::array<double, 4>{0, 0, 0, 0}));
  EXPECT_EQ(analysis.groupScores[0], (std::array<double, 4>{1, 1, 1, 1}));
  EXPECT_EQ(analysis.groupCorrect[0], (std::array<double, 2>{2, 2}));
}

// The message of the InputError that analysing `text` throws.
std::string errorFor(const fs::path& file) {
  try {
    analyzeStudyFile(file.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_F(StudyAnswersFile, MistakesNameTheFileLineAndField) {
  const std::string header = "participant,clip,true_fabric,true_group,guessed_fabric,guessed_group\n";
  const fs::path unknownFabric = write("fabric.csv", header + "a,c1,denim,stiff,denim,\na,c2,silk,stiff,denim,\n");
  EXPECT_EQ(errorFor(unknownFabric),
            unknownFabric.string() +
                ": line 3: true_fabric: unknown fabric 'silk' (expected denim, t-shirt, pants or swimsuit)");
  const fs::path shortRow = write("short.csv", header + "\n# a comment\na,c1,denim,stiff\n");
  EXPECT_EQ(errorFor(shortRow), shortRow.string() + ": line 4: malformed row: 4 fields, the header has 6");
  const fs::path missingColumn = write("missing.csv", "participant,clip,true_fabric,true_group,guessed_fabric\n");
  EXPECT_EQ(errorFor(missingColumn), missingColumn.string() + ": line 1: header: missing column 'guessed_group'");
  const fs::path wrongGroup = write("group.csv", header + "a,c1,swimsuit,stiff,denim,\n");
  EXPECT_EQ(errorFor(wrongGroup),
            wrongGroup.string() + ": line 2: true_group: stiff disagrees with true_fabric swimsuit, which is stretchy");
  const fs::path badGuessGroup = write("guess.csv", header + "a,c1,denim,stiff,denim,bouncy\n");
  EXPECT_EQ(errorFor(badGuessGroup),
            badGuessGroup.string() +
                ": line 2: guessed_group: unknown elasticity group 'bouncy' (expected stiff or stretchy)");
  const fs::path twice = write("twice.csv", header + "a,c1,denim,stiff,denim,\na,c1,denim,stiff,pants,\n");
  EXPECT_EQ(errorFor(twice), twice.string() + ": line 3: clip: participant 'a' already answered clip 'c1'");
  const fs::path incomplete = write("incomplete.csv", header + "a,c1,denim,stiff,denim,\n");
  EXPECT_EQ(
      errorFor(incomplete),
      incomplete.string() +
          ": participant a: no answer for a t-shirt clip; the tests compare every fabric within each participant");
  EXPECT_EQ(errorFor(root_ / "absent.csv"), (root_ / "absent.csv").string() + ": cannot open the file");
}

// The command itself: tables on stdout, the JSON file, and exit code 2 with the message on bad input.
TEST_F(StudyAnswersFile, CommandPrintsTablesWritesJsonAndRejectsBadInput) {
  // The sanitizer build (scripts/sanitize.sh) builds weft_tests alone, not the weft binary.
  if (!fs::exists(WEFT_BINARY)) GTEST_SKIP() << "no weft binary at " << WEFT_BINARY;
  const fs::path answers = write("answers.csv", answersFromTables4_11And4_17());
  const fs::path json = root_ / "study.json";
  const fs::path log = root_ / "log.txt";
  const auto run = [&](const fs::path& csv) {
    const std::string command = "'" + std::string(WEFT_BINARY) + "' study-analyze '" + csv.string() + "' --json '" +
                                json.string() + "' > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  const auto logText = [&] {
    std::stringstream text;
    text << std::ifstream(log).rdbuf();
    return text.str();
  };
  ASSERT_EQ(run(answers), 0) << logText();
  EXPECT_NE(logText().find("chi-squared = 1.366 (tie-corrected; 1.093 without), df = 3, asymptotic p = 0.714"),
            std::string::npos)
      << logText();
  EXPECT_NE(logText().find("W+ = 28.0, W- = 0.0, Z = 2.646, asymptotic p = 0.008"), std::string::npos) << logText();
  const nlohmann::json numbers = nlohmann::json::parse(std::ifstream(json));
  EXPECT_NEAR(numbers["friedman_fabric"]["statistic"].get<double>(), 1.366, 0.0005);
  EXPECT_NEAR(numbers["wilcoxon_fabric_vs_group"]["denim"]["asymptotic_p"].get<double>(), 0.008, 0.0005);

  const fs::path bad = write(
      "bad.csv", "participant,clip,true_fabric,true_group,guessed_fabric,guessed_group\na,c1,linen,stiff,denim,\n");
  EXPECT_EQ(run(bad), 2);
  EXPECT_NE(logText().find(bad.string() + ": line 2: true_fabric: unknown fabric 'linen'"), std::string::npos)
      << logText();
}

}  // namespace
}  // namespace weft::study
