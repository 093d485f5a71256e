// Memory for buffers that grow with a string, step after step. A buffer of a
// megabyte or more is pages of its own (mmap): growing it moves its pages
// (mremap) instead of copying them, and the pages already written stay
// faulted in, so a buffer that grows with the string is faulted in once, not
// at every step. Smaller buffers come from malloc.
#pragma once

#include <algorithm>
#include <cstddef>

namespace sylva::page_memory {

constexpr std::size_t kPage = 4096;
constexpr std::size_t kMappedFrom = std::size_t{1} << 20;

inline bool is_mapped(std::size_t capacity) { return capacity >= kMappedFrom; }
inline std::size_t whole_pages(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }

// A mapped buffer's pages, to be given back to the system before it is
// freed; nothing for a buffer from malloc.
struct Pages {
  unsigned char* data = nullptr;
  std::size_t bytes = 0;
};
// Gives the whole pages within bytes [from, to) of `pages` back to the
// system, as freeing the buffer would (they read as zeros after). Freeing a
// large buffer's pages is the kernel's work on the thread that frees it:
// threads giving back disjoint stretches first share it.
void release(const Pages& pages, std::size_t from, std::size_t to);

// A buffer of at least `capacity` bytes; `capacity` becomes its size (whole
// pages for a mapped one). Throws std::bad_alloc.
unsigned char* allocate(std::size_t& capacity);
void free(void* data, std::size_t capacity);
// `data` (of `capacity` bytes, the first `used` of them to keep) moved to a
// buffer of at least `wanted` bytes; `wanted` becomes the new capacity. A
// mapped buffer keeps all its bytes and pages.
unsigned char* reallocate(unsigned char* data, std::size_t capacity, std::size_t used, std::size_t& wanted);

// An array of a trivially copyable T in such memory, for what is rebuilt at
// every step of a growing string: room grows by half again when it runs
// short, and the pages written stay faulted in.
template <class T>
class GrowingArray {
 public:
  GrowingArray() = default;
  ~GrowingArray() { page_memory::free(data_, capacity_ * sizeof(T)); }
  GrowingArray(const GrowingArray&) = delete;
  GrowingArray& operator=(const GrowingArray&) = delete;

  // Room for at least `count` elements, whose values are then undefined:
  // nothing is copied when the array moves from malloc's memory to pages of
  // its own, so the fresh pages are faulted in by the threads that fill them.
  void make_room(std::size_t count) {
    if (count <= capacity_) return;
    std::size_t bytes = std::max(count, capacity_ + capacity_ / 2) * sizeof(T);
    data_ = reinterpret_cast<T*>(
        reallocate(reinterpret_cast<unsigned char*>(data_), capacity_ * sizeof(T), /*used=*/0, bytes));
    capacity_ = bytes / sizeof(T);
  }
  T* get() const { return data_; }
  Pages pages() const {
    const std::size_t bytes = capacity_ * sizeof(T);
    return is_mapped(bytes) ? Pages{reinterpret_cast<unsigned char*>(data_), bytes} : Pages{};
  }
  T& operator[](std::size_t k) const { return data_[k]; }

 private:
  T* data_ = nullptr;
  std::size_t capacity_ = 0;
};

}  // namespace sylva::page_memory
