# Cross toolchain for the firmware: Debian's gcc-arm-none-eabi with newlib (libnewlib-arm-none-eabi,
# libstdc++-arm-none-eabi-newlib). Bare metal: the compiler checks build a static library, not a program.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
find_program(CMAKE_SIZE arm-none-eabi-size)
