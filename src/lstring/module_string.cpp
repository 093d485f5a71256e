#include "lstring/module_string.h"

#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "lstring/run_limits.h"

namespace sylva {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::atomic<std::size_t> bytes_in_use{0};  // by every string's buffer

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
  bytes_in_use.fetch_add(capacity, std::memory_order_relaxed);
  return static_cast<unsigned char*>(data);
}

void free_bytes(void* data, std::size_t capacity) {
  if (!data) return;
  std::free(data);
  bytes_in_use.fetch_sub(capacity, std::memory_order_relaxed);
}

std::size_t grown_capacity(std::size_t current, std::size_t needed) {
  std::size_t capacity = current ? current : 256;
  while (capacity < needed) capacity += capacity / 2 + 64;
  return capacity;
}

void grow_buffer(abi::ModuleBuffer* b, std::size_t min_capacity) {
  std::size_t capacity = grown_capacity(b->capacity, min_capacity);
  if (const RunBudget* budget = RunBudget::active()) {
    // Near the memory limit a string grows by what it needs, not by half.
    capacity = std::max(min_capacity, std::min(capacity, budget->affordable(capacity)));
    budget->check_time();
    budget->check_modules(b->data, b->size);
    budget->check_memory(capacity);
  }
  unsigned char* data = allocate_bytes(capacity);
  if (b->size) std::memcpy(data, b->data, b->size);
  free_bytes(b->data, b->capacity);
  b->data = data;
  b->capacity = capacity;
}

}  // namespace

std::size_t string_bytes_in_use() { return bytes_in_use.load(std::memory_order_relaxed); }

ModuleString::ModuleString() { buffer_.grow = &grow_buffer; }

ModuleString::~ModuleString() { free_bytes(buffer_.data, buffer_.capacity); }

ModuleString::ModuleString(ModuleString&& other) noexcept : buffer_(other.buffer_) {
  other.buffer_.data = nullptr;
  other.buffer_.size = other.buffer_.capacity = 0;
}

ModuleString& ModuleString::operator=(ModuleString&& other) noexcept {
  if (this != &other) {
    free_bytes(buffer_.data, buffer_.capacity);
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
  buffer_.reserve_more(abi::encoded_module_size(param_size));
  buffer_.put_id(id);
  if (!param_size) return;
  std::memcpy(buffer_.data + buffer_.size, params, param_size);
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

PrependBuffer::~PrependBuffer() { free_bytes(data_, capacity_); }

void PrependBuffer::grow(std::size_t needed) {
  std::size_t used = capacity_ - begin_;
  std::size_t capacity = grown_capacity(capacity_, used + needed);
  if (const RunBudget* budget = RunBudget::active()) {
    budget->check_time();
    budget->check_memory(capacity);
  }
  unsigned char* data = allocate_bytes(capacity);
  if (used) std::memcpy(data + capacity - used, data_ + begin_, used);
  free_bytes(data_, capacity_);
  data_ = data;
  begin_ = capacity - used;
  capacity_ = capacity;
}

}  // namespace sylva
