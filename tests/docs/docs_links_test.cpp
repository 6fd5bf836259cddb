// The README links into docs/, one page per subsystem, and the pages link to each other, to
// presets/*/README.md and to files of the repository. Every relative link in those Markdown files
// must name a file that exists and, when it names a heading (`page.md#heading`), a heading that
// page has (GitHub's anchors: lower case, punctuation dropped, spaces as hyphens, repeats
// numbered). Links to other sites are not followed; links inside code blocks and code spans are
// not links.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> readLines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool isFence(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first != std::string::npos && line.compare(first, 3, "```") == 0;
}

// Decodes one UTF-8 code point at s[i], advancing i (a malformed byte counts as itself).
char32_t nextCodePoint(const std::string& s, size_t& i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  if (extra > 0 && i + extra >= s.size()) extra = 0;
  char32_t cp = extra == 0 ? b : (b & (0x3F >> extra));
  for (int k = 1; k <= extra; ++k) cp = (cp << 6) | (byte(i + k) & 0x3F);
  i += 1 + extra;
  return cp;
}

// GitHub's heading anchor: lower case; letters, digits, '-' and '_' kept, spaces become '-',
// punctuation and symbols dropped. Outside ASCII, the punctuation and symbol blocks that occur in
// headings (Latin-1 signs such as § and °, ×, general punctuation such as — and …, arrows,
// mathematical operators) are dropped and everything else (letters, ², ℜ) kept.
std::string anchorOf(const std::string& heading) {
  std::string out;
  for (size_t i = 0; i < heading.size();) {
    const size_t start = i;
    const char32_t cp = nextCodePoint(heading, i);
    if (cp < 0x80) {
      const char c = static_cast<char>(cp);
      if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      else if (c == ' ' || c == '-') out += '-';
      else if (c == '_') out += '_';
      continue;
    }
    const bool dropped = (cp >= 0xA0 && cp <= 0xBF) || cp == 0xD7 || cp == 0xF7 || (cp >= 0x2000 && cp <= 0x206F) ||
                         (cp >= 0x2190 && cp <= 0x22FF);
    if (!dropped) out.append(heading, start, i - start);
  }
  return out;
}

std::set<std::string> anchorsOf(const fs::path& markdown) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  bool inFence = false;
  for (const std::string& line : readLines(markdown)) {
    if (isFence(line)) inFence = !inFence;
    if (inFence) continue;
    const auto hashes = line.find_first_not_of('#');
    if (hashes == 0 || hashes == std::string::npos || hashes > 6 || line[hashes] != ' ') continue;
    const std::string base = anchorOf(line.substr(hashes + 1));
    const int n = seen[base]++;
    anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
  }
  return anchors;
}

// Every relative link of `markdown` that does not resolve, as "file:line: target (why)".
std::vector<std::string> brokenLinks(const fs::path& markdown, const fs::path& root) {
  static const std::regex codeSpan("`[^`]*`");
  static const std::regex link(R"(\]\(([^)\s]+)(\s+"[^"]*")?\))");
  std::vector<std::string> broken;
  bool inFence = false;
  const std::vector<std::string> lines = readLines(markdown);
  for (size_t n = 0; n < lines.size(); ++n) {
    if (isFence(lines[n])) inFence = !inFence;
    if (inFence) continue;
    const std::string text = std::regex_replace(lines[n], codeSpan, "code");
    for (auto m = std::sregex_iterator(text.begin(), text.end(), link); m != std::sregex_iterator(); ++m) {
      const std::string target = (*m)[1].str();
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const auto hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
      const fs::path file = path.empty() ? markdown : (markdown.parent_path() / path).lexically_normal();
      const std::string where = fs::relative(markdown, root).string() + ":" + std::to_string(n + 1) + ": " + target;
      if (!fs::exists(file)) {
        broken.push_back(where + " (no such file)");
      } else if (!anchor.empty() && file.extension() == ".md" && anchorsOf(file).count(anchor) == 0) {
        broken.push_back(where + " (no such heading)");
      }
    }
  }
  return broken;
}

std::vector<fs::path> documentation(const fs::path& root) {
  std::vector<fs::path> files{root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs")) {
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  }
  for (const auto& entry : fs::directory_iterator(root / "presets")) {
    if (fs::exists(entry.path() / "README.md")) files.push_back(entry.path() / "README.md");
  }
  return files;
}

std::string joined(const std::vector<std::string>& lines) {
  std::ostringstream out;
  for (const auto& line : lines) out << "\n  " << line;
  return out.str();
}

TEST(DocsLinks, EveryRelativeLinkOfTheReadmeAndTheDocsResolves) {
  const fs::path root(WEFT_SOURCE_DIR);
  const std::vector<fs::path> files = documentation(root);
  ASSERT_GE(files.size(), 10u) << "README.md, docs/*.md and presets/*/README.md";
  std::vector<std::string> broken;
  size_t pages = 0;
  for (const fs::path& file : files) {
    const auto b = brokenLinks(file, root);
    broken.insert(broken.end(), b.begin(), b.end());
    ++pages;
  }
  EXPECT_TRUE(broken.empty()) << broken.size() << " broken links in " << pages << " pages:" << joined(broken);
}

TEST(DocsLinks, TheReadmeLinksEveryDocsPage) {
  const fs::path root(WEFT_SOURCE_DIR);
  std::ifstream in(root / "README.md");
  std::stringstream readme;
  readme << in.rdbuf();
  std::vector<std::string> unlinked;
  for (const auto& entry : fs::directory_iterator(root / "docs")) {
    if (entry.path().extension() != ".md") continue;
    const std::string target = "](docs/" + entry.path().filename().string() + ")";
    if (readme.str().find(target) == std::string::npos) unlinked.push_back(entry.path().filename().string());
  }
  EXPECT_TRUE(unlinked.empty()) << "docs pages the README does not link:" << joined(unlinked);
}

TEST(DocsLinks, TheCheckFindsAMissingFileAndAMissingHeading) {
  const fs::path dir = fs::temp_directory_path() / ("weft-docs-links-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  fs::create_directories(dir / "docs");
  std::ofstream(dir / "docs" / "page.md") << "# Page\n\n## Overrides: `--set PATH=VALUE`\n\n## Figure 4.5 — not reproduced\n\n## Twice\n\n## Twice\n";
  std::ofstream(dir / "README.md")
      << "# Weft\n\n"
         "[ok](docs/page.md) [ok](docs/page.md#overrides---set-pathvalue) [ok](docs/page.md#figure-45--not-reproduced)\n"
         "[ok](docs/page.md#twice-1) [ok](#weft) ![ok](docs) [web](https://example.org/none.md)\n"
         "`[not a link](nowhere.md)`\n"
         "```\n[not a link](nowhere.md)\n```\n"
         "[bad](docs/missing.md)\n"
         "[bad](docs/page.md#no-such-heading)\n"
         "[bad](#twice-2)\n";
  const std::vector<std::string> broken = brokenLinks(dir / "README.md", dir);
  fs::remove_all(dir);
  ASSERT_EQ(broken.size(), 3u) << joined(broken);
  EXPECT_EQ(broken[0], "README.md:9: docs/missing.md (no such file)");
  EXPECT_EQ(broken[1], "README.md:10: docs/page.md#no-such-heading (no such heading)");
  EXPECT_EQ(broken[2], "README.md:11: #twice-2 (no such heading)");
}

}  // namespace
