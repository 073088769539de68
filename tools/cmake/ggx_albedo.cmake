# The albedo tables of ggx_conductor's multiple-scattering compensation and of openpbr's layering, computed at build time by a small
# program over the reference's GGX terms (engine/reference/ggx_albedo_table.cpp) and written as a C++ header: the
# reference reads it, and engine/brdf_tables uploads it into the kernels' table buffer (shared/brdf_tables.h).
# Sets RAYLAB_GGX_ALBEDO_INCLUDE, the directory that holds generated/ggx_albedo.h; the target raylab_ggx_albedo
# orders its users after it.
function(raylab_generate_ggx_albedo)
  set(out ${PROJECT_BINARY_DIR}/ggx_albedo)
  add_executable(raylab_ggx_albedo_table ${PROJECT_SOURCE_DIR}/engine/reference/ggx_albedo_table.cpp
                                         ${PROJECT_SOURCE_DIR}/engine/reference/ggx.cpp
                                         ${PROJECT_SOURCE_DIR}/engine/reference/sampling.cpp
                                         ${PROJECT_SOURCE_DIR}/engine/reference/terms.cpp)
  target_include_directories(raylab_ggx_albedo_table PRIVATE ${PROJECT_SOURCE_DIR}/engine ${PROJECT_SOURCE_DIR}/shaders)
  target_link_libraries(raylab_ggx_albedo_table PRIVATE glm::glm)
  add_custom_command(
    OUTPUT ${out}/generated/ggx_albedo.h
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out}/generated
    COMMAND raylab_ggx_albedo_table ${out}/generated/ggx_albedo.h
    DEPENDS raylab_ggx_albedo_table
    COMMENT "Tabulating GGX's directional albedo"
    VERBATIM)
  add_custom_target(raylab_ggx_albedo DEPENDS ${out}/generated/ggx_albedo.h)
  set(RAYLAB_GGX_ALBEDO_INCLUDE ${out} PARENT_SCOPE)
endfunction()
