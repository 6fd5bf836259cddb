#pragma once
// Working memory an object reuses from call to call, which is not part of its state: a copy of
// the object starts with an empty one (the editor's timeline copies the world at every frame, and
// a lattice or a buffer kept only to avoid allocating each call must not be copied with it, nor
// counted in heapBytes). Reuse matters for large buffers: glibc serves blocks above 128 KB by mmap,
// so allocating one every step also costs its pages' faults.
namespace weft {

template <typename T>
struct Scratch {
  T value;
  Scratch() = default;
  Scratch(const Scratch&) {}
  Scratch& operator=(const Scratch&) { return *this; }
  Scratch(Scratch&&) = default;
  Scratch& operator=(Scratch&&) = default;
};

}  // namespace weft
