#include "fit/fit_plan.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace raylab::fitting {

void applyVariables(const std::vector<Variable>& variables, const double* x, reference::Material& material) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const Variable& v = variables[i];
    const double clamped = std::clamp(x[i], v.lo, v.hi);  // finite differences may step past a bound
    const double value = v.log ? std::exp(clamped) : v.wideScale > 0.0 ? v.wideScale * std::expm1(clamped) : clamped;
    for (std::uint32_t slot : v.slots) material.params[slot] = value;
  }
}

namespace {

bool isSwitch(const ParamInfo& param) {
  // A 0/1 choice (multiscatter): kept at its default, not a continuous parameter.
  return !param.rgb && param.min == 0.0f && param.max == 1.0f && param.role.empty() &&
         param.meaning.find("0 off") != std::string_view::npos;
}

std::vector<Variable> variablesOf(const ModelInfo& model, bool isotropic) {
  std::vector<Variable> variables;
  const auto partner = [&](std::string_view role) -> const ParamInfo* {
    if (role == "slope_y") return findRole(model, "slope_x");
    if (role == "exponent_y") return findRole(model, "exponent_x");
    if (role == "lobe_y") return findRole(model, "lobe_x");
    return nullptr;
  };
  for (const ParamInfo& param : model.params) {
    if (!model.fitFree.empty() && std::find(model.fitFree.begin(), model.fitFree.end(), param.name) == model.fitFree.end()) {
      continue;  // held at its default: the registry's `fit: free` line leaves it out
    }
    // Not fitted: a file, a 0/1 switch, a transmittance (the pairs are reflections: it changes nothing), and
    // KHR_materials_specular's strength and colour (gltf_pbr's F0 is its ior's to fit; with them it would have
    // many equal answers).
    if (isFileParam(param) || isSwitch(param) || param.role == "transmittance" || param.role == "specular_weight" ||
        param.role == "specular_tint") {
      continue;
    }
    if (isotropic) {
      if (const ParamInfo* x = partner(param.role)) {
        for (Variable& v : variables) {
          if (v.slots.front() == x->slot) v.slots.push_back(param.slot);
        }
        continue;
      }
    }
    for (int c = 0; c < (param.rgb ? 3 : 1); ++c) {
      Variable v;
      v.slots = {param.slot + std::uint32_t(c)};
      v.log = param.logScale;
      v.lo = v.log ? std::log(double(param.min)) : param.min;
      v.hi = v.log ? std::log(double(param.max)) : param.max;
      v.start = v.log ? std::log(double(param.defaultValue)) : param.defaultValue;
      variables.push_back(v);
    }
  }
  return variables;
}

// A direction of the upper hemisphere at least 0.15 above the horizon, for the probes below.
glm::dvec3 randomDirection(std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double z = 0.15 + 0.85 * uniform(random), phi = 6.283185307179586 * uniform(random);
  const double r = std::sqrt(1.0 - z * z);
  return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Whether f is affine in the given RGB parameters (each channel in its own channel, jointly), tested at random
// points of the box and random pairs of directions: f(a) = f(0) + sum_k a_k (f(e_k) - f(0)) to 1e-9.
bool jointlyLinear(const ModelPlan& plan, const std::vector<std::array<int, 3>>& groups) {
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<double> x;
    for (const Variable& v : plan.variables) x.push_back(v.lo + (v.hi - v.lo) * uniform(random));
    reference::Material material = plan.base;
    applyVariables(plan.variables, x.data(), material);
    const auto with = [&](int group, double value) {
      reference::Material m = material;
      for (std::size_t k = 0; k < groups.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
          for (std::uint32_t slot : plan.variables[std::size_t(groups[k][c])].slots) {
            m.params[slot] = (int(k) == group) ? value : 0.0;
          }
        }
      }
      return m;
    };
    const reference::Material zero = with(-1, 0.0);
    std::vector<reference::Material> units;
    for (std::size_t k = 0; k < groups.size(); ++k) units.push_back(with(int(k), 1.0));
    reference::Material mixed = zero;
    std::vector<glm::dvec3> amounts;
    for (const auto& group : groups) {
      glm::dvec3 a;
      for (int c = 0; c < 3; ++c) {
        const Variable& v = plan.variables[std::size_t(group[c])];
        a[c] = v.lo + (v.hi - v.lo) * uniform(random);
        for (std::uint32_t slot : v.slots) mixed.params[slot] = a[c];
      }
      amounts.push_back(a);
    }
    for (int p = 0; p < 8; ++p) {
      const glm::dvec3 wi = randomDirection(random), wo = randomDirection(random);
      const glm::dvec3 h = reference::eval(zero, wi, wo);
      glm::dvec3 predicted = h, scale = glm::abs(h);
      for (std::size_t k = 0; k < groups.size(); ++k) {
        const glm::dvec3 g = reference::eval(units[k], wi, wo) - h;
        predicted += amounts[k] * g;
        scale += glm::abs(amounts[k] * g);
      }
      const glm::dvec3 f = reference::eval(mixed, wi, wo);
      for (int c = 0; c < 3; ++c) {
        if (!(std::abs(f[c] - predicted[c]) <= 1e-9 * (scale[c] + std::abs(f[c])) + 1e-300)) return false;
      }
    }
  }
  return true;
}

