// Linked into the fuzz targets that build a World from a shipped scene (scene_overrides,
// world_step): the two loaders of asset files, loadClosedObj (tools, obstacles) and loadObjMesh
// (OBJ cloths), each read a file once per process and then answer from a cache. The linker sends
// every call of them from core to the __wrap_ functions below (-Wl,--wrap, fuzz/CMakeLists.txt).
//
// Why: an input of these targets names an asset (a path under assets/) but never holds its bytes,
// so every execution parsed the same few files again; that was a tenth of a scene_overrides unit
// (tinyobjloader, the closed-surface check). The loaders themselves are fuzzed on mutated bytes by
// obj_cloth and closed_obj. A call is still made for every asset the input names, with the
// input's path and UV scale, and answers as the loader did: the same mesh, or the same
// InputError for a file that is not a valid asset (a preset's JSON, a missing file).
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "mesh/obj_import.h"
#include "rigid/closed_obj_import.h"

// The mangled names are the loaders' (nm fuzz/libweft_fuzz_loaders.a); a changed signature
// leaves __wrap_ undefined and the link fails, so they cannot silently go stale.
weft::TriangleMesh realLoadClosedObj(const std::filesystem::path& path) __asm__(
    "__real__ZN4weft13loadClosedObjERKNSt10filesystem7__cxx114pathE");
weft::TriangleMesh wrapLoadClosedObj(const std::filesystem::path& path) __asm__(
    "__wrap__ZN4weft13loadClosedObjERKNSt10filesystem7__cxx114pathE");
weft::ClothMesh realLoadObjMesh(const weft::ObjSpec& spec, const std::string& referencingFile,
                                weft::ObjVertexMap* outVertexMap) __asm__(
    "__real__ZN4weft11loadObjMeshERKNS_7ObjSpecERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEEPNS_12ObjVertexMapE");
weft::ClothMesh wrapLoadObjMesh(const weft::ObjSpec& spec, const std::string& referencingFile,
                                weft::ObjVertexMap* outVertexMap) __asm__(
    "__wrap__ZN4weft11loadObjMeshERKNS_7ObjSpecERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEEPNS_12ObjVertexMapE");

namespace {

template <typename T>
struct Loaded {
  std::optional<T> value;
  std::exception_ptr error;

  const T& get() const {
    if (error) std::rethrow_exception(error);
    return *value;
  }
};

template <typename T, typename Load>
Loaded<T> loadOnce(Load load) {
  Loaded<T> loaded;
  try {
    loaded.value = load();
  } catch (...) {
    loaded.error = std::current_exception();
  }
  return loaded;
}

struct ObjCloth {
  weft::ClothMesh mesh;
  weft::ObjVertexMap vertexMap;
};

}  // namespace

weft::TriangleMesh wrapLoadClosedObj(const std::filesystem::path& path) {
  static std::map<std::string, Loaded<weft::TriangleMesh>> cache;
  auto it = cache.find(path.string());
  if (it == cache.end()) {
    it = cache.emplace(path.string(), loadOnce<weft::TriangleMesh>([&] { return realLoadClosedObj(path); })).first;
  }
  return it->second.get();
}

weft::ClothMesh wrapLoadObjMesh(const weft::ObjSpec& spec, const std::string& referencingFile,
                                weft::ObjVertexMap* outVertexMap) {
  // The referencing file is part of the key: the loader's messages name it.
  using Key = std::tuple<std::string, double, std::string>;
  static std::map<Key, Loaded<ObjCloth>> cache;
  const Key key{spec.path.string(), spec.uvScale, referencingFile};
  auto it = cache.find(key);
  if (it == cache.end()) {
    it = cache.emplace(key, loadOnce<ObjCloth>([&] {
                ObjCloth cloth;
                cloth.mesh = realLoadObjMesh(spec, referencingFile, &cloth.vertexMap);
                return cloth;
              })).first;
  }
  const ObjCloth& cloth = it->second.get();
  if (outVertexMap != nullptr) *outVertexMap = cloth.vertexMap;
  return cloth.mesh;
}
