/* A shared object exporting the FMI 3.0 common and Co-Simulation names (the Model Exchange ones are
 * left out), so the loader's FMI 3.0 symbol resolution and missing-symbol report can be tested without
 * a real FMU. Only fmi3GetVersion is ever called; every other symbol only has to exist. With PARTIAL,
 * two required common names are left out too. */
#include "fmi3/fmi3FunctionTypes.h"

#define EXPORT __attribute__((visibility("default")))
#define PRESENT(name)       \
    EXPORT int name(void) { \
        return fmi3Error;   \
    }

EXPORT const char* fmi3GetVersion(void) {
    return "3.0";
}
PRESENT(fmi3SetDebugLogging)
PRESENT(fmi3FreeInstance)
PRESENT(fmi3EnterInitializationMode)
PRESENT(fmi3ExitInitializationMode)
PRESENT(fmi3EnterEventMode)
PRESENT(fmi3Terminate)
PRESENT(fmi3GetFloat32)
PRESENT(fmi3GetFloat64)
PRESENT(fmi3GetInt8)
PRESENT(fmi3GetUInt8)
PRESENT(fmi3GetInt16)
PRESENT(fmi3GetUInt16)
PRESENT(fmi3GetInt32)
PRESENT(fmi3GetUInt32)
PRESENT(fmi3GetInt64)
PRESENT(fmi3GetUInt64)
PRESENT(fmi3GetBoolean)
PRESENT(fmi3GetString)
PRESENT(fmi3SetFloat32)
PRESENT(fmi3SetFloat64)
PRESENT(fmi3SetInt8)
PRESENT(fmi3SetUInt8)
PRESENT(fmi3SetInt16)
PRESENT(fmi3SetUInt16)
PRESENT(fmi3SetInt32)
PRESENT(fmi3SetUInt32)
PRESENT(fmi3SetInt64)
PRESENT(fmi3SetUInt64)
PRESENT(fmi3SetBoolean)
PRESENT(fmi3SetString)
PRESENT(fmi3SetBinary)
PRESENT(fmi3UpdateDiscreteStates)
PRESENT(fmi3GetFMUState)
PRESENT(fmi3SetFMUState)
PRESENT(fmi3FreeFMUState)
#ifndef PARTIAL
PRESENT(fmi3Reset)
PRESENT(fmi3GetBinary)
#endif
PRESENT(fmi3InstantiateCoSimulation)
PRESENT(fmi3EnterStepMode)
PRESENT(fmi3DoStep)