// The channels of f (bit c for channel c) that differ between the variables' values x and moved on any of 16 random
// pairs of directions; NaN counts as a difference.
int channelsMoved(const ModelPlan& plan, const std::vector<double>& x, const std::vector<double>& moved,
                  std::mt19937_64& random) {
  reference::Material a = plan.base, b = plan.base;
  applyVariables(plan.variables, x.data(), a);
  applyVariables(plan.variables, moved.data(), b);
  int mask = 0;
  for (int p = 0; p < 16; ++p) {
    const glm::dvec3 wi = randomDirection(random), wo = randomDirection(random);
    const glm::dvec3 fa = reference::eval(a, wi, wo), fb = reference::eval(b, wi, wo);
    for (int c = 0; c < 3; ++c) {
      if (!(fa[c] == fb[c])) mask |= 1 << c;
    }
  }
  return mask;
}

// The nonlinear variables that f depends on only through linear group `group`: with the group's amounts at 0,
// changing one of them changes f on no pair tried, and with only this group's amounts non-zero it changes f on some
// (the second test keeps another lobe's variables out where the draws left that lobe dark: Lafortune's first lobe is
// 0 for every Cz < 0).
std::vector<int> privateVariables(const ModelPlan& plan, int group) {
  std::mt19937_64 random(54321);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Whether changing variable j moves f somewhere, with the linear groups' amounts drawn where `active` says and 0
  // elsewhere.
  const auto moves = [&](int j, const std::function<bool(int)>& active) {
    for (int trial = 0; trial < 16; ++trial) {
      std::vector<double> x;
      for (const Variable& v : plan.variables) x.push_back(v.lo + (v.hi - v.lo) * uniform(random));
      for (std::size_t g = 0; g < plan.linear.size(); ++g) {
        if (active(int(g))) continue;
        for (int c = 0; c < 3; ++c) x[std::size_t(plan.linear[g].variables[std::size_t(c)])] = 0.0;
      }
      std::vector<double> moved = x;
      const Variable& v = plan.variables[std::size_t(j)];
      moved[std::size_t(j)] = v.lo + (v.hi - v.lo) * uniform(random);
      if (channelsMoved(plan, x, moved, random) != 0) return true;
    }
    return false;
  };
  std::vector<int> found;
  for (int j : plan.nonlinear) {
    if (!moves(j, [&](int g) { return g != group; }) && moves(j, [&](int g) { return g == group; })) {
      found.push_back(j);
    }
  }
  return found;
}

// The one channel of f variable j moves, or -1 (several, or none seen): stepped at random points of the box, f
// changes only in that channel on every pair tried.
int channelOf(const ModelPlan& plan, int j) {
  std::mt19937_64 random(777u + std::uint64_t(j));
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int mask = 0;
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<double> x;
    for (const Variable& v : plan.variables) x.push_back(v.lo + (v.hi - v.lo) * (0.05 + 0.9 * uniform(random)));
    std::vector<double> moved = x;
    const Variable& v = plan.variables[std::size_t(j)];
    moved[std::size_t(j)] += (v.hi - v.lo) * (uniform(random) < 0.5 ? -0.03 : 0.03);
    mask |= channelsMoved(plan, x, moved, random);
  }
  return mask == 1 ? 0 : mask == 2 ? 1 : mask == 4 ? 2 : -1;
}

}  // namespace

