/* A shared object exporting a chosen subset of the FMI 2.0 names, so the loader's symbol resolution
 * and missing-symbol report can be tested without a real FMU. Only fmi2GetVersion and
 * fmi2GetTypesPlatform are ever called; every other symbol only has to exist. */
#include "fmi2/fmi2FunctionTypes.h"

#define EXPORT __attribute__((visibility("default")))
#define PRESENT(name)       \
    EXPORT int name(void) { \
        return fmi2Error;   \
    }

EXPORT const char* fmi2GetVersion(void) {
    return "2.0";
}
EXPORT const char* fmi2GetTypesPlatform(void) {
    return "default";
}
PRESENT(fmi2SetDebugLogging)
PRESENT(fmi2Instantiate)
PRESENT(fmi2FreeInstance)
PRESENT(fmi2SetupExperiment)
PRESENT(fmi2EnterInitializationMode)
PRESENT(fmi2ExitInitializationMode)
PRESENT(fmi2Terminate)
PRESENT(fmi2GetReal)
PRESENT(fmi2GetInteger)
PRESENT(fmi2GetBoolean)
PRESENT(fmi2SetReal)
PRESENT(fmi2SetInteger)
PRESENT(fmi2SetBoolean)
PRESENT(fmi2SetString)
PRESENT(fmi2GetFMUstate)
PRESENT(fmi2SetFMUstate)
PRESENT(fmi2FreeFMUstate)
PRESENT(fmi2SerializedFMUstateSize)
PRESENT(fmi2SerializeFMUstate)
PRESENT(fmi2DeSerializeFMUstate)
PRESENT(fmi2GetDirectionalDerivative)
#ifndef PARTIAL
PRESENT(fmi2Reset)
PRESENT(fmi2GetString)
#endif
/* The Co-Simulation set; the Model Exchange set is left out on purpose. */
PRESENT(fmi2SetRealInputDerivatives)
PRESENT(fmi2GetRealOutputDerivatives)
PRESENT(fmi2DoStep)
PRESENT(fmi2CancelStep)
PRESENT(fmi2GetStatus)
PRESENT(fmi2GetRealStatus)
PRESENT(fmi2GetIntegerStatus)
PRESENT(fmi2GetBooleanStatus)
PRESENT(fmi2GetStringStatus)
