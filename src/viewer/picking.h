// What lies under the cursor (SOFA's PickHandler, spec/user-interfaces.md §3.6): the
// closest simulated collision element the ray hits (triangles and spheres), else the
// closest visible visual-model triangle, resolved to the nearest particle of a Vec3d
// state, else, of the particles within a distance of the ray, the one nearest to the camera.
#pragma once

#include <string>

#include "viewer/camera_control.h"

namespace sinew {
class Node;
class CollisionModelBase;
class MechanicalState;
}  // namespace sinew

namespace sinew::render {
struct DrawList;
}

namespace sinew::viewer {

struct Pick {
  enum class On { nothing, collision_element, particle };
  On on = On::nothing;
  CollisionModelBase* model = nullptr;  // collision_element: the model and its element
  unsigned element = 0;
  MechanicalState* state = nullptr;     // particle: the state and the point
  unsigned index = 0;
  Vec3 point = Vec3::Zero();            // where the ray meets what was picked
  double distance = 0;                  // along the ray [length]
  explicit operator bool() const { return on != On::nothing; }
};

// `visible`: what the viewer draws (its visual models are the fallback surface).
// `tolerance`: the largest distance between ray and particle for the last resort [length].
Pick pick(Node& root, const render::DrawList& visible, const Ray& ray, double tolerance);

// Ray–triangle (Möller–Trumbore): distance along the ray, or a negative number when missed.
double ray_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c);
// Ray–sphere: distance to the first crossing in front of the origin, negative when missed.
double ray_sphere(const Ray& ray, const Vec3& centre, double radius);

}  // namespace sinew::viewer
