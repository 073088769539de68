// The scene as every kernel reads it (bindings from shared/bindings.h, records from shared/scene_records.h).
#ifndef RAYLAB_KERNEL_SCENE_BINDINGS_GLSL
#define RAYLAB_KERNEL_SCENE_BINDINGS_GLSL

#include "shared/bindings.h"
#include "shared/scene_records.h"

layout(set = 0, binding = kBindingTlas) uniform accelerationStructureEXT tlas;
layout(set = 0, binding = kBindingInstances, scalar) readonly buffer InstanceBuffer { InstanceRecord instances[]; };
layout(set = 0, binding = kBindingPositions, scalar) readonly buffer PositionBuffer { vec3 positions[]; };
layout(set = 0, binding = kBindingNormals, scalar) readonly buffer NormalBuffer { vec3 normals[]; };
layout(set = 0, binding = kBindingUvs, scalar) readonly buffer UvBuffer { vec2 uvs[]; };
layout(set = 0, binding = kBindingIndices, scalar) readonly buffer IndexBuffer { uint indices[]; };
layout(set = 0, binding = kBindingSpheres, scalar) readonly buffer SphereBuffer { SphereRecord spheres[]; };
layout(set = 0, binding = kBindingMaterials, scalar) readonly buffer MaterialBuffer { MaterialRecord materials[]; };
layout(set = 0, binding = kBindingLights, scalar) readonly buffer LightBuffer { LightRecord lights[]; };
layout(set = 0, binding = kBindingTextures, scalar) readonly buffer TextureBuffer { TextureRecord textures[]; };
layout(set = 0, binding = kBindingTexels, scalar) readonly buffer TexelBuffer { uint texels[]; };
layout(set = 0, binding = kBindingMaterialTextures, scalar) readonly buffer MaterialTextureBuffer {
  MaterialTextures materialTextures[];
};
layout(set = 0, binding = kBindingUvs1, scalar) readonly buffer Uv1Buffer { vec2 uvs1[]; };
layout(set = 0, binding = kBindingTangents, scalar) readonly buffer TangentBuffer { vec4 tangents[]; };
layout(set = 0, binding = kBindingEnvironment, scalar) readonly buffer EnvironmentBuffer {
  EnvironmentHeader environment;
  float environmentData[];
};

#endif
