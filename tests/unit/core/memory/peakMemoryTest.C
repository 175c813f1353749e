// Unit test of fdm::peakResidentBytes: touching a fresh 256 MiB block
// raises the process' peak resident memory to at least that much, and the
// peak stays there when the block is freed (the kernel settles its count
// of the peak at the unmapping, within pages of the value read before).

#include "peakMemory.H"
#include <gtest/gtest.h>
#include <cstdlib>
#include <cstring>

TEST(peakMemory, followsTheLargestResidentSet)
{
    const double before = Foam::fdm::peakResidentBytes();
    ASSERT_GT(before, 0);

    const std::size_t size = std::size_t(256) << 20;
    char* block = static_cast<char*>(std::malloc(size));
    ASSERT_NE(block, nullptr);
    std::memset(block, 1, size);
    const double with = Foam::fdm::peakResidentBytes();
    std::free(block);

    EXPECT_GE(with, double(size));
    EXPECT_GE(with, before);
    EXPECT_GE(Foam::fdm::peakResidentBytes(), double(size));
}
