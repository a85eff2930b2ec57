// The runtime's bouncing ball (closed-form state events) as an FMU for the master's tests.
#include "../../../../fmus/tests/test_blocks.hpp"
FMU_BLOCK(fmu_test::Ball)
