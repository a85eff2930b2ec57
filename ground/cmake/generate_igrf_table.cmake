# Build-time generator: IGRF14.SHC (data) -> a C++ translation unit holding the 2025.0 main field and the
# 2025-2030 secular variation, so the library (and the FMU built on it) reads no file at run time.
# Usage: cmake -DINPUT=<IGRF14.SHC> -DOUTPUT=<file.cpp> -P generate_igrf_table.cmake
if(NOT INPUT OR NOT OUTPUT)
  message(FATAL_ERROR "generate_igrf_table.cmake needs -DINPUT= and -DOUTPUT=")
endif()

file(STRINGS "${INPUT}" lines)
set(entries "")
set(count 0)
set(previous_key "")
foreach(line IN LISTS lines)
  string(STRIP "${line}" line)
  if(line MATCHES "^#" OR line STREQUAL "")
    continue()
  endif()
  string(REGEX REPLACE "[ \t]+" ";" fields "${line}")
  list(LENGTH fields nfields)
  # Coefficient rows: n, m and 27 epoch values (1900 ... 2030).
  if(NOT nfields EQUAL 29)
    continue()
  endif()
  list(GET fields 0 n)
  list(GET fields 1 m)
  list(GET fields 27 g2025)
  list(GET fields 28 g2030)
  # The SHC file lists g then h for the same (n, m); the second occurrence is h.
  set(key "${n}_${m}")
  if(key STREQUAL previous_key)
    set(kind 1)
  else()
    set(kind 0)
  endif()
  set(previous_key "${key}")
  string(APPEND entries "    {${n}, ${m}, ${kind}, ${g2025}, ${g2030}},\n")
  math(EXPR count "${count} + 1")
endforeach()

if(NOT count EQUAL 195)
  message(FATAL_ERROR "IGRF table: expected 195 coefficients (degree 13), found ${count} in ${INPUT}")
endif()

file(WRITE "${OUTPUT}.tmp"
"// Generated at build time from ground/data/IGRF14.SHC by generate_igrf_table.cmake. Do not edit.\n"
"#include \"ground/igrf_coefficients.hpp\"\n\n"
"namespace ground {\n\n"
"const std::array<IgrfCoefficient, kIgrfCoefficientCount> kIgrf14Coefficients = {{\n"
"${entries}"
"}};\n\n"
"}  // namespace ground\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
