// The L-system string: modules packed one after another as
// [id][parameters][id], or [id] without parameters (see sylva/abi.h), so it
// can be walked both ways with nothing but the table of module sizes.
#pragma once

#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

#include "lstring/module_types.h"
#include "lstring/page_memory.h"
#include "sylva/abi.h"

namespace sylva {

class BranchPartners;
class PrependBuffer;

// Reading an encoded string.
inline ModuleId module_id_at(const unsigned char* data, std::size_t offset) { return abi::leading_id(data + offset); }
// The id of the module that ends at `offset`.
inline ModuleId module_id_before(const unsigned char* data, std::size_t offset) {
  return abi::trailing_id(data + offset);
}
inline const unsigned char* module_params(const unsigned char* data, std::size_t offset) {
  return data + offset + (data[offset] != abi::kWideId ? 1 : 3);
}
inline unsigned char* module_params(unsigned char* data, std::size_t offset) {
  return const_cast<unsigned char*>(module_params(static_cast<const unsigned char*>(data), offset));
}

// Whether string buffers of several megabytes ask for transparent huge pages
// (off by default). Huge pages make a derivation's page faults cheaper where
// the system keeps free huge pages at hand; on virtual machines that hand
// free memory back to their host each one is faulted in afresh, and the
// derivation is slower with them. Applies to buffers allocated from then on.
void use_huge_pages(bool on);

// A read-only range of a string: modules between `begin` and `end` (byte offsets).
struct StringView {
  const unsigned char* data = nullptr;
  std::size_t begin = 0;
  std::size_t end = 0;
  const std::uint32_t* sizes = nullptr;  // encoded size by module id
  bool ring = false;  // context matching wraps around: first and last modules are neighbours
  // Where the branches of `data` open and close, when indexed (never for a
  // ring); context matching then skips a branch without walking it.
  const BranchPartners* branches = nullptr;

  ModuleId id_at(std::size_t offset) const { return module_id_at(data, offset); }
  std::size_t next(std::size_t offset) const { return offset + sizes[id_at(offset)]; }
  std::size_t previous(std::size_t offset) const { return offset - sizes[module_id_before(data, offset)]; }
};

// A string's buffer as the engine keeps it. A large buffer is mapped with
// room to grow (`reserved`), and its `capacity`, all a compiled model sees,
// ends where the pages already faulted in end: a model appending past it
// calls `grow`, which faults in the next stretch with one call instead of a
// fault per page.
struct OwnedModuleBuffer : abi::ModuleBuffer {
  std::size_t reserved = 0;  // bytes allocated; capacity <= reserved
};

// An owned, growable string of modules.
class ModuleString {
 public:
  ModuleString();
  ~ModuleString();
  ModuleString(ModuleString&& other) noexcept;
  ModuleString& operator=(ModuleString&& other) noexcept;
  ModuleString(const ModuleString&) = delete;
  ModuleString& operator=(const ModuleString&) = delete;
  // Exchanges buffers and notes: what three moves would do, without their
  // releasing and resetting. Decomposition swaps a level's successor into
  // place once per chain it expands, which made the moves 5% of a run.
  friend void swap(ModuleString& a, ModuleString& b) noexcept {
    std::swap(a.buffer_, b.buffer_);
    a.known_starts_.swap(b.known_starts_);
  }

  const unsigned char* data() const { return buffer_.data; }
  // For writing parameters in place (answers to query and communication modules).
  unsigned char* data_for_writing() { return buffer_.data; }
  std::size_t size_bytes() const { return buffer_.size; }
  bool empty() const { return buffer_.size == 0; }

  // Where compiled models append modules.
  abi::ModuleBuffer* buffer() { return &buffer_; }

  void clear() {
    buffer_.size = 0;
    known_starts_.clear();
  }
  void truncate(std::size_t size) {  // inline: a rule that produces nothing truncates
    buffer_.size = size;
    if (!known_starts_.empty()) forget_starts_from(size);
  }
  void reserve(std::size_t bytes);
  void append(const unsigned char* bytes, std::size_t n) {
    buffer_.reserve_more(n);
    std::memcpy(buffer_.data + buffer_.size, bytes, n);
    buffer_.size += n;
  }
  void append_module(ModuleId id, const void* params, std::size_t param_size);

