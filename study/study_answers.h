#pragma once
// The answers of a "guess the fabric" study, one per participant and clip, read from a CSV file.
//
// Format (UTF-8 text, comma-separated, no quoting; blank lines and lines starting with '#' are
// skipped). The first other line is the header and names these six columns, in any order:
//
//   participant,clip,true_fabric,true_group,guessed_fabric,guessed_group
//   p01,cloth1,denim,stiff,pants,stiff
//   p01,cloth2,t-shirt,stretchy,swimsuit,
//
// - participant, clip: free ids (no commas); a participant answers each clip at most once.
// - true_fabric, guessed_fabric: denim, t-shirt, pants or swimsuit.
// - true_group: the clip's elasticity group, stiff (denim, pants: the thesis' group one) or
//   stretchy (t-shirt, swimsuit: group two); it must agree with true_fabric.
// - guessed_group: the participant's answer to "which elasticity group", stiff or stretchy; empty
//   means "the group of guessed_fabric", which is how the thesis scored its study (§4.5.2.1 groups
//   the fabric guesses after the fact).
//
// Every mistake throws InputError naming the file, the line and the field.
#include <istream>
#include <string>
#include <vector>

#include "fabric.h"

namespace weft::study {

struct StudyAnswer {
  std::string participant;
  std::string clip;
  Fabric trueFabric = Fabric::Denim;
  Fabric guessedFabric = Fabric::Denim;
  ElasticityGroup guessedGroup = ElasticityGroup::Stiff;
  int line = 0;  // where it was read, for later messages
};

// `file` is only used in messages.
std::vector<StudyAnswer> parseStudyAnswers(std::istream& in, const std::string& file);
std::vector<StudyAnswer> readStudyAnswers(const std::string& file);

// The header line and one answer's row, in the column order of the example above (guessed_group
// always written out, so the file says what the participant answered).
std::string studyAnswersHeader();
std::string studyAnswerRow(const StudyAnswer& answer);

// Adds `answers` at the end of `file` (created with the header when missing or empty), rewriting
// it atomically (util/atomic_file.h) so that a crash leaves the old file or the new one, never
// half a row. The file's existing rows are read first and must parse; an answer a participant
// already gave for the same clip is an InputError, as it would be when reading the file back.
void appendStudyAnswers(const std::string& file, const std::vector<StudyAnswer>& answers);

}  // namespace weft::study
