#include "lstring/module_string.h"

#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cstring>

#include "lstring/page_memory.h"
#include "lstring/run_limits.h"

namespace sylva {
namespace {

using page_memory::is_mapped;
using page_memory::kPage;
using page_memory::whole_pages;

constexpr std::size_t kFaultInStep = std::size_t{64} << 10;

std::atomic<std::size_t> bytes_in_use{0};  // by every string's buffer
std::atomic<bool> huge_pages{false};

void advise(void* data, std::size_t capacity) {
  if (is_mapped(capacity) && huge_pages.load(std::memory_order_relaxed)) madvise(data, capacity, MADV_HUGEPAGE);
}

unsigned char* allocate_bytes(std::size_t& capacity) {
  unsigned char* data = page_memory::allocate(capacity);
  advise(data, capacity);
  bytes_in_use.fetch_add(capacity, std::memory_order_relaxed);
  return data;
}

void free_bytes(void* data, std::size_t capacity) {
  if (!data) return;
  page_memory::free(data, capacity);
  bytes_in_use.fetch_sub(capacity, std::memory_order_relaxed);
}

// `data` (of `capacity` bytes, `used` of them in use) moved to a buffer of
// at least `wanted` bytes; `wanted` becomes the new capacity.
unsigned char* reallocate_bytes(unsigned char* data, std::size_t capacity, std::size_t used, std::size_t& wanted) {
  unsigned char* moved = page_memory::reallocate(data, capacity, used, wanted);
  advise(moved, wanted);
  bytes_in_use.fetch_add(wanted, std::memory_order_relaxed);
  if (data) bytes_in_use.fetch_sub(capacity, std::memory_order_relaxed);
  return moved;
}

std::size_t grown_capacity(std::size_t current, std::size_t needed) {
  std::size_t capacity = current ? current : 256;
  while (capacity < needed) capacity += capacity / 2 + 64;
  return capacity;
}

// Faults in the pages of a mapped buffer from where those faulted in end to at
// least `needed` and an eighth of the buffer beyond (64 KiB at least), with
// one call, and returns where they now end. On virtual machines a page fault
// traps to the hypervisor, and faulting a stretch in at once took koch's
// derivation from 1.29 s to about 0.6 s; the eighth keeps what is faulted in
// but unused small, and so does the 64 KiB for a small part written into a
// buffer of its own. Where the kernel cannot (before Linux 5.14) pages fault
// in one by one, as they would anyway.
//
// A call holds the process's memory map for reading until its pages are in,
// and a thread that maps, grows or frees memory waits for it: two koch
// derivations on two threads of one process took 302-314 ms each, against
// 235 ms alone, while one faulted in its 200 MB string with one call. The
// pages are faulted in 4 MiB at a time: 255-271 ms.
void fault_in(unsigned char* at, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::size_t kStretch = std::size_t{4} << 20;
  for (std::size_t done = 0; done < bytes; done += kStretch)
    madvise(at + done, std::min(kStretch, bytes - done), MADV_POPULATE_WRITE);
#endif
}

std::size_t populate(OwnedModuleBuffer& b, std::size_t needed) {
  const std::size_t from = b.capacity / kPage * kPage;
  const std::size_t ahead = std::max(needed, from + std::max(kFaultInStep, from / 8));
  const std::size_t to = std::min(b.reserved, whole_pages(ahead));
  if (to > from) fault_in(b.data + from, to - from);
  return to;
}

// The reservation a buffer of `current` bytes grows to for `needed`.
std::size_t reservation(std::size_t current, std::size_t needed, const RunBudget* budget) {
  std::size_t reserved = grown_capacity(current, needed);
  if (budget) {
    // Near the memory limit a string grows by what it needs, not by half.
    reserved = std::max(needed, std::min(reserved, budget->affordable(reserved)));
    budget->check_memory(reserved);
  }
  return reserved;
}

void grow_buffer(abi::ModuleBuffer* buffer, std::size_t min_capacity) {
  // Every buffer with this function is a ModuleString's.
  OwnedModuleBuffer& b = *static_cast<OwnedModuleBuffer*>(buffer);
  const RunBudget* budget = RunBudget::active();
  if (budget) {
    budget->check_time();
    budget->check_modules(b.data, b.size);
  }
  if (min_capacity > b.reserved) {
    std::size_t reserved = reservation(b.reserved, min_capacity, budget);
    b.data = reallocate_bytes(b.data, b.reserved, b.size, reserved);
    b.reserved = reserved;
  }
  b.capacity = is_mapped(b.reserved) ? populate(b, min_capacity) : b.reserved;
}

void release(OwnedModuleBuffer& b) {
  free_bytes(b.data, b.reserved);
  b.data = nullptr;
  b.size = b.capacity = b.reserved = 0;
}

}  // namespace

std::size_t string_bytes_in_use() { return bytes_in_use.load(std::memory_order_relaxed); }

void use_huge_pages(bool on) { huge_pages.store(on, std::memory_order_relaxed); }

ModuleString::ModuleString() { buffer_.grow = &grow_buffer; }

ModuleString::~ModuleString() { release(buffer_); }

ModuleString::ModuleString(ModuleString&& other) noexcept
    : buffer_(other.buffer_), known_starts_(std::move(other.known_starts_)) {
  other.buffer_.data = nullptr;
  other.buffer_.size = other.buffer_.capacity = other.buffer_.reserved = 0;
}

ModuleString& ModuleString::operator=(ModuleString&& other) noexcept {
  if (this != &other) {
    release(buffer_);
    buffer_ = other.buffer_;
    known_starts_ = std::move(other.known_starts_);
    other.buffer_.data = nullptr;
    other.buffer_.size = other.buffer_.capacity = other.buffer_.reserved = 0;
  }
  return *this;
}

void ModuleString::reserve(std::size_t bytes) {
  if (bytes > buffer_.capacity) grow_buffer(&buffer_, bytes);
}

void ModuleString::forget_starts_from(std::size_t size) {
  while (!known_starts_.empty() && known_starts_.back() >= size) known_starts_.pop_back();
}

void ModuleString::reserve_unwritten(std::size_t bytes) {
  clear();
  if (bytes > buffer_.reserved) grow_unwritten(bytes, 0);
}

void ModuleString::reserve_unwritten_keeping(std::size_t bytes) {
  if (bytes > buffer_.reserved) grow_unwritten(bytes, buffer_.reserved);
}

void ModuleString::grow_unwritten(std::size_t bytes, std::size_t kept) {
  const RunBudget* budget = RunBudget::active();
  if (budget) budget->check_time();
  std::size_t reserved = reservation(buffer_.reserved, bytes, budget);
  const bool was_mapped = is_mapped(buffer_.reserved);
  buffer_.data = reallocate_bytes(buffer_.data, buffer_.reserved, kept, reserved);
  buffer_.reserved = reserved;
  // Mapped pages move with the buffer; into fresh ones only `kept` was copied.
  if (!is_mapped(reserved)) buffer_.capacity = reserved;
  else if (!was_mapped) buffer_.capacity = std::min(reserved, whole_pages(kept));
  else buffer_.capacity = std::min(buffer_.capacity, reserved);
}

void ModuleString::fault_in(std::size_t from, std::size_t to) {
  if (!is_mapped(buffer_.reserved)) return;
  from = from / kPage * kPage;
  to = std::min(to, buffer_.reserved);
  if (to > from) sylva::fault_in(buffer_.data + from, to - from);
}

page_memory::Pages ModuleString::faulted_in_pages() const {
  return is_mapped(buffer_.reserved) ? page_memory::Pages{buffer_.data, buffer_.capacity} : page_memory::Pages{};
}

void ModuleString::set_written_size(std::size_t size) {
  buffer_.size = size;
  // Written means faulted in: the capacity goes on from there.
  const std::size_t written = whole_pages(size);
  buffer_.capacity = std::min(buffer_.reserved, std::max(buffer_.capacity, written));
}

void ModuleString::append_module(ModuleId id, const void* params, std::size_t param_size) {
  buffer_.reserve_more(abi::encoded_module_size(id, param_size));
  unsigned char* at = buffer_.data + buffer_.size;
  abi::put_encoded_module(at, id, params, param_size);
  buffer_.size = static_cast<std::size_t>(at - buffer_.data);
}

void ModuleString::assign(const unsigned char* bytes, std::size_t n) {
  known_starts_.clear();
  reserve(n);
  std::memcpy(buffer_.data, bytes, n);
  buffer_.size = n;
}

void ModuleString::take(PrependBuffer& built) {
  const std::size_t n = built.size_bytes();
  if (n && built.begin_) std::memmove(built.data_, built.data_ + built.begin_, n);
  unsigned char* old_data = buffer_.data;
  const std::size_t old_reserved = buffer_.reserved;
  buffer_.data = built.data_;
  buffer_.reserved = buffer_.capacity = built.capacity_;  // PrependBuffer::grow faulted it all in
  buffer_.size = n;
  known_starts_.clear();
  built.data_ = old_data;
  built.capacity_ = built.begin_ = old_reserved;
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
  // The free front will be filled before the buffer grows again: fault it in
  // at once (see populate).
  if (is_mapped(capacity)) fault_in(data, capacity);
  if (used) std::memcpy(data + capacity - used, data_ + begin_, used);
  free_bytes(data_, capacity_);
  data_ = data;
  begin_ = capacity - used;
  capacity_ = capacity;
}

}  // namespace sylva
