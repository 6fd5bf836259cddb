#pragma once
// The thesis' per-participant study data (Karaoz 2015, §4.5.2), transcribed for the study tests.
#include <array>
#include <vector>

namespace weft::study {

using Row = std::array<double, 4>;  // denim, t-shirt, pants, swimsuit (the tables' column order)

// Table 4.11: fabric guessed right (0, 0.5 or 1 for the two denim and two t-shirt clips), subjects 01-14.
inline const std::vector<Row> kTable4_11{{0.0, 0.5, 0.0, 1.0}, {0.5, 0.0, 1.0, 0.0}, {0.5, 0.5, 0.0, 1.0}, {0.5, 0.5, 0.0, 1.0},
                                  {1.0, 0.5, 1.0, 1.0}, {0.5, 1.0, 0.0, 1.0}, {0.0, 0.5, 0.0, 1.0}, {0.0, 0.5, 0.0, 0.0},
                                  {0.0, 0.0, 1.0, 0.0}, {0.5, 1.0, 1.0, 1.0}, {0.0, 0.5, 1.0, 1.0}, {0.5, 0.0, 1.0, 0.0},
                                  {0.5, 0.5, 0.0, 0.0}, {1.0, 0.0, 1.0, 0.0}};

// Table 4.17: elasticity group guessed right, same layout.
inline const std::vector<Row> kTable4_17{{0.5, 0.5, 1.0, 1.0}, {1.0, 0.5, 1.0, 0.0}, {0.5, 0.5, 0.0, 1.0}, {1.0, 0.5, 1.0, 1.0},
                                  {1.0, 1.0, 1.0, 1.0}, {1.0, 1.0, 1.0, 1.0}, {0.5, 1.0, 1.0, 1.0}, {0.0, 0.5, 0.0, 0.0},
                                  {0.0, 1.0, 1.0, 1.0}, {1.0, 1.0, 1.0, 1.0}, {0.0, 0.5, 1.0, 1.0}, {1.0, 1.0, 1.0, 1.0},
                                  {0.5, 0.5, 0.0, 0.0}, {1.0, 1.0, 1.0, 1.0}};

}  // namespace weft::study
