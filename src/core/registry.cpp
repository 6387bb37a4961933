#include "core/registry.h"

#include <algorithm>
#include <sstream>

#include "core/node.h"
#include "core/parse.h"
#include "core/path.h"

namespace sinew {

Registry& registry() {
  static Registry r;
  return r;
}

void Registry::add(ComponentInfo info) {
  for (const auto& a : info.aliases) aliases_[a] = info.name;
  std::string key = info.name;
  classes_[key] = std::move(info);
}

const ComponentInfo* Registry::find(std::string_view name) const {
  if (auto it = classes_.find(name); it != classes_.end()) return &it->second;
  if (auto it = aliases_.find(name); it != aliases_.end()) return find(it->second);
  return nullptr;
}

std::vector<std::string> Registry::names() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : classes_) out.push_back(k);
  return out;
}

std::string_view renamed_component(std::string_view name) {
  static const std::map<std::string, std::string, std::less<>> table = {
      {"FixedConstraint", "FixedProjectiveConstraint"},
      {"AffineMovementConstraint", "AffineMovementProjectiveConstraint"},
      {"AttachConstraint", "AttachProjectiveConstraint"},
      {"FixedPlaneConstraint", "FixedPlaneProjectiveConstraint"},
      {"FixedRotationConstraint", "FixedRotationProjectiveConstraint"},
      {"FixedTranslationConstraint", "FixedTranslationProjectiveConstraint"},
      {"HermiteSplineConstraint", "HermiteSplineProjectiveConstraint"},
      {"LinearMovementConstraint", "LinearMovementProjectiveConstraint"},
      {"LinearVelocityConstraint", "LinearVelocityProjectiveConstraint"},
      {"OscillatorConstraint", "OscillatorProjectiveConstraint"},
      {"ParabolicConstraint", "ParabolicProjectiveConstraint"},
      {"PartialFixedConstraint", "PartialFixedProjectiveConstraint"},
      {"PartialLinearMovementConstraint", "PartialLinearMovementProjectiveConstraint"},
      {"PatchTestMovementConstraint", "PatchTestMovementProjectiveConstraint"},
      {"PositionBasedDynamicsConstraint", "PositionBasedDynamicsProjectiveConstraint"},
      {"SkeletalMotionConstraint", "SkeletalMotionProjectiveConstraint"},
      {"ProjectToLineConstraint", "LineProjectiveConstraint"},
      {"ProjectToPlaneConstraint", "PlaneProjectiveConstraint"},
      {"ProjectToPointConstraint", "PointProjectiveConstraint"},
      {"ProjectDirectionConstraint", "DirectionProjectiveConstraint"},
      {"BilateralInteractionConstraint", "BilateralLagrangianConstraint"},
      {"SlidingConstraint", "SlidingLagrangianConstraint"},
      {"StopperConstraint", "StopperLagrangianConstraint"},
      {"UniformConstraint", "UniformLagrangianConstraint"},
      {"UnilateralInteractionConstraint", "UnilateralLagrangianConstraint"},
      {"StiffSpringForceField", "SpringForceField"},
      {"ParallelStiffSpringForceField", "ParallelSpringForceField"},
      {"ShewchukPCGLinearSolver", "PCGLinearSolver"},
      {"OglCylinderModel", "CylinderVisualModel"},
      {"TriangleOctreeModel", "TriangleOctreeCollisionModel"},
      {"VolumeFromTetrahedrons", "VolumeFromVolumetricElements"},
  };
  auto it = table.find(name);
  return it == table.end() ? name : std::string_view(it->second);
}

std::string resolve_template_alias(std::string_view tmpl, std::vector<std::string>* deprecations) {
  static const std::map<std::string, std::pair<std::string, bool>, std::less<>> table = {
      {"Vec1", {"Vec1d", false}},   {"Vec2", {"Vec2d", false}},     {"Vec3", {"Vec3d", false}},
      {"Vec6", {"Vec6d", false}},   {"Rigid2", {"Rigid2d", false}}, {"Rigid3", {"Rigid3d", false}},
      {"Vec1f", {"Vec1d", true}},   {"Vec2f", {"Vec2d", true}},     {"Vec3f", {"Vec3d", true}},
      {"Vec6f", {"Vec6d", true}},   {"Rigid2f", {"Rigid2d", true}}, {"Rigid3f", {"Rigid3d", true}},
      {"Rigid", {"Rigid3d", true}}, {"CompressedRowSparseMatrix", {"CompressedRowSparseMatrixd", false}},
      {"CompressedRowSparseMatrixMat3x3", {"CompressedRowSparseMatrixMat3x3d", false}},
  };
  std::string out;
  std::size_t i = 0;
  while (i <= tmpl.size()) {
    std::size_t j = tmpl.find(',', i);
    if (j == std::string_view::npos) j = tmpl.size();
    std::string_view tok = tmpl.substr(i, j - i);
    if (!out.empty() || i > 0) out += ',';
    if (auto it = table.find(tok); it != table.end()) {
      out += it->second.first;
      if (it->second.second && deprecations)
        deprecations->push_back("the deprecated template '" + std::string(tok) + "' has been replaced by " +
                                it->second.first);
    } else {
      out += tok;
    }
    i = j + 1;
  }
  return out;
}

