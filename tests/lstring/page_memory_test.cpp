// Arrays that grow with a string (the branch index's) copy nothing when they
// grow, and the pages written before a growth move with them: an index
// rebuilt at every step faults in only what it grew by, on the threads that
// fill it. Residency is checked with
// mincore, faults with getrusage.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/resource.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lstring/page_memory.h"

namespace sylva::test {
namespace {

constexpr std::size_t kPage = page_memory::kPage;

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

std::size_t resident_pages(const void* at, std::size_t bytes) {
  std::vector<unsigned char> in((bytes + kPage - 1) / kPage);
  EXPECT_EQ(mincore(const_cast<void*>(at), bytes, in.data()), 0);
  std::size_t n = 0;
  for (unsigned char page : in) n += page & 1;
  return n;
}

TEST(GrowingArray, MovingToPagesOfItsOwnTouchesNone) {
  constexpr std::size_t kSmall = (900 << 10) / 4;  // 900 KiB of 4-byte words: from malloc
  constexpr std::size_t kMapped = std::size_t{1} << 20;  // 4 MiB: mapped
  page_memory::GrowingArray<std::uint32_t> array;
  array.make_room(kSmall);
  for (std::uint32_t k = 0; k < kSmall; ++k) array[k] = k;
  array.make_room(kMapped);
  // Its values are rebuilt after a growth: copying the 900 KiB would fault in
  // 225 pages on this thread, before the threads that fill them could.
  EXPECT_EQ(resident_pages(array.get(), kMapped * 4), 0u);
  for (std::size_t k = 0; k < kMapped; ++k) array[k] = static_cast<std::uint32_t>(3 * k);
  array.make_room(kMapped + 1);  // mapped to mapped
  for (std::size_t k = 0; k < kMapped; k += 4099) ASSERT_EQ(array[k], 3 * k) << k;
}

TEST(GrowingArray, PagesWrittenStayInMemoryWhenItGrows) {
  constexpr std::size_t kWords = std::size_t{1} << 18;  // 2 MiB of 8-byte words
  page_memory::GrowingArray<std::uint64_t> array;
  array.make_room(kWords);
  madvise(array.get(), kWords * 8, MADV_NOHUGEPAGE);  // page by page, as the count below assumes
  ASSERT_EQ(resident_pages(array.get(), kWords * 8), 0u);
  for (std::size_t k = 0; k < kWords; ++k) array[k] = k;
  ASSERT_EQ(resident_pages(array.get(), kWords * 8), kWords * 8 / kPage);
  const long faults_before = minor_faults();
  array.make_room(4 * kWords);
  // The pages written moved with the array, not copied into fresh ones
  // (512 faults); the rest are untouched.
  EXPECT_LT(minor_faults() - faults_before, 64);
  EXPECT_EQ(resident_pages(array.get(), kWords * 8), kWords * 8 / kPage);
  EXPECT_EQ(resident_pages(array.get() + kWords, 3 * kWords * 8), 0u);
  EXPECT_EQ(array[kWords - 1], kWords - 1);
}

}  // namespace
}  // namespace sylva::test
