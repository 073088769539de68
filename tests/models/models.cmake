# Models that live in the test tree, registered in test builds only (RAYLAB_BUILD_TESTS): they exercise the
# procedure of docs/extending.md, and every per-model test (parity, chi2 sampling on the CPU and the device,
# albedo quadrature, reciprocity, the parameter tables) covers them without an edit.
raylab_brdf_model(minnaert PREFIX minnaert GLSL minnaert.glsl GLSL_ROOT ${CMAKE_CURRENT_LIST_DIR}
                  REFERENCE minnaert.cpp)
