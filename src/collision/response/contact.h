// Contact: the response to the detection outputs of one pair of collision
// models (spec/interaction.md §4.1–4.2). The contact manager keeps one per
// pair while the pair collides; each step it gets the pair's outputs and is
// (re)attached to the graph where the response belongs.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "collision/collision_model.h"
#include "collision/detection_output.h"
#include "core/node.h"

namespace sinew {

class Intersection;

class Contact {
 public:
  Contact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method)
      : m1_(&m1), m2_(&m2), method_(&method) {}
  virtual ~Contact() = default;

  CollisionModelBase& model1() const { return *m1_; }
  CollisionModelBase& model2() const { return *m2_; }
  // Data of the response set from the manager's responseParams ("mu=0.5"); false when unknown.
  virtual bool set_param(const std::string& name, const std::string& value, std::string& error) = 0;
  // This step's outputs of the pair (the vector outlives the call until the next detection).
  virtual void set_detection_outputs(std::vector<DetectionOutput>& outputs) = 0;
  // Attaches the response (force field or constraint) in `where` (kept there while the pair collides).
  virtual void create_response(Node& where) = 0;
  // The component attached by create_response (nullptr before).
  virtual Component* response() const = 0;
  // The pair stopped colliding: detaches and deletes what the contact added to the graph.
  virtual void cleanup() = 0;
  // Contacts that persist after separation (stick contacts).
  virtual bool keep_alive() const { return false; }
  // Number of contact points this step.
  virtual std::size_t count() const = 0;

 protected:
  CollisionModelBase* m1_;
  CollisionModelBase* m2_;
  const Intersection* method_;
};

// Puts a contact's response component in `where` (Contact::create_response):
// it stays when already there, moves from the node it was attached to, or
// comes out of `detached` (built before its first attachment). Returns it.
template <class T>
T* attach_response(Node& where, T* attached, std::unique_ptr<T>& detached) {
  if (attached && attached->node() == &where) return attached;  // attached there since an earlier step
  std::unique_ptr<Component> owned = attached ? attached->node()->remove_object(attached) : std::move(detached);
  return static_cast<T*>(where.add_object(std::move(owned)));
}

}  // namespace sinew
