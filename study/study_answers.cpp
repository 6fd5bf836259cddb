#include "study_answers.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <optional>
#include <set>
#include <utility>

#include "util/atomic_file.h"
#include "util/echo.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

enum Column { kParticipant, kClip, kTrueFabric, kTrueGroup, kGuessedFabric, kGuessedGroup, kColumnCount };
constexpr std::array<const char*, kColumnCount> kColumnNames{"participant", "clip",           "true_fabric",
                                                             "true_group",  "guessed_fabric", "guessed_group"};

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trimmed(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

std::string where(int line) { return "line " + std::to_string(line); }

std::string fieldAt(int line, const char* column) { return where(line) + ": " + column; }

// The column of each field of the header, or an error naming what is missing, unknown or repeated.
std::array<int, kColumnCount> readHeader(const std::vector<std::string>& header, const std::string& file, int line) {
  std::array<int, kColumnCount> fieldOf;
  fieldOf.fill(-1);
  for (std::size_t i = 0; i < header.size(); ++i) {
    int column = -1;
    for (int c = 0; c < kColumnCount; ++c) {
      if (header[i] == kColumnNames[c]) column = c;
    }
    if (column < 0) {
      throw InputError(
          file, where(line) + ": header",
          "unknown column '" + echo(header[i], 60) +
              "' (the columns are participant, clip, true_fabric, true_group, guessed_fabric, guessed_group)");
    }
    if (fieldOf[column] >= 0)
      throw InputError(file, where(line) + ": header",
                       std::string("column '") + kColumnNames[column] + "' appears twice");
    fieldOf[column] = static_cast<int>(i);
  }
  for (int c = 0; c < kColumnCount; ++c) {
    if (fieldOf[c] < 0)
      throw InputError(file, where(line) + ": header", std::string("missing column '") + kColumnNames[c] + "'");
  }
  return fieldOf;
}

Fabric fabricField(const std::string& value, const std::string& file, int line, const char* column) {
  if (const auto fabric = parseFabric(value)) return *fabric;
  throw InputError(file, fieldAt(line, column),
                   "unknown fabric '" + echo(value, 60) + "' (expected denim, t-shirt, pants or swimsuit)");
}

ElasticityGroup groupField(const std::string& value, const std::string& file, int line, const char* column) {
  if (const auto group = parseGroup(value)) return *group;
  throw InputError(file, fieldAt(line, column),
                   "unknown elasticity group '" + echo(value, 60) + "' (expected stiff or stretchy)");
}

}  // namespace

std::vector<StudyAnswer> parseStudyAnswers(std::istream& in, const std::string& file) {
  std::vector<StudyAnswer> answers;
  std::optional<std::array<int, kColumnCount>> fieldOf;
  std::set<std::pair<std::string, std::string>> answered;  // (participant, clip)
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const std::string content = trimmed(text);
    if (content.empty() || content.front() == '#') continue;
    if (content.find('"') != std::string::npos) {
      throw InputError(file, where(line), "quoted fields are not supported (ids and names have no commas)");
    }
    const std::vector<std::string> fields = splitFields(content);
    if (!fieldOf) {
      fieldOf = readHeader(fields, file, line);
      continue;
    }
    if (fields.size() != kColumnCount) {
      throw InputError(file, where(line),
                       "malformed row: " + std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(kColumnCount));
    }
    const auto field = [&](Column c) -> const std::string& { return fields[static_cast<std::size_t>((*fieldOf)[c])]; };
    StudyAnswer answer;
    answer.line = line;
    answer.participant = field(kParticipant);
    answer.clip = field(kClip);
    if (answer.participant.empty()) throw InputError(file, fieldAt(line, "participant"), "empty participant id");
    if (answer.clip.empty()) throw InputError(file, fieldAt(line, "clip"), "empty clip id");
    answer.trueFabric = fabricField(field(kTrueFabric), file, line, "true_fabric");
    const ElasticityGroup trueGroup = groupField(field(kTrueGroup), file, line, "true_group");
    if (trueGroup != groupOf(answer.trueFabric)) {
      throw InputError(file, fieldAt(line, "true_group"),
                       std::string(groupName(trueGroup)) + " disagrees with true_fabric " +
                           std::string(fabricName(answer.trueFabric)) + ", which is " +
                           std::string(groupName(groupOf(answer.trueFabric))));
    }
    answer.guessedFabric = fabricField(field(kGuessedFabric), file, line, "guessed_fabric");
    answer.guessedGroup = field(kGuessedGroup).empty() ? groupOf(answer.guessedFabric)
                                                       : groupField(field(kGuessedGroup), file, line, "guessed_group");
    if (!answered.emplace(answer.participant, answer.clip).second) {
      throw InputError(
          file, fieldAt(line, "clip"),
          "participant '" + echo(answer.participant, 60) + "' already answered clip '" + echo(answer.clip, 60) + "'");
    }
    answers.push_back(std::move(answer));
  }
  if (!fieldOf)
    throw InputError(file, "header",
                     "no header line (participant,clip,true_fabric,true_group,guessed_fabric,guessed_group)");
  if (answers.empty()) throw InputError(file, "", "no answers after the header");
  return answers;
}

std::vector<StudyAnswer> readStudyAnswers(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot open the file");
  return parseStudyAnswers(in, file);
}

std::string studyAnswersHeader() {
  std::string header;
  for (int c = 0; c < kColumnCount; ++c) header += std::string(c > 0 ? "," : "") + kColumnNames[c];
  return header;
}

std::string studyAnswerRow(const StudyAnswer& answer) {
  return answer.participant + "," + answer.clip + "," + std::string(fabricName(answer.trueFabric)) + "," +
         std::string(groupName(groupOf(answer.trueFabric))) + "," + std::string(fabricName(answer.guessedFabric)) +
         "," + std::string(groupName(answer.guessedGroup));
}

void appendStudyAnswers(const std::string& file, const std::vector<StudyAnswer>& answers) {
  std::string text;
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    std::ifstream in(file);
    if (!in) throw InputError(file, "", "cannot open the file");
    std::stringstream contents;
    contents << in.rdbuf();
    text = contents.str();
  }
  const bool blank = text.find_first_not_of(" \t\r\n") == std::string::npos;
  if (blank) text = studyAnswersHeader() + "\n";
  if (text.back() != '\n') text += '\n';
  for (const StudyAnswer& answer : answers) text += studyAnswerRow(answer) + "\n";
  // Read back before writing: the old rows must parse, and no clip may be answered twice.
  std::istringstream check(text);
  parseStudyAnswers(check, file);
  writeFileAtomically(file, text);
}

}  // namespace weft::study
