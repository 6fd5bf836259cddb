#pragma once
// The order a participant of `weft guess` sees the clips in. The thesis shuffled its clips for
// every run of the study (§3.4) so that the order would not sway the answers; here the shuffle is
// seeded, so a participant's order can be told again (and tested): by default the seed comes from
// the participant's id, so two participants see different orders and one participant always the
// same.
#include <cstdint>
#include <string_view>
#include <vector>

namespace weft::study {

// The participant's seed: the 64-bit FNV-1a hash of the id's bytes (offset basis
// 14695981039346656037, prime 1099511628211, as published by Fowler, Noll and Vo).
std::uint64_t seedOfParticipant(std::string_view participant);

// A permutation of 0 .. count-1: Fisher-Yates driven by std::mt19937_64 (whose output the
// standard fixes), not std::shuffle (whose algorithm it does not), so the order is the same with
// every standard library. Each draw is `engine() % (i + 1)`: biased by less than 2^-58 here.
std::vector<int> shuffledOrder(int count, std::uint64_t seed);

}  // namespace weft::study
