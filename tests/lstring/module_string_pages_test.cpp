// Where a large string's pages are faulted in: with one call for a stretch,
// never page by page as the bytes are written (a page fault traps to the
// hypervisor on a virtual machine), and never twice. Checked with mincore,
// which says which pages of a mapping are in memory.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

#include "lstring/module_string.h"
#include "lstring/page_memory.h"
#include "test_support.h"

namespace sylva::test {
namespace {

constexpr std::size_t kPage = 4096;

// Whether each page of [at, at + bytes) is in memory.
std::vector<bool> resident(const unsigned char* at, std::size_t bytes) {
  std::vector<unsigned char> in((bytes + kPage - 1) / kPage);
  EXPECT_EQ(mincore(const_cast<unsigned char*>(at), bytes, in.data()), 0);
  std::vector<bool> pages;
  for (unsigned char page : in) pages.push_back(page & 1);
  return pages;
}

std::size_t count(const std::vector<bool>& pages) {
  std::size_t n = 0;
  for (bool page : pages) n += page;
  return n;
}

// Appends `bytes` bytes of parameterless modules (id 0, one byte each).
void append_bytes(ModuleString& s, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) s.append_module(0, nullptr, 0);
}

class ModuleStringPages : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!kernel_populates_pages()) GTEST_SKIP() << "this kernel cannot fault in a stretch of pages at once";
    whole_.reserve_unwritten(8 << 20);  // a mapped buffer, nothing faulted in
    ASSERT_EQ(reinterpret_cast<std::uintptr_t>(whole_.data()) % kPage, 0u);
    // Page by page, where the system would otherwise fault in huge pages.
    madvise(whole_.data_for_writing(), 8 << 20, MADV_NOHUGEPAGE);
    ASSERT_EQ(count(resident(whole_.data(), 8 << 20)), 0u);
  }
  ModuleString whole_;
};

// Before a part is copied into the string, its stretch is faulted in at
// once.
TEST_F(ModuleStringPages, AStretchIsFaultedInOnAsking) {
  whole_.fault_in(3 * kPage + 100, 6 * kPage);  // from the page holding its first byte
  const std::vector<bool> pages = resident(whole_.data(), 10 * kPage);
  for (std::size_t p = 0; p < pages.size(); ++p) EXPECT_EQ(pages[p], p >= 3 && p < 6) << "page " << p;
  whole_.fault_in(6 * kPage, 200 << 20);  // not past the buffer
  EXPECT_EQ(count(resident(whole_.data(), 8 << 20)), (8 << 20) / kPage - 3);
}

// A string about to be freed gives its pages back a stretch at a time
// (from the page after `from`'s first byte to the page holding `to`), from
// several threads at once.
TEST_F(ModuleStringPages, PagesAreGivenBackAStretchAtATime) {
  const page_memory::Pages buffer{const_cast<unsigned char*>(whole_.data()), whole_.reserved_bytes()};
  auto release_pages = [&](std::size_t from, std::size_t to) { page_memory::release(buffer, from, to); };
  whole_.fault_in(0, 16 * kPage);
  std::thread other([&] { release_pages(8 * kPage, 12 * kPage); });
  release_pages(2 * kPage + 100, 6 * kPage + 100);
  other.join();
  const std::vector<bool> pages = resident(whole_.data(), 16 * kPage);
  for (std::size_t p = 0; p < pages.size(); ++p)
    EXPECT_EQ(pages[p], !((p >= 3 && p < 6) || (p >= 8 && p < 12))) << "page " << p;
  release_pages(14 * kPage, 200 << 20);  // not past the buffer
  EXPECT_EQ(count(resident(whole_.data(), 8 << 20)), 16u - 3 - 4 - 2);
}

// After a parallel pass the string knows how far its pages are in: as far
// as it was written, rounded up to a page, or as an earlier pass's pages
// went, whichever is further.
TEST_F(ModuleStringPages, AStringWrittenInPlaceKnowsWhereItsPagesEnd) {
  whole_.set_written_size(5 * kPage);  // an earlier pass's string
  whole_.set_written_size(100);
  EXPECT_EQ(whole_.ready_bytes(), 5 * kPage);
  whole_.set_written_size(7 * kPage + 1);
  EXPECT_EQ(whole_.ready_bytes(), 8 * kPage);
}

// A buffer that becomes a mapped one faults in only what it kept: nothing,
// for a string about to be written in place.
TEST(ModuleStringPagesOfNewBuffer, NoneAreInWhenAStringMovesToAMappedBuffer) {
  ModuleString s;
  append_bytes(s, 1000);  // a small buffer, all of it ready
  EXPECT_GE(s.ready_bytes(), 1000u);
  s.reserve_unwritten(4 << 20);
  EXPECT_EQ(s.ready_bytes(), 0u);
}

}  // namespace
}  // namespace sylva::test
