#pragma once
// Following a list of named things (a scene's cloths, its obstacles) across an edit that may have
// removed, inserted or reordered them: what the editor keeps per cloth or per obstacle (a painted
// strength map, a tool's tags) stays with its own, not with whatever now has its index.
#include <string>
#include <vector>

namespace weft::editor {

// For each of `before`'s entries, its index in `after` (-1: gone), aligning the two lists on their
// longest common subsequence: a removal or an insertion moves only what follows it, and of two
// entries of one name, each keeps its own place.
std::vector<int> alignByName(const std::vector<std::string>& before, const std::vector<std::string>& after);

}  // namespace weft::editor
