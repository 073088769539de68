# The emitter-type registry's machinery (docs/extending.md). raylab_light() registers one type of light for next
# event estimation; kind ids follow the order of registration. raylab_generate_light_registry() writes, at
# configure time (only when the content changes, so nothing rebuilds otherwise):
#   light_registry/generated/light_kinds.h         kLight<Name> ids, kLightKindCount and the delta kinds, for
#                                                  C++ and GLSL alike, and the kinds' names for C++
#   light_registry/generated/light_dispatch.glsl   sampleLightKind and lightKindPdf over every registered type
# and sets RAYLAB_LIGHT_REGISTRY_INCLUDE, the directory both compilers search.

# raylab_light(<name> PREFIX <functionPrefix> GLSL <file under shaders/> [DELTA])
# The GLSL file defines <prefix>LightSample(LightRecord, vec3 x, vec3 u) and, unless DELTA (a point or a direction
# that no ray can hit), <prefix>LightPdf(LightRecord, vec3 x, vec3 wi, vec3 y).
function(raylab_light name)
  cmake_parse_arguments(arg "DELTA" "PREFIX;GLSL" "" ${ARGN})
  if(NOT arg_PREFIX OR NOT arg_GLSL)
    message(FATAL_ERROR "raylab_light(${name}): PREFIX and GLSL are required")
  endif()
  if(NOT EXISTS ${PROJECT_SOURCE_DIR}/shaders/${arg_GLSL})
    message(FATAL_ERROR "raylab_light(${name}): shaders/${arg_GLSL} does not exist")
  endif()
  set(delta 0)
  if(arg_DELTA)
    set(delta 1)
  endif()
  set_property(GLOBAL APPEND PROPERTY RAYLAB_LIGHTS "${name}|${arg_PREFIX}|${arg_GLSL}|${delta}")
endfunction()

# point -> Point, area_sphere -> AreaSphere: the suffix of the kind's constant.
function(raylab_light_constant_suffix name out)
  string(REPLACE "_" ";" words ${name})
  set(result "")
  foreach(word IN LISTS words)
    string(SUBSTRING ${word} 0 1 first)
    string(SUBSTRING ${word} 1 -1 rest)
    string(TOUPPER ${first} first)
    string(APPEND result "${first}${rest}")
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

function(raylab_generate_light_registry)
  get_property(lights GLOBAL PROPERTY RAYLAB_LIGHTS)
  set(out ${PROJECT_BINARY_DIR}/light_registry)
  set(ids "")
  set(names "")
  set(includes "")
  set(samples "")
  set(pdfs "")
  set(deltaBits 0)
  set(id 0)
  foreach(entry IN LISTS lights)
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 name)
    list(GET fields 1 prefix)
    list(GET fields 2 glsl)
    list(GET fields 3 delta)
    raylab_light_constant_suffix(${name} suffix)
    string(APPEND ids "RL_CONST uint kLight${suffix} = ${id};\n")
    string(APPEND names "    \"${name}\",\n")
    string(APPEND includes "#include \"${glsl}\"\n")
    string(APPEND samples
           "  if (lightKindEnabled(kLight${suffix}) && light.kind == kLight${suffix}) return ${prefix}LightSample(light, x, u);\n")
    if(delta)
      math(EXPR deltaBits "${deltaBits} | (1 << ${id})")
    else()
      string(APPEND pdfs
             "  if (lightKindEnabled(kLight${suffix}) && light.kind == kLight${suffix}) return ${prefix}LightPdf(light, x, wi, y);\n")
    endif()
    math(EXPR id "${id} + 1")
  endforeach()
  set(header "// Generated from shaders/lights/lights.cmake by tools/cmake/light_registry.cmake: edit those, not this.")
  file(CONFIGURE OUTPUT ${out}/generated/light_kinds.h @ONLY CONTENT
"@header@
// LightRecord.kind: the types of light next event estimation samples, in registration order.
#ifndef RAYLAB_GENERATED_LIGHT_KINDS_H
#define RAYLAB_GENERATED_LIGHT_KINDS_H

#include \"shared/compat.h\"

RL_NAMESPACE_BEGIN

@ids@RL_CONST uint kLightKindCount = @id@;
// Bit (1 << kind) per delta light (a point or a direction: no ray hits it, so nothing weighs it by MIS).
RL_CONST uint kDeltaLightKinds = @deltaBits@u;

RL_NAMESPACE_END

#ifdef __cplusplus
namespace raylab::gpu {
// The registered names, by kind: what `raylab info`, Python and the docs call each type.
inline constexpr const char* kLightKindNames[] = {
@names@};
}  // namespace raylab::gpu
#endif

#endif
")
  file(CONFIGURE OUTPUT ${out}/generated/light_dispatch.glsl @ONLY CONTENT
"@header@
// Next event estimation's dispatch over the light kinds: each kind's sample and density (shaders/lights/*.glsl).
#ifndef RAYLAB_GENERATED_LIGHT_DISPATCH_GLSL
#define RAYLAB_GENERATED_LIGHT_DISPATCH_GLSL

@includes@
LightSample sampleLightKind(LightRecord light, vec3 x, vec3 u) {
@samples@  return noLightSample();
}

// Delta kinds have no density a continuation could meet: 0.
float lightKindPdf(LightRecord light, vec3 x, vec3 wi, vec3 y) {
@pdfs@  return 0.0;
}

#endif
")
  set(RAYLAB_LIGHT_REGISTRY_INCLUDE ${out} PARENT_SCOPE)
endfunction()
