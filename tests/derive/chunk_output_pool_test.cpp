// The buffers a parallel pass's chunks write into: each thread gets back the
// one it took last, a new one comes with the room asked for, and every one
// comes empty.
#include <gtest/gtest.h>
#include <sys/mman.h>

#include <memory>
#include <thread>
#include <vector>

#include "derive/chunk_output_pool.h"
#include "lstring/page_memory.h"
#include "test_support.h"

namespace sylva::derive {
namespace {

using Output = ChunkOutputPool::Output;

void fill(Output& output, int modules) {
  for (int k = 0; k < modules; ++k) output.string.append_module(0, nullptr, 0);
}

TEST(ChunkOutputPool, ANewBufferHasTheRoomAskedFor) {
  ChunkOutputPool pool;
  const std::unique_ptr<Output> output = pool.take(1 << 20);
  EXPECT_GE(output->string.reserved_bytes(), std::size_t{1} << 20);
  EXPECT_TRUE(output->string.empty());
  EXPECT_EQ(pool.size(), 0u);
}

// A new buffer is mapped, so its pages fault in a stretch at a time, but
// only what the part is expected to take is faulted in: a whole megabyte per
// new buffer made the first parallel step of a run slower than a serial one.
TEST(ChunkOutputPool, ANewBufferFaultsInOnlyTheRoomAskedFor) {
  if (!test::kernel_populates_pages()) GTEST_SKIP() << "this kernel cannot fault in a stretch of pages at once";
  ChunkOutputPool pool;
  const std::unique_ptr<Output> output = pool.take(100 << 10);
  const std::size_t mapped = output->string.reserved_bytes();
  ASSERT_GE(mapped, std::size_t{1} << 20);
  std::vector<unsigned char> pages(mapped / 4096);
  ASSERT_EQ(mincore(const_cast<unsigned char*>(output->string.data()), mapped, pages.data()), 0);
  std::size_t resident = 0;
  for (unsigned char page : pages) resident += page & 1;
  EXPECT_GE(resident, std::size_t{25});  // 100 KiB
  EXPECT_LE(resident, std::size_t{32});
}

// The pages the pool names are those its buffers faulted in: giving them
// back leaves none in memory, so freeing the buffers afterwards finds none.
TEST(ChunkOutputPool, NamesThePagesItsBuffersFaultedIn) {
  if (!test::kernel_populates_pages()) GTEST_SKIP() << "this kernel cannot fault in a stretch of pages at once";
  ChunkOutputPool pool;
  std::unique_ptr<Output> output = pool.take(100 << 10);
  const unsigned char* data = output->string.data();
  const std::size_t mapped = output->string.reserved_bytes();
  pool.give_back(std::move(output));
  const std::vector<sylva::page_memory::Pages> pages = pool.pages();
  ASSERT_EQ(pages.size(), 1u);
  EXPECT_EQ(pages[0].data, data);
  EXPECT_GE(pages[0].bytes, std::size_t{100} << 10);
  EXPECT_LT(pages[0].bytes, mapped);
  auto resident = [&] {
    std::vector<unsigned char> in(mapped / 4096);
    EXPECT_EQ(mincore(const_cast<unsigned char*>(data), mapped, in.data()), 0);
    std::size_t n = 0;
    for (unsigned char page : in) n += page & 1;
    return n;
  };
  EXPECT_GE(resident(), std::size_t{25});
  sylva::page_memory::release(pages[0], 0, pages[0].bytes);
  EXPECT_EQ(resident(), 0u);
}

TEST(ChunkOutputPool, AThreadGetsBackTheBufferItTookLast) {
  ChunkOutputPool pool;
  std::unique_ptr<Output> mine = pool.take(64);
  std::unique_ptr<Output> theirs;
  std::thread([&] { theirs = pool.take(64); }).join();
  const Output* mine_was = mine.get();
  const Output* theirs_was = theirs.get();
  fill(*mine, 10);
  // Given back in this order, the last one in is the other thread's.
  pool.give_back(std::move(mine));
  pool.give_back(std::move(theirs));
  const std::unique_ptr<Output> again = pool.take(64);
  EXPECT_EQ(again.get(), mine_was);
  EXPECT_TRUE(again->string.empty());
  // Where the pool has none of a thread's own, it takes another's.
  std::unique_ptr<Output> other;
  std::thread([&] { other = pool.take(64); }).join();
  EXPECT_EQ(other.get(), theirs_was);
}

TEST(ChunkOutputPool, KeepsAtMostWhatItIsTold) {
  ChunkOutputPool pool;
  for (int k = 0; k < 5; ++k) pool.give_back(std::make_unique<Output>());
  pool.keep_at_most(2);
  EXPECT_EQ(pool.size(), 2u);
  pool.keep_at_most(3);
  EXPECT_EQ(pool.size(), 2u);
}

}  // namespace
}  // namespace sylva::derive
