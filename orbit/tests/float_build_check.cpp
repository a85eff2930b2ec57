// Compiled with -fno-exceptions -fno-rtti (CMakeLists.txt): the float SGP4 and TEME -> J2000 the firmware
// uses must build as the Cortex-M4F firmware builds them. Nothing runs this; the build is the check.
#include "orbit/frames.hpp"
#include "orbit/sgp4.hpp"

namespace orbit {
template class Sgp4<float>;
template OrbitState<float> teme_to_j2000(const OrbitState<float>&, float, int) noexcept;
}  // namespace orbit
