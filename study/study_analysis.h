#pragma once
// What the thesis computed from its "guess the fabric" study (§4.5.2), from the answers alone:
//
//   Table 4.10  guesses per clip          -> clips
//   Table 4.11  fabric scores             -> fabricScores   -> Friedman (Tables 4.12, 4.13)
//   Table 4.15  group guesses per group   -> groupCorrect   -> Wilcoxon stretchy vs stiff (4.16)
//   Table 4.17  group scores              -> groupScores    -> Friedman (Tables 4.18, 4.19)
//   Tables 4.20/22/24/26  fabric vs group score per fabric  -> Wilcoxon (4.21/23/25/27)
//
// A participant's score for a fabric is the share of that fabric's clips they guessed right: the
// thesis' 0, 0.5 or 1 for its two denim and two t-shirt clips, 0 or 1 for pants and swimsuit.
#include <array>
#include <string>
#include <vector>

#include "fabric.h"
#include "friedman_test.h"
#include "study_answers.h"
#include "wilcoxon_test.h"

namespace weft::study {

struct ClipGuesses {
  std::string clip;
  Fabric trueFabric = Fabric::Denim;
  std::array<int, 4> guesses{};  // how many participants guessed each fabric, in kFabrics order
  int answers = 0;
};

struct StudyAnalysis {
  std::vector<ClipGuesses> clips;                   // in the order first seen in the file
  std::vector<std::string> participants;            // likewise; the rows of the score tables
  std::vector<std::array<double, 4>> fabricScores;  // [participant][fabric]: share guessed right
  std::vector<std::array<double, 4>> groupScores;   // [participant][fabric]: share whose group was right
  std::vector<std::array<double, 2>> groupCorrect;  // [participant][group]: clips whose group was right
  FriedmanResult fabricFriedman;                    // over fabricScores
  FriedmanResult groupFriedman;                     // over groupScores
  // first = stretchy, second = stiff: the order whose W+ is the thesis' Table 4.16 "3.0".
  WilcoxonResult stretchyVsStiff;
  // Per fabric, first = fabric score, second = group score (Tables 4.21, 4.23, 4.25, 4.27).
  std::array<WilcoxonResult, 4> fabricVsGroup;
};

// Throws InputError (naming `file` and the participant) when a participant has no answer for
// some fabric: the tests compare every fabric within every participant.
StudyAnalysis analyzeStudy(const std::vector<StudyAnswer>& answers, const std::string& file);

// Reads and analyses an answers CSV (study_answers.h): what `weft study-analyze` runs.
StudyAnalysis analyzeStudyFile(const std::string& file);

}  // namespace weft::study