namespace {

// Why `tmpl` cannot be created in `node` (empty string: it can).
std::string requirement_problem(const ComponentInfo& info, const std::string& tmpl, Node& node,
                                const AttributeMap& attrs) {
  if (info.requirement == Requirement::state) {
    MechanicalState* s = nullptr;
    if (const std::string* p = attrs.peek("mstate")) {
      s = dynamic_cast<MechanicalState*>(resolve_object_path(
          node, nullptr, *p, [](Base* b) { return dynamic_cast<MechanicalState*>(b) != nullptr; }));
    } else {
      s = node.get_mechanical_state();
    }
    if (!s) return "no mechanical state in the context";
    // Two-parameter templates (DiagonalMass<DataTypes, GeometricalTypes>): the first names the state.
    if (tmpl.substr(0, tmpl.find(',')) != s->info().name) return std::string("the mechanical state is ") + s->info().name;
    return {};
  }
  if (info.requirement == Requirement::mapping) {
    // "In,Out"; a one-type template names the input only (SOFA's classes templated on
    // their input alone, e.g. DistanceToPlaneMapping<Vec3d>: the class fixes its output).
    const std::size_t comma = tmpl.find(',');
    auto want_in = tmpl.substr(0, comma);
    auto want_out = comma == std::string::npos ? std::string() : tmpl.substr(comma + 1);
    // Type name of the state a path designates ("" when none): mechanical
    // states, and visual models (always Vec3d) as outputs.
    auto state_at = [&](const std::string& path, bool allow_visual, Base** which) -> std::string {
      Base* b = resolve_object_path(node, nullptr, path, [allow_visual](Base* c) {
        return dynamic_cast<MechanicalState*>(c) != nullptr ||
               (allow_visual && dynamic_cast<VisualState*>(c) != nullptr);
      });
      *which = b;
      if (auto* m = dynamic_cast<MechanicalState*>(b)) return m->info().name;
      if (dynamic_cast<VisualState*>(b)) return "Vec3d";
      return {};
    };
    const std::string* in_attr = attrs.peek("input");
    const std::string* out_attr = attrs.peek("output");
    Base* out = nullptr;
    const std::string out_type = state_at(out_attr ? *out_attr : "@./", true, &out);
    if (!out) return "output state not found";
    // Multi-mappings list several inputs, all of the In type.
    std::istringstream tokens(in_attr ? *in_attr : std::string("@../"));
    int count = 0;
    for (std::string p; tokens >> p; ++count) {
      Base* in = nullptr;
      const std::string in_type = state_at(p, false, &in);
      if (!in) return "input state not found (" + p + ")";
      if (in == out) return "input and output are the same state";
      if (want_in != in_type) return "input is " + in_type;
    }
    if (count == 0) return "input state not found";
    if (!want_out.empty() && want_out != out_type) return "output is " + out_type;
    return {};
  }
  return {};
}

}  // namespace

Registry::Created Registry::create(std::string_view type, std::string_view tmpl_raw, Node& node,
                                   const AttributeMap& attrs) const {
  Created out;
  const ComponentInfo* info = find(renamed_component(type));
  if (!info) {
    out.errors.push_back("the component '" + std::string(type) + "' cannot be found in the factory");
    return out;
  }
  std::vector<std::string> deprecations;
  std::string tmpl = resolve_template_alias(tmpl_raw, &deprecations);
  for (auto& d : deprecations) out.warnings.push_back(d);

  auto try_make = [&](const std::string& t) -> bool {
    if (!requirement_problem(*info, t, node, attrs).empty()) return false;
    out.component = info->create(t);
    out.used_template = t;
    return out.component != nullptr;
  };

  if (info->templates.empty()) {
    out.component = info->create({});
    return out;
  }
  const bool known = std::find(info->templates.begin(), info->templates.end(), tmpl) != info->templates.end();
  const std::string first = known ? tmpl : info->default_template;
  if (try_make(first)) {
    if (!tmpl.empty() && !known)
      out.errors.push_back("requested template '" + std::string(tmpl_raw) +
                           "' cannot be found in the list of available templates; falling back to '" + first + "'");
    return out;
  }
  std::vector<std::string> others = info->templates;
  std::sort(others.begin(), others.end());
  for (const auto& t : others) {
    if (t == first) continue;
    if (try_make(t)) {
      if (!tmpl.empty())
        out.errors.push_back("requested template '" + std::string(tmpl_raw) +
                             "' is not compatible with the current context; falling back to '" + t + "'");
      return out;
    }
  }
  out.errors.push_back("the object is in the factory but cannot be created");
  for (const auto& t : info->templates)
    out.errors.push_back("  template " + t + ": " + requirement_problem(*info, t, node, attrs));
  return out;
}

}  // namespace sinew
