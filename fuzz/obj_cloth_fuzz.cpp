// libFuzzer target: the OBJ cloth loader (mesh/obj_import.h) on arbitrary bytes, written to a
// file as a scene's mesh would be. Any input must give a valid cloth mesh or an InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_file.h"
#include "mesh/mesh_check.h"
#include "mesh/obj_import.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  weft::ObjSpec spec;
  spec.path = weft::fuzz::writeInput(data, size, "cloth.obj");
  try {
    weft::ObjVertexMap map;
    const weft::ClothMesh mesh = weft::loadObjMesh(spec, "fuzz.json", &map);
    // A mesh that loads is a valid cloth and every cloth vertex is some `v` line's.
    if (!weft::checkMesh(mesh).empty()) std::abort();
    std::size_t mapped = 0;
    for (const auto& ids : map.clothVertices) mapped += ids.size();
    if (mapped != static_cast<std::size_t>(mesh.vertexCount())) std::abort();
  } catch (const weft::InputError& e) {
    if (std::string(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
