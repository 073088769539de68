// The options of a render, each declared once: its name, values or range, default and help. The command line
// (tools/raylab/cli.cpp), the Python Renderer, the farm's RenderJob and command line (through
// raylab.render_options()), the viewer's panel and its script all read these, so that a name, a range or a
// default is written here and nowhere else. A value becomes an enum once, where it enters
// (render/render_choices.h); this header is plain data, for layers without the renderer.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace raylab {

// An option with named values. The order of `values` is the order of its enum (render/render_choices.h).
struct ChoiceOption {
  std::string_view name;  // as on the command line without "--", and Python's keyword with '_' for '-'
  std::span<const std::string_view> values;
  std::string_view defaultValue;
  std::string_view help;
};

// A count with an inclusive range.
struct CountOption {
  std::string_view name;
  std::uint32_t min;
  std::uint32_t max;
  std::uint32_t defaultValue;
  std::string_view help;
};

inline constexpr std::array<std::string_view, 3> kIntegratorValues = {"auto", "slides", "path"};
inline constexpr ChoiceOption kIntegratorOption{
    "integrator", kIntegratorValues, "auto",
    "slides: equation 2 of the slides (mirror weight, direct light); path: the rendering equation; auto: path when "
    "the scene has an emissive surface or an environment image"};

inline constexpr std::array<std::string_view, 3> kSamplingValues = {"mis", "bsdf", "light"};
inline constexpr ChoiceOption kSamplingOption{
    "sampling", kSamplingValues, "mis",
    "path integrator: how emitters are estimated, MIS of light and BSDF sampling, or one alone"};

inline constexpr std::array<std::string_view, 2> kFresnelValues = {"exact", "schlick"};
inline constexpr ChoiceOption kFresnelOption{
    "fresnel", kFresnelValues, "exact",
    "Fresnel term of glass: exact, or Schlick's approximation (faster, less accurate)"};

inline constexpr std::array<std::string_view, 3> kScheduleValues = {"auto", "megakernel", "wavefront"};
inline constexpr ChoiceOption kScheduleOption{
    "schedule", kScheduleValues, "auto",
    "how paths are traced: megakernel (a lane per pixel until its path ends) or wavefront (one segment of every live "
    "path per dispatch; the path integrator on ray queries only); auto: the wavefront for path kernels in closed "
    "scenes (no environment image, black background), where it measured faster; the image is the same"};

inline constexpr std::array<std::string_view, 3> kBackendValues = {"auto", "query", "pipeline"};
inline constexpr ChoiceOption kBackendOption{
    "backend", kBackendValues, "auto",
    "query: compute kernels with ray queries; pipeline: a ray-tracing pipeline (raygen, closest-hit, miss and "
    "intersection programs); auto: ray queries where the device has them"};

inline constexpr std::array<std::string_view, 3> kGuidingValues = {"off", "on", "auto"};
inline constexpr ChoiceOption kGuidingOption{
    "guiding", kGuidingValues, "off",
    "path integrator: path guiding, a radiance cache learned over the first 64 spp that draws half the continuations "
    "of diffuse surfaces towards where light came from; on: always; auto: after an unguided trial over the first 16 "
    "spp, only if it estimated that the guide cuts the variance by 1.25x; the image stays unbiased either way"};

inline constexpr std::array<std::string_view, 3> kDenoiseQualityValues = {"fast", "balanced", "high"};
// Balanced by default: at 1280x720 with albedo and normal on 2 cores, 0.85 s against high's 2.0 s, for errors
// within 0-20% of high's (docs/performance.md, "Denoising").
inline constexpr ChoiceOption kDenoiseQualityOption{
    "denoise-quality", kDenoiseQualityValues, "balanced",
    "Open Image Denoise's quality: balanced; high (about 2.4x the time, up to 20% less error at 64 spp); fast "
    "(about half balanced's time, the viewer's)"};

inline constexpr CountOption kMaxDepthOption{"max-depth", 0, 64, 8,
                                             "bounces after the primary hit (mirror, glass, paths)"};

// The most samples per pixel one image accumulates (--spp, --spp-limit, Python's render and add_samples): float
// sums of more would stop changing.
inline constexpr std::uint32_t kMaxSamplesPerPixel = 1u << 20;

inline constexpr std::array<const ChoiceOption*, 6> kChoiceOptions = {&kIntegratorOption, &kSamplingOption,
                                                                      &kFresnelOption, &kScheduleOption,
                                                                      &kBackendOption, &kGuidingOption};

// The index of `value` among the option's values; throws Error (kExitUsage) naming `where`, the option and its
// values otherwise.
std::size_t choiceIndex(const ChoiceOption& option, std::string_view value, const std::string& where);
// "auto, slides or path".
std::string choiceList(const ChoiceOption& option);
// Throws Error (kExitUsage) naming `where`, the option and its range when `value` lies outside it.
void checkCount(const CountOption& option, std::int64_t value, const std::string& where);

}  // namespace raylab
