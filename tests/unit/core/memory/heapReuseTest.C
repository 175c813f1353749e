// Unit test of fdm::keepFreedMemory: a freed 64 MB block stays in the heap
// (the C library's count of free heap bytes holds it) and the next block
// of that size is served from it without growing the heap.

#include "heapReuse.H"
#include <gtest/gtest.h>
#include <malloc.h>
#include <cstdlib>
#include <cstring>

TEST(heapReuse, freedLargeBlockIsKeptAndReused)
{
    ASSERT_TRUE(Foam::fdm::keepFreedMemory());

    const std::size_t size = std::size_t(64) << 20;
    char* block = static_cast<char*>(std::malloc(size));
    ASSERT_NE(block, nullptr);
    std::memset(block, 1, size);
    const std::size_t heapWithBlock = mallinfo2().arena;
    // Not from mmap: the block is part of the heap
    EXPECT_EQ(mallinfo2().hblkhd, std::size_t(0));
    std::free(block);

    // Freed, not returned to the kernel
    EXPECT_GE(mallinfo2().fordblks, size);
    EXPECT_EQ(mallinfo2().arena, heapWithBlock);

    char* again = static_cast<char*>(std::malloc(size));
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(mallinfo2().arena, heapWithBlock);
    std::free(again);
}
