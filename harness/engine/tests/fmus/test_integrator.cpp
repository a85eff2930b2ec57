#include "test_blocks.hpp"
FMU_BLOCK(cosim_test::Integrator)
