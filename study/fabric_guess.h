#pragma once
// One answer of `weft guess`: the fabric a participant saw in a texture-hidden clip and its
// elasticity group (thesis §4.5.2 asks the first; the group is asked too, so the file records what
// the participant thought rather than what the fabric implies), and the prepared answers of its
// non-interactive mode (`--answers-from FILE`, for tests and for transcribing paper forms).
//
// Answers file: one answer per line, in the order the clips are played; blank lines and lines
// starting with '#' are skipped:
//
//   pants,stiff
//   swimsuit          (no group: the group of the fabric)
#include <string>
#include <vector>

#include "fabric.h"

namespace weft::study {

struct FabricGuess {
  Fabric fabric = Fabric::Denim;
  ElasticityGroup group = ElasticityGroup::Stiff;
};

// Throws InputError naming the file and line for an unknown fabric or group or a malformed line.
std::vector<FabricGuess> readFabricGuesses(const std::string& file);

}  // namespace weft::study
