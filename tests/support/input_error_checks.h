#pragma once
// Bad input is refused with an InputError naming the file and the field: the check every loader
// test makes of each bad case.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/scene_json.h"
#include "util/input_error.h"

namespace weft::test {

// Loading `file` throws an InputError whose message names the file (`fileName`) and mentions
// `mentions`, and whose field starts with `field`. `input` is shown when it does not.
inline void expectLoadRefused(const std::filesystem::path& file, const std::string& fileName, const std::string& field,
                              const std::string& mentions, const std::string& input) {
  try {
    (void)loadScene(file);
    ADD_FAILURE() << "loaded without an InputError: " << input;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fileName), std::string::npos) << what;
    EXPECT_EQ(e.field().rfind(field, 0), 0u) << "field " << e.field() << ", expected " << field << "; " << what;
    EXPECT_NE(what.find(mentions), std::string::npos) << "expected '" << mentions << "' in: " << what;
  }
}

}  // namespace weft::test
