// CollisionResponse (formerly DefaultContactManager, spec/interaction.md
// §4.1): one contact per colliding pair of models, created when the pair
// starts colliding, updated every step, removed when it stops.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "collision/detection.h"
#include "collision/intersection.h"
#include "collision/response/contact.h"

namespace sinew {

// Contact responses by the names scenes use ("PenalityContactForceField",
// "FrictionContactConstraint", ...). Modules above collision (constraints)
// add theirs when they register their components.
using ContactFactory =
    std::function<std::unique_ptr<Contact>(CollisionModelBase&, CollisionModelBase&, const Intersection&)>;
void add_contact_response(const std::string& name, ContactFactory factory);
// Names of the available responses, sorted, comma-separated (for messages).
std::string contact_response_names();

class CollisionResponse : public Component {
 public:
  Field<std::string> response{this, "response", "", "contact response: PenalityContactForceField, FrictionContactConstraint, ...", "Collision"};
  Field<std::string> response_params{this, "responseParams", "",
                                     "parameters of the response, as name1=value1&name2=value2", "Collision"};

  void init() override;
  // Creates, updates and removes contacts from this step's outputs (pairs without outputs stop colliding).
  void create_contacts(std::vector<PairOutputs>& outputs, const Intersection& method);
  // Contacts in map order (first appearance of their models).
  const std::vector<Contact*>& contacts() const { return contacts_; }

 protected:
  // Name of the response for a pair (models' contactResponse override the default).
  virtual std::string response_for(const CollisionModelBase& m1, const CollisionModelBase& m2) const;

 private:
  std::unique_ptr<Contact> create(const std::string& name, CollisionModelBase& m1, CollisionModelBase& m2,
                                  const Intersection& method);
  struct Entry {
    ModelPair models;
    std::pair<std::size_t, std::size_t> key;
    std::unique_ptr<Contact> contact;  // null: the pair's response is "nullptr" or could not be created
    bool seen = false;
  };
  std::vector<Entry> entries_;
  FirstSeenIds ids_;
  std::vector<Contact*> contacts_;
  std::vector<DetectionOutput> no_outputs_;  // what a kept-alive contact gets once its pair stopped colliding
  int creation_errors_ = 0;
};

}  // namespace sinew
