#include <algorithm>
#include "study_report.h"

#include <iomanip>
#include <string>

namespace weft::study {
namespace {

std::string padded(const std::string& text, int width) {
  return text.size() >= static_cast<std::size_t>(width) ? text + " " : text + std::string(width - text.size(), ' ');
}

void printScores(std::ostream& out, const StudyAnalysis& analysis, const std::vector<std::array<double, 4>>& scores) {
  out << "  " << padded("participant", 14);
  for (Fabric fabric : kFabrics) out << padded(std::string(fabricName(fabric)), 10);
  out << "\n";
  for (std::size_t p = 0; p < scores.size(); ++p) {
    out << "  " << padded(analysis.participants[p], 14);
    for (double score : scores[p]) out << padded(std::to_string(score).substr(0, 4), 10);
    out << "\n";
  }
}

// As SPSS prints them: mean ranks to 2 decimals, the statistic and p to 3.
void printFriedman(std::ostream& out, const FriedmanResult& result) {
  out << "  mean rank: ";
  for (Fabric fabric : kFabrics) {
    out << fabricName(fabric) << " " << std::fixed << std::setprecision(2)
        << result.meanRanks[static_cast<std::size_t>(indexOf(fabric))] << (fabric == Fabric::Swimsuit ? "\n" : ", ");
  }
  out << std::fixed << std::setprecision(3) << "  N = " << result.blocks << ", chi-squared = " << result.statistic
      << " (tie-corrected; " << result.uncorrectedStatistic << " without), df = " << result.degreesOfFreedom
      << ", asymptotic p = " << result.asymptoticP << "\n";
}

void printWilcoxon(std::ostream& out, const std::string& label, const WilcoxonResult& result) {
  // As SPSS prints them: rank sums to 1 decimal, Z and p to 3.
  out << std::fixed << std::setprecision(1) << "  " << padded(label, 34) << "N = " << result.pairs << ", +"
      << result.positive << " -" << result.negative << " =" << result.ties << ", W+ = " << result.positiveRankSum
      << ", W- = " << result.negativeRankSum << std::setprecision(3) << ", Z = " << result.z
      << ", asymptotic p = " << result.asymptoticP << "\n";
}

nlohmann::ordered_json friedmanJson(const FriedmanResult& result) {
  nlohmann::ordered_json meanRanks;
  for (Fabric fabric : kFabrics)
    meanRanks[std::string(fabricName(fabric))] = result.meanRanks[static_cast<std::size_t>(indexOf(fabric))];
  return {{"n", result.blocks},
          {"mean_ranks", meanRanks},
          {"statistic", result.statistic},
          {"statistic_without_tie_correction", result.uncorrectedStatistic},
          {"degrees_of_freedom", result.degreesOfFreedom},
          {"asymptotic_p", result.asymptoticP}};
}

nlohmann::ordered_json wilcoxonJson(const std::string& first, const std::string& second, const WilcoxonResult& result) {
  return {{"first", first},
          {"second", second},
          {"n", result.pairs},
          {"positive", result.positive},
          {"negative", result.negative},
          {"ties", result.ties},
          {"positive_rank_sum", result.positiveRankSum},
          {"negative_rank_sum", result.negativeRankSum},
          {"z", result.z},
          {"asymptotic_p", result.asymptoticP}};
}

nlohmann::ordered_json scoresJson(const StudyAnalysis& analysis, const std::vector<std::array<double, 4>>& scores) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (std::size_t p = 0; p < scores.size(); ++p) {
    nlohmann::ordered_json row{{"participant", analysis.participants[p]}};
    for (Fabric fabric : kFabrics)
      row[std::string(fabricName(fabric))] = scores[p][static_cast<std::size_t>(indexOf(fabric))];
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

void printStudyReport(std::ostream& out, const StudyAnalysis& analysis) {
  const auto oldFlags = out.flags();
  const auto oldPrecision = out.precision();
  out << "Guesses per clip (rows: the clip's fabric; columns: the fabric guessed; thesis Table 4.10)\n";
  std::size_t clipWidth = 14;  // the thesis' clip names; ids such as "swimsuit-hidden" are longer
  for (const ClipGuesses& clip : analysis.clips) clipWidth = std::max(clipWidth, clip.clip.size() + 2);
  out << "  " << padded("clip", static_cast<int>(clipWidth)) << padded("fabric", 10);
  for (Fabric fabric : kFabrics) out << padded(std::string(fabricName(fabric)), 10);
  out << "correct\n";
  for (const ClipGuesses& clip : analysis.clips) {
    out << "  " << padded(clip.clip, static_cast<int>(clipWidth)) << padded(std::string(fabricName(clip.trueFabric)), 10);
    for (int count : clip.guesses) out << padded(std::to_string(count), 10);
    out << clip.guesses[static_cast<std::size_t>(indexOf(clip.trueFabric))] << "/" << clip.answers << "\n";
  }
  out << "\nFabric guessed right, share of each fabric's clips (Table 4.11)\n";
  printScores(out, analysis, analysis.fabricScores);
  out << "Friedman test across fabrics (Tables 4.12, 4.13)\n";
  printFriedman(out, analysis.fabricFriedman);

  out << "\nElasticity group guessed right, share of each fabric's clips (Table 4.17; stiff = denim, pants;"
         " stretchy = t-shirt, swimsuit)\n";
  printScores(out, analysis, analysis.groupScores);
  out << "Friedman test across fabrics, by group guesses (Tables 4.18, 4.19)\n";
  printFriedman(out, analysis.groupFriedman);

  out << "\nWilcoxon signed-rank tests (differences second - first; W+ is the thesis' \"test statistic\"; two-sided "
         "p)\n";
  printWilcoxon(out, "stiff - stretchy clips (4.16)", analysis.stretchyVsStiff);
  for (Fabric fabric : kFabrics) {
    printWilcoxon(out, std::string(fabricName(fabric)) + ": group - fabric guess",
                  analysis.fabricVsGroup[static_cast<std::size_t>(indexOf(fabric))]);
  }
  out.flags(oldFlags);
  out.precision(oldPrecision);
}

nlohmann::ordered_json studyReportJson(const StudyAnalysis& analysis) {
  nlohmann::ordered_json clips = nlohmann::ordered_json::array();
  for (const ClipGuesses& clip : analysis.clips) {
    nlohmann::ordered_json guesses;
    for (Fabric fabric : kFabrics)
      guesses[std::string(fabricName(fabric))] = clip.guesses[static_cast<std::size_t>(indexOf(fabric))];
    clips.push_back({{"clip", clip.clip},
                     {"fabric", fabricName(clip.trueFabric)},
                     {"answers", clip.answers},
                     {"guesses", guesses}});
  }
  nlohmann::ordered_json groupCorrect = nlohmann::ordered_json::array();
  for (std::size_t p = 0; p < analysis.groupCorrect.size(); ++p) {
    groupCorrect.push_back(
        {{"participant", analysis.participants[p]},
         {"stiff", analysis.groupCorrect[p][static_cast<std::size_t>(indexOf(ElasticityGroup::Stiff))]},
         {"stretchy", analysis.groupCorrect[p][static_cast<std::size_t>(indexOf(ElasticityGroup::Stretchy))]}});
  }
  nlohmann::ordered_json perFabric;
  for (Fabric fabric : kFabrics) {
    perFabric[std::string(fabricName(fabric))] =
        wilcoxonJson("fabric_score", "group_score", analysis.fabricVsGroup[static_cast<std::size_t>(indexOf(fabric))]);
  }
  return {{"participants", analysis.participants.size()},
          {"clips", clips},
          {"fabric_scores", scoresJson(analysis, analysis.fabricScores)},
          {"group_scores", scoresJson(analysis, analysis.groupScores)},
          {"group_correct_counts", groupCorrect},
          {"friedman_fabric", friedmanJson(analysis.fabricFriedman)},
          {"friedman_group", friedmanJson(analysis.groupFriedman)},
          {"wilcoxon_stiff_vs_stretchy", wilcoxonJson("stretchy", "stiff", analysis.stretchyVsStiff)},
          {"wilcoxon_fabric_vs_group", perFabric}};
}

}  // namespace weft::study
