#pragma once
// The thesis' per-participant study data (Karaoz 2015, §4.5.2), transcribed for the study tests.
#include <array>
#include <vector>

// clang-format off: one subject per line, as the thesis prints them.
namespace weft::study {

using Row = std::array<double, 4>;  // denim, t-shirt, pants, swimsuit (the tables' column order)

// Table 4.11: fabric guessed right (0, 0.5 or 1 for the two denim and two t-shirt clips), subjects 01-14.
inline const std::vector<Row> kTable4_11{
    {0.0, 0.5, 0.0, 1.0},  // subject 01
    {0.5, 0.0, 1.0, 0.0},  // subject 02
    {0.5, 0.5, 0.0, 1.0},  // subject 03
    {0.5, 0.5, 0.0, 1.0},  // subject 04
    {1.0, 0.5, 1.0, 1.0},  // subject 05
    {0.5, 1.0, 0.0, 1.0},  // subject 06
    {0.0, 0.5, 0.0, 1.0},  // subject 07
    {0.0, 0.5, 0.0, 0.0},  // subject 08
    {0.0, 0.0, 1.0, 0.0},  // subject 09
    {0.5, 1.0, 1.0, 1.0},  // subject 10
    {0.0, 0.5, 1.0, 1.0},  // subject 11
    {0.5, 0.0, 1.0, 0.0},  // subject 12
    {0.5, 0.5, 0.0, 0.0},  // subject 13
    {1.0, 0.0, 1.0, 0.0},  // subject 14
};

// Table 4.17: elasticity group guessed right, same layout.
inline const std::vector<Row> kTable4_17{
    {0.5, 0.5, 1.0, 1.0},  // subject 01
    {1.0, 0.5, 1.0, 0.0},  // subject 02
    {0.5, 0.5, 0.0, 1.0},  // subject 03
    {1.0, 0.5, 1.0, 1.0},  // subject 04
    {1.0, 1.0, 1.0, 1.0},  // subject 05
    {1.0, 1.0, 1.0, 1.0},  // subject 06
    {0.5, 1.0, 1.0, 1.0},  // subject 07
    {0.0, 0.5, 0.0, 0.0},  // subject 08
    {0.0, 1.0, 1.0, 1.0},  // subject 09
    {1.0, 1.0, 1.0, 1.0},  // subject 10
    {0.0, 0.5, 1.0, 1.0},  // subject 11
    {1.0, 1.0, 1.0, 1.0},  // subject 12
    {0.5, 0.5, 0.0, 0.0},  // subject 13
    {1.0, 1.0, 1.0, 1.0},  // subject 14
};

// clang-format on
}  // namespace weft::study