ModelPlan planOf(const ModelInfo& model, bool isotropic) {
  ModelPlan plan;
  plan.model = &model;
  plan.variables = variablesOf(model, isotropic);
  plan.base = reference::fromRecord(defaultRecord(model.id));
  // Candidates: RGB parameters on a linear scale, each channel its own variable, each linear on its own; then in
  // blocks, each group joining the first block it is jointly linear with.
  std::vector<std::vector<std::array<int, 3>>> blocks;
  for (std::size_t i = 0; i + 2 < plan.variables.size(); ++i) {
    const Variable& v = plan.variables[i];
    if (v.log || v.slots.size() != 1) continue;
    const ParamInfo* param = nullptr;
    for (const ParamInfo& p : model.params) {
      if (p.rgb && p.slot == v.slots[0]) param = &p;
    }
    if (param == nullptr) continue;
    const std::array<int, 3> group{int(i), int(i + 1), int(i + 2)};
    i += 2;
    if (!jointlyLinear(plan, {group})) continue;
    bool placed = false;
    for (auto& block : blocks) {
      std::vector<std::array<int, 3>> trial = block;
      trial.push_back(group);
      if (!placed && jointlyLinear(plan, trial)) {
        block = trial;
        placed = true;
      }
    }
    if (!placed) blocks.push_back({group});
  }
  for (const auto& block : blocks) {
    plan.blocks.emplace_back();
    for (const auto& group : block) {
      for (int c = 0; c < 3; ++c) plan.variables[std::size_t(group[c])].linearGroup = int(plan.linear.size());
      plan.blocks.back().push_back(int(plan.linear.size()));
      plan.linear.push_back({group});
    }
  }
  for (std::size_t i = 0; i < plan.variables.size(); ++i) {
    if (plan.variables[i].linearGroup < 0) plan.nonlinear.push_back(int(i));
  }
  for (const ParamInfo& param : model.params) {
    for (std::size_t i = 0; param.rgb && i + 2 < plan.variables.size(); ++i) {
      if (plan.variables[i].slots.front() == param.slot && plan.variables[i].linearGroup < 0) {
        plan.nonlinearColours.push_back({int(i), int(i + 1), int(i + 2)});
      }
    }
  }
  // A nonlinear parameter from 0 over at least kWideRange: fitted in t = log(1 + value / kWideScale) (Variable).
  // Drawn uniformly in its own scale, SGD's shadowing c in [0, 1e38] was above 1e30 in 99 of 100 search points.
  constexpr double kWideRange = 1e6, kWideScale = 1e-9;
  for (int j : plan.nonlinear) {
    Variable& v = plan.variables[std::size_t(j)];
    if (v.log || v.lo != 0.0 || !(v.hi >= kWideRange)) continue;
    v.wideScale = kWideScale;
    v.hi = std::log1p(v.hi / kWideScale);
    v.start = std::log1p(v.start / kWideScale);
  }
  // Difference groups: a variable that moves one channel joins the first group with no variable of that channel.
  for (std::size_t j = 0; j < plan.variables.size(); ++j) {
    plan.variables[j].channel = channelOf(plan, int(j));
    const int channel = plan.variables[j].channel;
    bool placed = false;
    for (std::vector<int>& group : plan.diffGroups) {
      if (channel < 0) break;
      bool free = true;
      for (int k : group) {
        const int other = plan.variables[std::size_t(k)].channel;
        free &= other >= 0 && other != channel;
      }
      if (free) {
        group.push_back(int(j));
        placed = true;
        break;
      }
    }
    if (!placed) plan.diffGroups.push_back({int(j)});
  }
  for (std::size_t g = 0; g < plan.linear.size(); ++g) {
    std::vector<int> own = privateVariables(plan, int(g));
    if (!own.empty()) plan.lobes.push_back({int(g), std::move(own)});
  }
  for (const std::string_view role : {"roughness", "slope", "slope_x", "exponent", "exponent_x", "mirror_exponent"}) {
    const ParamInfo* param = findRole(model, role);
    for (std::size_t i = 0; param != nullptr && plan.width < 0 && i < plan.variables.size(); ++i) {
      if (plan.variables[i].slots.front() != param->slot) continue;
      plan.width = int(i);
      plan.narrowIsLow = role.find("exponent") == std::string_view::npos;
    }
  }
  if (!model.fitStart.empty()) {
    for (const Variable& v : plan.variables) plan.declaredStart.push_back(v.start);
    for (const auto& [name, value] : model.fitStart) {
      const ParamInfo* param = findParam(model, name);  // the registry checked the name
      for (std::size_t i = 0; param != nullptr && i < plan.variables.size(); ++i) {
        const Variable& v = plan.variables[i];
        if (v.slots.front() < param->slot || v.slots.front() >= param->slot + (param->rgb ? 3u : 1u)) continue;
        plan.declaredStart[i] = v.log ? std::log(value) : v.wideScale > 0.0 ? std::log1p(value / v.wideScale) : value;
      }
    }
  }
  return plan;
}

gpu::MaterialRecord recordOf(const ModelPlan& plan, const std::vector<double>& x) {
  reference::Material material = plan.base;
  applyVariables(plan.variables, x.data(), material);
  gpu::MaterialRecord record = defaultRecord(plan.model->id);
  for (std::uint32_t i = 0; i < gpu::kMaxMaterialParams; ++i) record.params[i] = float(material.params[i]);
  return record;
}

double residual(FitMetric metric, double target, double model, double cosine) {
  return metric == FitMetric::kCosine ? (target - model) * cosine
                                      : std::log1p(target * cosine) - std::log1p(std::max(0.0, model) * cosine);
}

}  // namespace raylab::fitting
