# The emitter-type registry: one entry per type of light that next event estimation samples, in kind order. A
# type is its GLSL file (<prefix>LightSample, and <prefix>LightPdf unless DELTA) and this entry; the dispatch,
# the kind ids, the kernel variants and the names derive from it (tools/cmake/light_registry.cmake,
# docs/extending.md). Where a type's records come from and how much power each carries (the light-selection
# distribution) is engine/render/light_records.cpp.
raylab_light(point PREFIX point GLSL lights/point.glsl DELTA)
raylab_light(spot PREFIX spot GLSL lights/spot.glsl DELTA)
raylab_light(directional PREFIX directional GLSL lights/directional.glsl DELTA)
raylab_light(headlight PREFIX headlight GLSL lights/headlight.glsl DELTA)
raylab_light(triangle PREFIX triangle GLSL lights/triangle.glsl)
raylab_light(sphere PREFIX sphere GLSL lights/sphere.glsl)
raylab_light(environment PREFIX environment GLSL lights/environment.glsl)
