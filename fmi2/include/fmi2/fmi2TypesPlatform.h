/* FMI 2.0 platform types (FMI 2.0.4 standard, section 2.1.2), written for this project from the
 * standard's text. The standard fixes these typedefs for the "default" platform; an importer and an
 * FMU must agree on them, so nothing here may change. */
#ifndef FMI2_TYPES_PLATFORM_H
#define FMI2_TYPES_PLATFORM_H

/* The platform string an FMU reports through fmi2GetTypesPlatform. */
#define fmi2TypesPlatform "default"

/* Opaque handles: an instance, the importer's environment pointer, a saved FMU state. */
typedef void* fmi2Component;
typedef void* fmi2ComponentEnvironment;
typedef void* fmi2FMUstate;

typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean; /* fmi2True or fmi2False, an int for C compatibility */
typedef char fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char fmi2Byte; /* serialized FMU states are arrays of bytes */

#define fmi2True 1
#define fmi2False 0

#endif
