// The host of the test programs' precompiled header (cmake/test_programs.cmake): it only needs to compile.
#include <gtest/gtest.h>

TEST(TestPch, Compiles) {
    SUCCEED();
}
