#include "study_analysis.h"

#include <algorithm>

#include "util/echo.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

template <typename T>
int indexIn(std::vector<T>& list, const std::string& id, const auto& idOf) {
  const auto found = std::find_if(list.begin(), list.end(), [&](const T& item) { return idOf(item) == id; });
  return static_cast<int>(found - list.begin());
}

std::vector<std::vector<double>> asRows(const std::vector<std::array<double, 4>>& table) {
  std::vector<std::vector<double>> rows;
  for (const auto& row : table) rows.emplace_back(row.begin(), row.end());
  return rows;
}

std::vector<double> column(const auto& table, int c) {
  std::vector<double> out;
  for (const auto& row : table) out.push_back(row[static_cast<std::size_t>(c)]);
  return out;
}

}  // namespace

StudyAnalysis analyzeStudy(const std::vector<StudyAnswer>& answers, const std::string& file) {
  StudyAnalysis analysis;
  struct Tally {
    std::array<int, 4> clips{}, fabricRight{}, groupRight{};
  };
  std::vector<Tally> tallies;
  for (const StudyAnswer& answer : answers) {
    const int clip = indexIn(analysis.clips, answer.clip, [](const ClipGuesses& c) { return c.clip; });
    if (clip == static_cast<int>(analysis.clips.size()))
      analysis.clips.push_back({answer.clip, answer.trueFabric, {}, 0});
    ClipGuesses& guesses = analysis.clips[static_cast<std::size_t>(clip)];
    if (guesses.trueFabric != answer.trueFabric) {
      throw InputError(file, "line " + std::to_string(answer.line) + ": true_fabric",
                       "clip '" + echo(answer.clip, 60) + "' was " + std::string(fabricName(guesses.trueFabric)) +
                           " on an earlier line");
    }
    ++guesses.guesses[static_cast<std::size_t>(indexOf(answer.guessedFabric))];
    ++guesses.answers;

    const int who = indexIn(analysis.participants, answer.participant, [](const std::string& p) { return p; });
    if (who == static_cast<int>(analysis.participants.size())) {
      analysis.participants.push_back(answer.participant);
      tallies.emplace_back();
    }
    Tally& tally = tallies[static_cast<std::size_t>(who)];
    const auto f = static_cast<std::size_t>(indexOf(answer.trueFabric));
    ++tally.clips[f];
    tally.fabricRight[f] += answer.guessedFabric == answer.trueFabric ? 1 : 0;
    tally.groupRight[f] += answer.guessedGroup == groupOf(answer.trueFabric) ? 1 : 0;
  }

  for (std::size_t p = 0; p < tallies.size(); ++p) {
    const Tally& tally = tallies[p];
    std::array<double, 4> fabricScore{}, groupScore{};
    std::array<double, 2> groupCorrect{};
    for (Fabric fabric : kFabrics) {
      const auto f = static_cast<std::size_t>(indexOf(fabric));
      if (tally.clips[f] == 0) {
        throw InputError(file, "participant " + echo(analysis.participants[p], 60),
                         "no answer for a " + std::string(fabricName(fabric)) +
                             " clip; the tests compare every fabric within each participant");
      }
      fabricScore[f] = static_cast<double>(tally.fabricRight[f]) / tally.clips[f];
      groupScore[f] = static_cast<double>(tally.groupRight[f]) / tally.clips[f];
      groupCorrect[static_cast<std::size_t>(indexOf(groupOf(fabric)))] += tally.groupRight[f];
    }
    analysis.fabricScores.push_back(fabricScore);
    analysis.groupScores.push_back(groupScore);
    analysis.groupCorrect.push_back(groupCorrect);
  }

  analysis.fabricFriedman = friedmanTest(asRows(analysis.fabricScores));
  analysis.groupFriedman = friedmanTest(asRows(analysis.groupScores));
  analysis.stretchyVsStiff = wilcoxonSignedRankTest(column(analysis.groupCorrect, indexOf(ElasticityGroup::Stretchy)),
                                                    column(analysis.groupCorrect, indexOf(ElasticityGroup::Stiff)));
  for (Fabric fabric : kFabrics) {
    const int f = indexOf(fabric);
    analysis.fabricVsGroup[static_cast<std::size_t>(f)] =
        wilcoxonSignedRankTest(column(analysis.fabricScores, f), column(analysis.groupScores, f));
  }
  return analysis;
}

StudyAnalysis analyzeStudyFile(const std::string& file) { return analyzeStudy(readStudyAnswers(file), file); }

}  // namespace weft::study
