#include "guess_order.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>

namespace weft::study {

std::uint64_t seedOfParticipant(std::string_view participant) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : participant) {
    hash ^= byte;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::vector<int> shuffledOrder(int count, std::uint64_t seed) {
  std::vector<int> order(static_cast<std::size_t>(std::max(count, 0)));
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 engine(seed);
  for (int i = count - 1; i > 0; --i) {
    const auto j = static_cast<int>(engine() % static_cast<std::uint64_t>(i + 1));
    std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
  }
  return order;
}

}  // namespace weft::study
