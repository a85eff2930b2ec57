// The ball block as this test binary's model (fmu::make_model).
#include "test_blocks.hpp"

FMU_BLOCK(fmu_test::Ball)
