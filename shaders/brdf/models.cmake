# The BRDF model registry: one entry per model, in id order. A model is its GLSL file (lobe flags, parameter
# table, <prefix>Eval/Pdf/Sample or <prefix>DeltaEvent) and its double-precision reference file; everything
# else (dispatch, parameter table, CLI, viewer, Python, tests, tools) derives from these entries
# (tools/cmake/brdf_registry.py, docs/extending.md). Scenes name models, never ids: the order may change.
set(reference ${PROJECT_SOURCE_DIR}/engine/reference/models)
raylab_brdf_model(lambert PREFIX lambert GLSL brdf/lambert.glsl REFERENCE ${reference}/lambert.cpp)
raylab_brdf_model(phong PREFIX phong GLSL brdf/phong.glsl REFERENCE ${reference}/phong.cpp)
raylab_brdf_model(blinnphong PREFIX blinnPhong GLSL brdf/blinnphong.glsl REFERENCE ${reference}/blinnphong.cpp)
raylab_brdf_model(cooktorrance PREFIX cookTorrance GLSL brdf/cooktorrance.glsl REFERENCE ${reference}/cooktorrance.cpp)
raylab_brdf_model(ward PREFIX ward GLSL brdf/ward.glsl REFERENCE ${reference}/ward.cpp)
raylab_brdf_model(ward_duer PREFIX wardDuer GLSL brdf/ward_duer.glsl REFERENCE ${reference}/ward_duer.cpp)
raylab_brdf_model(ward_gmd PREFIX wardGmd GLSL brdf/ward_gmd.glsl REFERENCE ${reference}/ward_gmd.cpp)
raylab_brdf_model(ashikhmin_shirley PREFIX ashikhminShirley GLSL brdf/ashikhmin_shirley.glsl
                  REFERENCE ${reference}/ashikhmin_shirley.cpp)
raylab_brdf_model(glass PREFIX glass GLSL brdf/glass.glsl REFERENCE ${reference}/glass.cpp)
raylab_brdf_model(oren_nayar PREFIX orenNayar GLSL brdf/oren_nayar.glsl REFERENCE ${reference}/oren_nayar.cpp)
raylab_brdf_model(eon PREFIX eon GLSL brdf/eon.glsl REFERENCE ${reference}/eon.cpp)
raylab_brdf_model(gltf_pbr PREFIX gltfPbr GLSL brdf/gltf_pbr.glsl REFERENCE ${reference}/gltf_pbr.cpp)
raylab_brdf_model(ggx_conductor PREFIX ggxConductor GLSL brdf/ggx_conductor.glsl REFERENCE ${reference}/ggx_conductor.cpp)
raylab_brdf_model(ggx_dielectric PREFIX ggxDielectric GLSL brdf/ggx_dielectric.glsl REFERENCE ${reference}/ggx_dielectric.cpp)
raylab_brdf_model(measured PREFIX measured GLSL brdf/measured.glsl REFERENCE ${reference}/measured.cpp)
raylab_brdf_model(lafortune PREFIX lafortune GLSL brdf/lafortune.glsl REFERENCE ${reference}/lafortune.cpp)
raylab_brdf_model(abc_microfacet PREFIX abcMicrofacet GLSL brdf/abc_microfacet.glsl REFERENCE ${reference}/abc_microfacet.cpp)
raylab_brdf_model(sgd PREFIX sgd GLSL brdf/sgd.glsl REFERENCE ${reference}/sgd.cpp)
raylab_brdf_model(abc_smooth PREFIX abcSmooth GLSL brdf/abc_smooth.glsl REFERENCE ${reference}/abc_smooth.cpp)
raylab_brdf_model(nbrdf PREFIX nbrdf GLSL brdf/nbrdf.glsl REFERENCE ${reference}/nbrdf.cpp)
raylab_brdf_model(openpbr PREFIX openpbr GLSL brdf/openpbr.glsl REFERENCE ${reference}/openpbr.cpp)
