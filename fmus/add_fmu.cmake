# add_fmu(<name> SOURCES <files...> [LIBRARIES <targets...>] [OUTPUT_DIR <dir>] [OUTPUT_DIR3 <dir>])
#
# <name> is the model identifier, the folder, the shared library and the .fmu (one name everywhere).
# Makes the block's FMI 2.0 archive and, from the same table, its FMI 3.0 archive:
#   <name>_model     static library of the block's sources (what its unit tests link)
#   <name>           the FMU binary <name>.so: the block plus the FMI runtime, only fmi2* exported
#   <name>_describe  the build-time writer of modelDescription.xml and documentation/index.html
#   <name>_fmu       ${PVATT_FMU_DIR}/<name>.fmu (or OUTPUT_DIR, for test FMUs), built by default; its
#                    binary without debug information, which stays in fmu_binaries/<name>.so.debug
#   <name>_fmi3      the FMI 3.0 binary fmu_binaries3/<name>.so: the block plus the runtime's FMI 3.0
#                    layer, only fmi3* exported
#   <name>_fmu3      ${PVATT_FMU3_DIR}/<name>.fmu (or OUTPUT_DIR3; OUTPUT_DIR/fmi3 beside a test's
#                    OUTPUT_DIR): binaries/x86_64-linux/<name>.so, the FMI 3.0 modelDescription.xml
# The same function serves this tree and a project built on the installed package (find_package(pvatt),
# examples/battery_heater): it names the runtime's targets as pvatt::..., FMU_VERSION_SCRIPT and
# PVATT_FMU_DIR come from the tree or from pvattConfig.cmake.
function(add_fmu name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR;OUTPUT_DIR3" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_OUTPUT_DIR3)
    if(ARG_OUTPUT_DIR)
      set(ARG_OUTPUT_DIR3 ${ARG_OUTPUT_DIR}/fmi3)
    else()
      set(ARG_OUTPUT_DIR3 ${PVATT_FMU3_DIR})
    endif()
  endif()
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${PVATT_FMU_DIR})
  endif()

  add_library(${name}_model STATIC ${ARG_SOURCES})
  target_link_libraries(${name}_model PUBLIC pvatt::fmu_model ${ARG_LIBRARIES})
  # Linked into the FMU's shared library: position-independent whatever the including project sets.
  set_target_properties(${name}_model PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    POSITION_INDEPENDENT_CODE ON)

  add_library(${name} SHARED $<TARGET_OBJECTS:pvatt::fmu_runtime_objects>)
  target_link_libraries(${name} PRIVATE ${name}_model)
  set_target_properties(${name} PROPERTIES PREFIX "" OUTPUT_NAME ${name}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fmu_binaries)
  target_link_options(${name} PRIVATE -Wl,--version-script=${FMU_VERSION_SCRIPT} -Wl,--no-undefined)
  if(NOT PVATT_SANITIZE)
    # A host such as MATLAB may bring an older C++ runtime; carry our own, kept local by fmu.map.
    target_link_options(${name} PRIVATE -static-libstdc++ -static-libgcc)
    # Only what the exported entry points reach: the static C++ runtime's unused members and sections
    # would otherwise be unpacked from the archive and mapped at every load. (Not under the sanitizers,
    # whose instrumented globals are not worth the risk for a test build's load time.)
    target_link_options(${name} PRIVATE -Wl,--gc-sections)
  endif()

  add_executable(${name}_describe $<TARGET_OBJECTS:pvatt::fmu_describe_main>)
  target_link_libraries(${name}_describe PRIVATE ${name}_model pvatt::fmu_description_writer)

  set(stage ${CMAKE_BINARY_DIR}/fmu_staging/${name})
  set(fmu_file ${ARG_OUTPUT_DIR}/${name}.fmu)
  add_custom_command(
    OUTPUT ${fmu_file}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${stage}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${stage}/binaries/linux64 ${ARG_OUTPUT_DIR}
    COMMAND $<TARGET_FILE:${name}_describe> ${stage}
    # The archive carries the code without debug information (a smaller archive, a faster extraction
    # at every load); the debug information stays beside the build's own copy, found by its debuglink.
    COMMAND ${CMAKE_OBJCOPY} --only-keep-debug $<TARGET_FILE:${name}> $<TARGET_FILE:${name}>.debug
    COMMAND ${CMAKE_OBJCOPY} --strip-debug --add-gnu-debuglink=$<TARGET_FILE:${name}>.debug
            $<TARGET_FILE:${name}> ${stage}/binaries/linux64/${name}.so
    COMMAND ${CMAKE_COMMAND} -E rm -f ${fmu_file}
    COMMAND ${CMAKE_COMMAND} -E chdir ${stage}
            ${CMAKE_COMMAND} -E tar cf ${fmu_file} --format=zip modelDescription.xml binaries documentation
    DEPENDS ${name} ${name}_describe
    COMMENT "Packing ${name}.fmu"
    VERBATIM)
  add_custom_target(${name}_fmu ALL DEPENDS ${fmu_file})

  # The FMI 3.0 archive: the same block and description tool, the FMI 3.0 entry points.
  add_library(${name}_fmi3 SHARED $<TARGET_OBJECTS:pvatt::fmu_runtime3_objects>)
  target_link_libraries(${name}_fmi3 PRIVATE ${name}_model)
  set_target_properties(${name}_fmi3 PROPERTIES PREFIX "" OUTPUT_NAME ${name}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fmu_binaries3)
  target_link_options(${name}_fmi3 PRIVATE -Wl,--version-script=${FMU3_VERSION_SCRIPT} -Wl,--no-undefined)
  if(NOT PVATT_SANITIZE)
    target_link_options(${name}_fmi3 PRIVATE -static-libstdc++ -static-libgcc)
    target_link_options(${name}_fmi3 PRIVATE -Wl,--gc-sections)
  endif()
  set(stage3 ${CMAKE_BINARY_DIR}/fmu_staging3/${name})
  set(fmu3_file ${ARG_OUTPUT_DIR3}/${name}.fmu)
  add_custom_command(
    OUTPUT ${fmu3_file}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${stage3}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${stage3}/binaries/x86_64-linux ${ARG_OUTPUT_DIR3}
    COMMAND $<TARGET_FILE:${name}_describe> ${stage3} 3.0
    COMMAND ${CMAKE_OBJCOPY} --only-keep-debug $<TARGET_FILE:${name}_fmi3> $<TARGET_FILE:${name}_fmi3>.debug
    COMMAND ${CMAKE_OBJCOPY} --strip-debug --add-gnu-debuglink=$<TARGET_FILE:${name}_fmi3>.debug
            $<TARGET_FILE:${name}_fmi3> ${stage3}/binaries/x86_64-linux/${name}.so
    COMMAND ${CMAKE_COMMAND} -E rm -f ${fmu3_file}
    COMMAND ${CMAKE_COMMAND} -E chdir ${stage3}
            ${CMAKE_COMMAND} -E tar cf ${fmu3_file} --format=zip modelDescription.xml binaries documentation
    DEPENDS ${name}_fmi3 ${name}_describe
    COMMENT "Packing ${name}.fmu (FMI 3.0)"
    VERBATIM)
  add_custom_target(${name}_fmu3 ALL DEPENDS ${fmu3_file})
endfunction()
