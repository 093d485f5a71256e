#include "lstring/page_memory.h"

#include <sys/mman.h>

#include <cstdlib>
#include <cstring>
#include <new>

namespace sylva::page_memory {

unsigned char* allocate(std::size_t& capacity) {
  void* data = nullptr;
  if (is_mapped(capacity)) {
    capacity = whole_pages(capacity);
    data = mmap(nullptr, capacity, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (data == MAP_FAILED) throw std::bad_alloc();
  } else {
    data = std::malloc(capacity);
    if (!data) throw std::bad_alloc();
  }
  return static_cast<unsigned char*>(data);
}

void free(void* data, std::size_t capacity) {
  if (!data) return;
  if (is_mapped(capacity)) munmap(data, capacity);
  else std::free(data);
}

void release(const Pages& pages, std::size_t from, std::size_t to) {
  from = whole_pages(from);
  to = std::min(to, pages.bytes) / kPage * kPage;
  if (pages.data && to > from) madvise(pages.data + from, to - from, MADV_DONTNEED);
}

unsigned char* reallocate(unsigned char* data, std::size_t capacity, std::size_t used, std::size_t& wanted) {
  if (data && is_mapped(capacity)) {
    wanted = whole_pages(wanted);
    void* moved = mremap(data, capacity, wanted, MREMAP_MAYMOVE);
    if (moved == MAP_FAILED) throw std::bad_alloc();
    return static_cast<unsigned char*>(moved);
  }
  unsigned char* fresh = allocate(wanted);
  if (used) std::memcpy(fresh, data, used);
  free(data, capacity);
  return fresh;
}

}  // namespace sylva::page_memory
