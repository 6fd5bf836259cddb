// libFuzzer target: the obstacle and tool loader (rigid/closed_obj_import.h) on arbitrary bytes,
// written to a file as a scene's `"shape": {"mesh": {"path": ...}}` would name it, then what a
// scene does with a loaded tool: a dynamic body's centre of mass and inertia (mass_properties.h)
// and the collision mesh contact walks. Any input must give a closed, outward, finite solid whose
// mass properties are finite numbers, or an InputError with a short message. Anything else (a
// crash, a sanitizer report, another exception, a broken invariant) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz_file.h"
#include "rigid/closed_obj_import.h"
#include "rigid/closed_surface_check.h"
#include "rigid/mass_properties.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = weft::fuzz::writeInput(data, size, "tool.obj");
  try {
    weft::TriangleMesh mesh = weft::loadClosedObj(file);
    // What the loader promises: a closed, consistently oriented surface around a positive volume.
    if (!weft::closedSurfaceProblems(mesh).empty()) std::abort();
    const double volume = weft::signedVolume(mesh);
    if (!(volume > 0.0) || !std::isfinite(volume)) std::abort();
    // What a dynamic body of 1 kg built from it needs (contact/obstacle.cpp): a centre of mass to
    // move the body frame to, and a finite positive mass and inertia about it.
    (void)weft::recentreAtCentreOfMass(mesh, "tool");
    for (const weft::Vec3& v : mesh.vertices) {
      if (!v.allFinite()) std::abort();
    }
    const double recentredVolume = weft::computeMassProperties(mesh, 1.0, "tool").volume;
    if (!(recentredVolume > 0.0) || !std::isfinite(recentredVolume)) std::abort();
    const weft::MassProperties body = weft::computeMassProperties(mesh, 1.0 / recentredVolume, "tool");
    if (!(body.mass > 0.0) || !std::isfinite(body.mass) || !body.inertia.allFinite()) std::abort();
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
