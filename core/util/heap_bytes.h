#pragma once
// What a value keeps on the heap, approximately: the capacity of its vectors (and of the vectors
// in them) and a per-allocation overhead. For memory budgets (the editor's timeline keeps a copy
// of the world per frame: World::approximateBytes); never exact, never a hot path.
//
// A struct joins by an overload `std::size_t heapBytes(const T&)` in namespace weft (found by
// argument-dependent lookup), a class with private members by a member `heapBytes()` and an
// overload forwarding to it. Vectors of such values add their elements' heap bytes.
#include <array>
#include <concepts>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace weft {

// Bytes glibc's malloc spends on each block beyond what was asked (its header and rounding),
// roughly: it matters for vectors of many small vectors (the triangles around each vertex).
inline constexpr std::size_t kAllocationOverhead = 16;

template <typename T>
std::size_t heapBytes(const std::vector<T>& v);

template <typename T>
concept HasHeapBytes = requires(const T& t) {
  { heapBytes(t) } -> std::convertible_to<std::size_t>;
};

template <typename T>
std::size_t heapBytes(const std::vector<T>& v) {
  std::size_t bytes = v.capacity() == 0 ? 0 : v.capacity() * sizeof(T) + kAllocationOverhead;
  if constexpr (HasHeapBytes<T>) {
    for (const T& element : v) bytes += heapBytes(element);
  }
  return bytes;
}

template <typename T, std::size_t N>
  requires HasHeapBytes<T>
std::size_t heapBytes(const std::array<T, N>& values) {
  std::size_t bytes = 0;
  for (const T& value : values) bytes += heapBytes(value);
  return bytes;
}

// A node per entry (key, value, next pointer, cached hash) and the bucket array.
template <typename K, typename V>
std::size_t heapBytes(const std::unordered_map<K, V>& map) {
  return map.size() * (sizeof(K) + sizeof(V) + 2 * sizeof(void*) + kAllocationOverhead) +
         map.bucket_count() * sizeof(void*);
}

}  // namespace weft
