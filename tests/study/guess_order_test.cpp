// The clip order of `weft guess`: a permutation, fixed by the seed, different between participants.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "study/guess_order.h"

namespace weft::study {
namespace {

TEST(GuessOrder, SeedOfParticipantIsFnv1a64) {
  // The published FNV-1a 64-bit test vectors (Fowler, Noll and Vo).
  EXPECT_EQ(seedOfParticipant(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(seedOfParticipant("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(seedOfParticipant("foobar"), 0x85944171f73967e8ull);
}

TEST(GuessOrder, EveryClipAppearsExactlyOnce) {
  for (int count = 0; count <= 12; ++count) {
    for (std::uint64_t seed : {0ull, 1ull, 42ull, 0xffffffffffffffffull}) {
      std::vector<int> order = shuffledOrder(count, seed);
      ASSERT_EQ(static_cast<int>(order.size()), count);
      std::sort(order.begin(), order.end());
      for (int i = 0; i < count; ++i) EXPECT_EQ(order[static_cast<std::size_t>(i)], i) << "count " << count;
    }
  }
}

TEST(GuessOrder, TheSameSeedGivesTheSameOrder) {
  EXPECT_EQ(shuffledOrder(6, 12345), shuffledOrder(6, 12345));
  EXPECT_EQ(shuffledOrder(4, seedOfParticipant("p01")), shuffledOrder(4, seedOfParticipant("p01")));
}

TEST(GuessOrder, OrdersAreTheSameOnEveryStandardLibrary) {
  // mt19937_64's output is fixed by the standard and the shuffle is written out, so these orders
  // hold everywhere. If the algorithm is ever changed on purpose, print the new orders and paste.
  EXPECT_EQ(shuffledOrder(4, 1), (std::vector<int>{1, 2, 3, 0}));
  EXPECT_EQ(shuffledOrder(6, seedOfParticipant("p01")), (std::vector<int>{2, 4, 1, 3, 0, 5}));
}

TEST(GuessOrder, ParticipantsSeeEveryOrderOfFourClips) {
  // 24 orders of four clips; 2000 participants see all of them, none far more often than others.
  std::vector<int> seen(24, 0);
  for (int p = 0; p < 2000; ++p) {
    std::vector<int> order = shuffledOrder(4, seedOfParticipant("p" + std::to_string(p)));
    int rank = 0;
    std::vector<int> rest{0, 1, 2, 3};
    const int factorial[4] = {6, 2, 1, 1};
    for (int k = 0; k < 4; ++k) {
      const auto at = std::find(rest.begin(), rest.end(), order[static_cast<std::size_t>(k)]);
      rank += static_cast<int>(at - rest.begin()) * factorial[k];
      rest.erase(at);
    }
    ++seen[static_cast<std::size_t>(rank)];
  }
  for (int count : seen) {
    EXPECT_GT(count, 40);   // expected 83.3
    EXPECT_LT(count, 135);
  }
}

}  // namespace
}  // namespace weft::study
