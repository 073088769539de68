# The BRDF model registry's machinery (docs/extending.md). raylab_brdf_model() registers a model; the ids follow
# the order of registration. raylab_generate_brdf_registry() runs tools/cmake/brdf_registry.py at build time
# over every registered model's GLSL table and sets:
#   RAYLAB_BRDF_GLSL_INCLUDES   -I directories for glslangValidator (the generated dispatch and model folders)
#   RAYLAB_BRDF_GLSL_DISPATCH   the generated GLSL (the dispatch, the opacity), a dependency of every kernel
#   RAYLAB_BRDF_TABLE_SOURCES   the C++ model table, for the parameter library
#   RAYLAB_BRDF_REFERENCE_SOURCES  the models' reference files and the generated reference dispatch
#   RAYLAB_BRDF_REFERENCE_INCLUDE  where the generated reference header lives

# raylab_brdf_model(<name> PREFIX <functionPrefix> GLSL <file> REFERENCE <file> [GLSL_ROOT <dir>])
# GLSL is the include name under GLSL_ROOT (default: shaders/), as kernels #include it.
function(raylab_brdf_model name)
  cmake_parse_arguments(arg "" "PREFIX;GLSL;GLSL_ROOT;REFERENCE" "" ${ARGN})
  if(NOT arg_PREFIX OR NOT arg_GLSL OR NOT arg_REFERENCE)
    message(FATAL_ERROR "raylab_brdf_model(${name}): PREFIX, GLSL and REFERENCE are required")
  endif()
  if(NOT arg_GLSL_ROOT)
    set(arg_GLSL_ROOT ${PROJECT_SOURCE_DIR}/shaders)
  endif()
  cmake_path(ABSOLUTE_PATH arg_REFERENCE BASE_DIRECTORY ${CMAKE_CURRENT_LIST_DIR} NORMALIZE)
  set_property(GLOBAL APPEND PROPERTY RAYLAB_BRDF_MODEL_ARGS
               "--model=${name}\\;${arg_PREFIX}\\;${arg_GLSL}\\;${arg_GLSL_ROOT}/${arg_GLSL}\\;${arg_REFERENCE}")
  set_property(GLOBAL APPEND PROPERTY RAYLAB_BRDF_GLSL_FILES ${arg_GLSL_ROOT}/${arg_GLSL})
  set_property(GLOBAL APPEND PROPERTY RAYLAB_BRDF_GLSL_ROOTS ${arg_GLSL_ROOT})
  set_property(GLOBAL APPEND PROPERTY RAYLAB_BRDF_REFERENCE_FILES ${arg_REFERENCE})
endfunction()

function(raylab_generate_brdf_registry)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  get_property(modelArgs GLOBAL PROPERTY RAYLAB_BRDF_MODEL_ARGS)
  get_property(glslFiles GLOBAL PROPERTY RAYLAB_BRDF_GLSL_FILES)
  get_property(glslRoots GLOBAL PROPERTY RAYLAB_BRDF_GLSL_ROOTS)
  get_property(referenceFiles GLOBAL PROPERTY RAYLAB_BRDF_REFERENCE_FILES)
  list(REMOVE_DUPLICATES glslRoots)
  set(out ${PROJECT_BINARY_DIR}/brdf_registry)
  set(outputs ${out}/glsl/generated/bsdf_models.glsl ${out}/glsl/generated/model_opacity.glsl
              ${out}/cpp/brdf_model_table.cpp
              ${out}/cpp/generated/reference_params.h ${out}/cpp/reference_dispatch.cpp)
  set(script ${PROJECT_SOURCE_DIR}/tools/cmake/brdf_registry.py)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND Python3::Interpreter ${script} --source-dir ${PROJECT_SOURCE_DIR} --out ${out} ${modelArgs}
    DEPENDS ${script} ${glslFiles}
    COMMENT "Expanding the BRDF model registry"
    VERBATIM)
  add_custom_target(raylab_brdf_registry DEPENDS ${outputs})
  set(includes -I${out}/glsl)
  foreach(root IN LISTS glslRoots)
    list(APPEND includes -I${root})
  endforeach()
  set(RAYLAB_BRDF_GLSL_INCLUDES ${includes} PARENT_SCOPE)
  set(RAYLAB_BRDF_GLSL_DISPATCH ${out}/glsl/generated/bsdf_models.glsl ${out}/glsl/generated/model_opacity.glsl
      PARENT_SCOPE)
  set(RAYLAB_BRDF_TABLE_SOURCES ${out}/cpp/brdf_model_table.cpp PARENT_SCOPE)
  set(RAYLAB_BRDF_REFERENCE_SOURCES ${referenceFiles} ${out}/cpp/reference_dispatch.cpp
      ${out}/cpp/generated/reference_params.h PARENT_SCOPE)
  set(RAYLAB_BRDF_REFERENCE_INCLUDE ${out}/cpp PARENT_SCOPE)
endfunction()
