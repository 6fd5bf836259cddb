// libFuzzer target: the sharp-tag loader (rigid/sharp_tags.h) on arbitrary bytes, read against the
// sword's mesh (assets/tools/sword.obj, 434 vertices) as a tool's tags beside its OBJ are. Any input
// must give tags in canonical form that name vertices and edges of the mesh, or an InputError.
// Anything else is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz_file.h"
#include "rigid/closed_obj_import.h"
#include "rigid/sharp_tags.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const weft::TriangleMesh sword =
      weft::loadClosedObj(std::filesystem::path(WEFT_SOURCE_DIR) / "assets" / "tools" / "sword.obj");
  static const std::vector<std::array<int, 2>> swordEdges = weft::undirectedEdges(sword);
  const std::filesystem::path file = weft::fuzz::writeInput(data, size, "fuzz.sharp.json");
  try {
    const weft::SharpTags tags = weft::loadSharpTags(file, sword);
    const int n = static_cast<int>(sword.vertices.size());
    if (!std::is_sorted(tags.vertices.begin(), tags.vertices.end()) ||
        std::adjacent_find(tags.vertices.begin(), tags.vertices.end()) != tags.vertices.end()) {
      std::abort();
    }
    for (const int v : tags.vertices) {
      if (v < 0 || v >= n) std::abort();
    }
    if (!std::is_sorted(tags.edges.begin(), tags.edges.end()) ||
        std::adjacent_find(tags.edges.begin(), tags.edges.end()) != tags.edges.end()) {
      std::abort();
    }
    for (const auto& e : tags.edges) {
      if (!(e[0] < e[1]) || !std::binary_search(swordEdges.begin(), swordEdges.end(), e)) std::abort();
    }
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
