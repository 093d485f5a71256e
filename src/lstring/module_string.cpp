#include "lstring/module_string.h"

#include <sys/mman.h>

#include <cstdlib>
#include <new>

namespace sylva {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Strings of millions of modules live in huge pages where the system allows
// it: a fresh buffer is touched once per step, and 4 KiB pages make the page
// faults cost as much as the derivation.
unsigned char* allocate_bytes(std::size_t& capacity) {
  void* data = nullptr;
  if (capacity >= 4 * kHugePage) {
    capacity = (capacity + kHugePage - 1) / kHugePage * kHugePage;
    data = std::aligned_alloc(kHugePage, capacity);
    if (data) madvise(data, capacity, MADV_HUGEPAGE);
  } else {
    data = std::malloc(capacity);
  }
  if (!data) throw std::bad_alloc();
  return static_cast<unsigned char*>(data);
}

std::size_t grown_capacity(std::size_t current, std::size_t needed) {
  std::size_t capacity = current ? current : 256;
  while (capacity < needed) capacity += capacity / 2 + 64;
  return capacity;
}

void grow_buffer(abi::ModuleBuffer* b, std::size_t min_capacity) {
  std::size_t capacity = grown_capacity(b->capacity, min_capacity);
  unsigned char* data = allocate_bytes(capacity);
  if (b->size) std::memcpy(data, b->data, b->size);
  std::free(b->data);
  b->data = data;
  b->capacity = capacity;
}

}  // namespace

ModuleString::ModuleString() { buffer_.grow = &grow_buffer; }

ModuleString::~ModuleString() { std::free(buffer_.data); }

ModuleString::ModuleString(ModuleString&& other) noexcept : buffer_(other.buffer_) {
  other.buffer_.data = nullptr;
  other.buffer_.size = other.buffer_.capacity = 0;
}

ModuleString& ModuleString::operator=(ModuleString&& other) noexcept {
  if (this != &other) {
    std::free(buffer_.data);
    buffer_ = other.buffer_;
    other.buffer_.data = nullptr;
    other.buffer_.size = other.buffer_.capacity = 0;
  }
  return *this;
}

void ModuleString::reserve(std::size_t bytes) {
  if (bytes > buffer_.capacity) grow_buffer(&buffer_, bytes);
}

void ModuleString::append_module(ModuleId id, const void* params, std::size_t param_size) {
  buffer_.reserve_more(param_size + abi::kModuleOverhead);
  buffer_.put_id(id);
  if (param_size) std::memcpy(buffer_.data + buffer_.size, params, param_size);
  buffer_.size += param_size;
  buffer_.put_id(id);
}

void ModuleString::assign(const unsigned char* bytes, std::size_t n) {
  reserve(n);
  std::memcpy(buffer_.data, bytes, n);
  buffer_.size = n;
}

std::size_t ModuleString::count_modules(const ModuleTypes& types) const {
  std::size_t count = 0;
  StringView v = view(types);
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) ++count;
  return count;
}

PrependBuffer::~PrependBuffer() { std::free(data_); }

void PrependBuffer::grow(std::size_t needed) {
  std::size_t used = capacity_ - begin_;
  std::size_t capacity = grown_capacity(capacity_, used + needed);
  unsigned char* data = allocate_bytes(capacity);
  if (used) std::memcpy(data + capacity - used, data_ + begin_, used);
  std::free(data_);
  data_ = data;
  begin_ = capacity - used;
  capacity_ = capacity;
}

}  // namespace sylva
