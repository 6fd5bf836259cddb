#pragma once
// The analysis of a study as people read it (tables on a terminal) and as scripts read it (JSON
// with the same numbers, unrounded).
#include <nlohmann/json.hpp>
#include <ostream>

#include "study_analysis.h"

namespace weft::study {

void printStudyReport(std::ostream& out, const StudyAnalysis& analysis);
nlohmann::ordered_json studyReportJson(const StudyAnalysis& analysis);

}  // namespace weft::study
