// The BRDF library's precomputed tables (shared/brdf_tables.h): one read-only buffer at kBindingBrdfTables, which
// every kernel that includes the library binds (engine/brdf_tables).
#ifndef RAYLAB_BRDF_BRDF_TABLES_GLSL
#define RAYLAB_BRDF_BRDF_TABLES_GLSL

#extension GL_EXT_scalar_block_layout : require

#include "shared/bindings.h"
#include "shared/brdf_tables.h"

layout(set = 0, binding = kBindingBrdfTables, scalar) readonly buffer BrdfTables { float brdfTables[]; };

// 1 - E and 1 - E_avg of single-scattering GGX with F = 1 at table entry i.
float ggxAlbedoLossEntry(uint i) { return brdfTables[kGgxAlbedoOffset + i]; }
float ggxAverageLossEntry(uint i) { return brdfTables[kGgxAlbedoAverageOffset + i]; }

// Where the block of a file parameter's file begins (the parameter holds the block's number, exact in a float).
uint fileBlock(float file) { return floatBitsToUint(brdfTables[kFileDirectoryOffset + uint(file)]); }

#endif
