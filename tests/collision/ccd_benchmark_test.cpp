// The CCD on the public sample queries of Wang, Ferguson et al. 2021, "A large-scale benchmark and
// an inclusion-based algorithm for continuous collision detection" (WEFT_SHARED_DIR
// /data/ccd-sample-queries/, format in its README.md): many of them are built to be degenerate
// (coplanar, parallel, touching at t = 0 or t = 1). With minDistance = 0 the CCD must have no
// false negative at all; false positives are only counted and reported, with the query time.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "collision/ccd.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

const fs::path kQueries = fs::path(WEFT_SHARED_DIR) / "data" / "ccd-sample-queries";

struct Query {
  Vec3 points[8];  // in the order of the README: the four points at t = 0, then at t = 1
  bool collides = false;
};

// An integer column as a double. Numerators (|n| <= 2^53) and denominators (powers of two, some
// beyond 2^64) are exact doubles, and from_chars rounds correctly, so the value is exact.
double parseExactInteger(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool integer = text.find_first_not_of("-0123456789") == std::string::npos;
  if (error != std::errc() || end != text.data() + text.size() || !integer) {
    ADD_FAILURE() << "not an integer: '" << text << "'";
  }
  return value;
}

// numerator / denominator, exactly: the quotient of an exact double by a power of two.
double exactRational(double numerator, double denominator) {
  int exponent = 0;
  EXPECT_EQ(std::frexp(denominator, &exponent), 0.5) << "denominator " << denominator << " is not a power of two";
  EXPECT_LE(std::abs(numerator), 0x1p53) << "numerator " << numerator << " may not be exact";
  return numerator / denominator;
}

// Every query of one file: 8 rows each of 7 integers (x, y, z as numerator/denominator pairs, and
// the ground truth).
std::vector<Query> readQueries(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Query> queries;
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> columns;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) columns.push_back(parseExactInteger(field));
    if (columns.size() != 7) {
      ADD_FAILURE() << file << ": a row with " << columns.size() << " columns";
      return {};
    }
    if (row % 8 == 0) queries.emplace_back();
    Query& query = queries.back();
    query.points[row % 8] = Vec3(exactRational(columns[0], columns[1]), exactRational(columns[2], columns[3]),
                                 exactRational(columns[4], columns[5]));
    query.collides = columns[6] == 1.0;
    ++row;
  }
  EXPECT_EQ(row % 8, 0) << file << ": the row count is not a multiple of 8";
  return queries;
}

bool ccdReportsHit(const Query& q, bool edgeEdge) {
  const Vec3* x = q.points;
  if (edgeEdge) return edgeEdgeCcd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], 0.0).has_value();
  return vertexFaceCcd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], 0.0).has_value();
}

struct Tally {
  int queries = 0, positives = 0, falseNegatives = 0, falsePositives = 0;
  double seconds = 0.0;
  double falsePositiveRate() const {
    const int negatives = queries - positives;
    return negatives > 0 ? double(falsePositives) / negatives : 0.0;
  }
  void add(const Tally& other) {
    queries += other.queries, positives += other.positives;
    falseNegatives += other.falseNegatives, falsePositives += other.falsePositives;
    seconds += other.seconds;
  }
};

Tally runFile(const fs::path& file, bool edgeEdge) {
  const std::vector<Query> queries = readQueries(file);
  // Timed as one loop: a clock read per query would cost about as much as a query.
  std::vector<char> hits(queries.size());
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < queries.size(); ++i) hits[i] = ccdReportsHit(queries[i], edgeEdge);
  Tally tally;
  tally.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (size_t i = 0; i < queries.size(); ++i) {
    ++tally.queries;
    tally.positives += queries[i].collides;
    if (queries[i].collides && !hits[i]) {
      ++tally.falseNegatives;
      ADD_FAILURE() << "false negative: query " << i << " of " << file;
    }
    tally.falsePositives += !queries[i].collides && hits[i];
  }
  return tally;
}

void report(const std::string& name, const Tally& t) {
  std::cout << std::left << std::setw(52) << name << std::right << std::setw(7) << t.queries << std::setw(7)
            << t.positives << std::setw(5) << t.falseNegatives << std::setw(7) << t.falsePositives << std::setw(9)
            << std::fixed << std::setprecision(4) << t.falsePositiveRate() << std::setw(10) << std::setprecision(3)
            << (t.queries > 0 ? 1e6 * t.seconds / t.queries : 0.0) << "\n";
}

TEST(CcdBenchmark, SampleQueriesHaveNoFalseNegatives) {
  if (!fs::is_directory(kQueries)) GTEST_SKIP() << "CCD sample queries not found at " << kQueries;

  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kQueries)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // a fixed order, whatever the file system's
  ASSERT_FALSE(files.empty()) << "no .csv query files under " << kQueries;

  std::cout << std::left << std::setw(52) << "file" << std::right << std::setw(7) << "queries" << std::setw(7)
            << "true" << std::setw(5) << "FN" << std::setw(7) << "FP" << std::setw(9) << "FP rate" << std::setw(10)
            << "us/query" << "\n";
  Tally total, vertexFace, edgeEdge;
  for (const fs::path& file : files) {
    const bool isEdgeEdge = file.parent_path().filename() == "edge-edge";
    const Tally tally = runFile(file, isEdgeEdge);
    report(fs::relative(file, kQueries).string(), tally);
    (isEdgeEdge ? edgeEdge : vertexFace).add(tally);
    total.add(tally);
  }
  report("all vertex-face", vertexFace);
  report("all edge-edge", edgeEdge);
  report("all", total);
  std::cout << "total CCD time " << std::setprecision(2) << 1e3 * total.seconds << " ms for " << total.queries
            << " queries\n";

  RecordProperty("queries", total.queries);
  RecordProperty("false_negatives", total.falseNegatives);
  RecordProperty("false_positives", total.falsePositives);
  RecordProperty("false_positive_rate", std::to_string(total.falsePositiveRate()));
  RecordProperty("total_query_seconds", std::to_string(total.seconds));
  EXPECT_EQ(total.falseNegatives, 0);
  EXPECT_GT(total.positives, 0);  // the files were read
}

}  // namespace
}  // namespace weft