  // Writing in place: a parallel pass copies its chunks' parts of the next
  // string straight into its buffer, each once the parts before it are
  // written. Maps `bytes` for this string without faulting them in (the
  // writers do that), and empties it.
  void reserve_unwritten(std::size_t bytes);
  // The same, keeping the bytes written so far (they may move, at the same
  // offsets from data()).
  void reserve_unwritten_keeping(std::size_t bytes);
  std::size_t reserved_bytes() const { return buffer_.reserved; }
  // Bytes the string can take before its buffer grows: in a mapped buffer,
  // where the pages faulted in end.
  std::size_t ready_bytes() const { return buffer_.capacity; }
  // Faults in at once the pages of bytes [from, to) of a mapped buffer
  // (see grow_buffer), before a part of the string is copied there.
  void fault_in(std::size_t from, std::size_t to);
  // The first `size` bytes were written in place.
  void set_written_size(std::size_t size);
  // The pages of a mapped buffer that may be in memory: those faulted in.
  page_memory::Pages faulted_in_pages() const;

  // Offsets known to start modules, in order, or none: some of the starts a
  // pass noted as it wrote the string, and where a parallel pass joined its
  // parts. The next parallel pass cuts the string near them rather than
  // walking it to find module boundaries: a walk is serial, and on many
  // threads walking a string took longer than rewriting it. Appending keeps
  // them; what replaces or cuts the string drops them.
  const std::vector<std::size_t>& known_module_starts() const { return known_starts_; }
  void set_known_module_starts(std::vector<std::size_t> starts) { known_starts_ = std::move(starts); }
  // Notes that a module starts where the string now ends, unless one was
  // noted less than `spacing` bytes before.
  void note_module_start(std::size_t spacing) {
    if (known_starts_.empty() || buffer_.size - known_starts_.back() >= spacing) known_starts_.push_back(buffer_.size);
  }
  // Takes a copy of `n` bytes of modules.
  void assign(const unsigned char* bytes, std::size_t n);
  // Takes what `built` holds, buffer and all, moved to its start; `built`
  // goes on with this string's buffer, emptied. Backward derivation ends a
  // step so, without copying the new string into a buffer of its own.
  void take(PrependBuffer& built);

  StringView view(const ModuleTypes& types) const {
    return StringView{buffer_.data, 0, buffer_.size, types.encoded_sizes()};
  }
  std::size_t count_modules(const ModuleTypes& types) const;

 private:
  void grow_unwritten(std::size_t bytes, std::size_t kept);
  void forget_starts_from(std::size_t size);

  OwnedModuleBuffer buffer_;
  std::vector<std::size_t> known_starts_;
};

// A buffer filled from its end toward its start: backward derivation builds
// the new string this way, so the part already built is contiguous and can be
// read as new right context.
class PrependBuffer {
 public:
  PrependBuffer() = default;
  ~PrependBuffer();
  PrependBuffer(const PrependBuffer&) = delete;
  PrependBuffer& operator=(const PrependBuffer&) = delete;

  void clear() { begin_ = capacity_; }
  // Room for `bytes` more before what is built, so that building them moves
  // nothing.
  void reserve_more(std::size_t bytes) {
    if (bytes > begin_) grow(bytes);
  }
  void prepend(const unsigned char* bytes, std::size_t n) {
    if (n > begin_) grow(n);
    begin_ -= n;
    std::memcpy(data_ + begin_, bytes, n);
  }
  const unsigned char* data() const { return data_; }
  std::size_t begin() const { return begin_; }
  std::size_t end() const { return capacity_; }
  std::size_t size_bytes() const { return capacity_ - begin_; }

 private:
  friend class ModuleString;  // take()
  void grow(std::size_t needed);
  unsigned char* data_ = nullptr;
  std::size_t begin_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace sylva
