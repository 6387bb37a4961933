// Collision pipeline components (spec/interaction.md §1–§4): the pipeline,
// broad and narrow phases, intersection methods and the contact manager.
//
// Collision detection and response are not implemented yet. A pipeline
// whose scene has no collision model does exactly what SOFA does (nothing),
// so these components load and cost nothing; a scene with collision models
// is refused at init with an explicit error instead of running without contacts.
#include <vector>

#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"

namespace sinew {

namespace {

class CollisionPipeline final : public Component {
 public:
  Field<bool> verbose{this, "verbose", false, "log the collision steps", "Collision"};
  Field<bool> draw{this, "draw", false, "draw contacts (viewer)", "Visualization"};
  Field<int> depth{this, "depth", 6, "depth of the bounding-volume hierarchies", "Collision"};
  Field<bool> parallel_detection{this, "parallelDetection", false, "detect collisions in parallel", "Collision"};

  void init() override {
    if (depth.value() < 0) {
      msg_warning("depth must be positive; reset to 6");
      depth.set(6);
    }
    std::vector<CollisionModel*> models;
    node()->collect_down(models);
    if (!models.empty()) {
      msg_error("collision detection and response are not implemented yet: this scene has " +
                std::to_string(models.size()) + " collision model(s), starting with " + models.front()->describe());
      set_state(ComponentState::invalid);
    }
  }
};

class BruteForceBroadPhase final : public Component {
 public:
  Field<std::vector<double>> box{this, "box", {}, "if set, only models intersecting this box collide", "Collision"};
};

class BVHNarrowPhase final : public Component {};

class CollisionResponse final : public Component {
 public:
  Field<std::string> response{this, "response", "", "contact response (PenalityContactForceField, ...)",
                              "Collision"};
  Field<std::string> response_params{this, "responseParams", "", "name=value&... parameters of the response",
                                     "Collision"};
};

class DiscreteIntersection final : public Component {};

class ProximityIntersection final : public Component {
 public:
  Field<double> alarm_distance{this, "alarmDistance", 1.0, "distance below which contacts are detected",
                               "Collision"};
  Field<double> contact_distance{this, "contactDistance", 0.5, "distance kept between objects", "Collision"};
  Field<bool> use_sphere_triangle{this, "useSphereTriangle", true, "sphere-triangle tests", "Collision"};
  Field<bool> use_point_point{this, "usePointPoint", true, "point-point tests", "Collision"};
  Field<bool> use_surface_normals{this, "useSurfaceNormals", false, "use surface normals", "Collision"};
  Field<bool> use_line_point{this, "useLinePoint", true, "line-point tests", "Collision"};
  Field<bool> use_line_line{this, "useLineLine", true, "line-line tests", "Collision"};
};

template <class T>
void add(Registry& r, const char* name, const char* what, std::vector<std::string> aliases = {}) {
  ComponentInfo info;
  info.name = name;
  info.category = "Collision";
  info.description = std::string(what) + " (no collision models supported yet)";
  info.aliases = std::move(aliases);
  info.create = creator<T>();
  r.add(std::move(info));
}

}  // namespace

void register_collision_pipeline(Registry& r) {
  add<CollisionPipeline>(r, "CollisionPipeline", "collision pipeline", {"DefaultPipeline"});
  add<BruteForceBroadPhase>(r, "BruteForceBroadPhase", "broad phase testing every pair of models",
                            {"ParallelBruteForceBroadPhase"});
  add<BVHNarrowPhase>(r, "BVHNarrowPhase", "narrow phase over bounding-volume hierarchies",
                      {"ParallelBVHNarrowPhase"});
  add<CollisionResponse>(r, "CollisionResponse", "contact manager creating contact responses",
                         {"DefaultContactManager"});
  add<DiscreteIntersection>(r, "DiscreteIntersection", "intersection tests without proximity");
  add<ProximityIntersection>(r, "MinProximityIntersection", "proximity intersection tests");
  add<ProximityIntersection>(r, "NewProximityIntersection", "proximity intersection tests");
}

}  // namespace sinew
