# `cmake --install` and the exported CMake package `pvatt`: the FMI 2.0 runtime (fmus/), the FMI 2.0
# headers (fmi2/), the CVODE wrapper it steps Co-Simulation with (integrator/) and add_fmu(), so that a
# block can be written and packed into an .fmu outside this tree (examples/battery_heater, built against
# the installed package by the test Package.OutOfTreeBlock); and the master's engine, so that a program
# outside this tree can run a system (examples/run_system, test Package.OutOfTreeEngine). The layout is
# described in docs/package.md.
include(CMakePackageConfigHelpers)

install(TARGETS fmi2_headers fmi3_headers fmi_vocabulary time_rule cvode_integrator fmu_model fmu_runtime_objects
  fmu_runtime3_objects fmu_description_writer fmu_describe_main
  EXPORT pvattTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/pvatt/objects
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY fmus/include/fmu fmi2/include/fmi2 fmi3/include/fmi3 fmus/vocabulary/include/fmi fmus/time_rule/include/time_rule integrator/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp")
install(FILES ${CMAKE_BINARY_DIR}/fmus_runtime/generated/fmu/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fmu)
# The master's engine (pvatt::engine: systems from .ssd/.ssp, their execution, observers) with what it
# stands on: the FMU loader, the hardware bridge's wire protocol and the CVODE wrapper above. Left out of a
# developer's subset build without harness/.
if(TARGET pvatt_engine)
  # Installed under the names this tree's aliases give them: pvatt::engine, pvatt::protocol.
  set_target_properties(pvatt_engine PROPERTIES EXPORT_NAME engine)
  set_target_properties(pvatt_protocol PROPERTIES EXPORT_NAME protocol)
  install(TARGETS pvatt_engine fmi_loader pvatt_protocol EXPORT pvattTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(DIRECTORY harness/engine/include/engine harness/fmi_loader/include/fmi_loader protocol/include/protocol
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
  set(PVATT_ENGINE ON)
else()
  set(PVATT_ENGINE OFF)
endif()

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/pvatt)
install(EXPORT pvattTargets NAMESPACE pvatt:: DESTINATION ${config_dir})
configure_package_config_file(cmake/pvattConfig.cmake.in ${CMAKE_BINARY_DIR}/pvattConfig.cmake
  INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/pvattConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/pvattConfig.cmake ${CMAKE_BINARY_DIR}/pvattConfigVersion.cmake
  fmus/add_fmu.cmake fmus/fmu.map fmus/fmu3.map DESTINATION ${config_dir})
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/pvatt)
