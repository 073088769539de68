// Constants shared by the BRDF library.
#ifndef RAYLAB_BRDF_COMMON_GLSL
#define RAYLAB_BRDF_COMMON_GLSL

const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;

#endif
