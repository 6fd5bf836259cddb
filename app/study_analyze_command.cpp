// `weft study-analyze ANSWERS.csv [--json FILE]`: the thesis' user-study statistics (§4.5.2) for a
// file of "guess the fabric" answers (format: study/study_answers.h and docs/study.md). Tables go to
// stdout; --json writes the same numbers unrounded.
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "study/study_analysis.h"
#include "study/study_report.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

struct StudyAnalyzeOptions {
  std::string answers;
  std::string json;  // empty: no JSON file
};

int analyzeStudyAnswers(const StudyAnalyzeOptions& options) {
  study::StudyAnalysis analysis;
  try {
    analysis = study::analyzeStudyFile(options.answers);
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  study::printStudyReport(std::cout, analysis);
  if (!options.json.empty()) {
    try {
      writeFileAtomically(options.json, study::studyReportJson(analysis).dump(2) + "\n");
    } catch (const std::exception& e) {
      std::cerr << "weft: " << e.what() << "\n";
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace

Command addStudyAnalyzeCommand(CLI::App& app) {
  auto options = std::make_shared<StudyAnalyzeOptions>();
  CLI::App* cli = app.add_subcommand(
      "study-analyze", "Friedman and Wilcoxon tests of a \"guess the fabric\" study's answers (thesis §4.5)");
  cli->add_option("answers", options->answers,
                  "Answers CSV: participant,clip,true_fabric,true_group,guessed_fabric,guessed_group")
      ->required();
  cli->add_option("--json", options->json, "Also write the numbers to this JSON file");
  return {cli, [options] { return analyzeStudyAnswers(*options); }};
}

}  // namespace weft::app
