#include "collision/contact_manager.h"

#include <map>

#include "collision/response/penalty_contact.h"
#include "core/registry.h"

namespace sinew {

namespace {
constexpr const char* kPenalty = "PenalityContactForceField";
std::map<std::string, ContactFactory>& factories() {
  static std::map<std::string, ContactFactory> f = {
      {kPenalty, [](CollisionModelBase& a, CollisionModelBase& b, const Intersection& m) -> std::unique_ptr<Contact> {
         return std::make_unique<PenaltyContact>(a, b, m);
       }}};
  return f;
}
// "nullptr" is a deliberate "no contact" (SOFA skips the pair).
bool known_response(const std::string& n) { return n == "nullptr" || factories().count(n) != 0; }
}  // namespace

void add_contact_response(const std::string& name, ContactFactory factory) { factories()[name] = std::move(factory); }

std::string contact_response_names() {
  std::string out;
  for (const auto& [name, f] : factories()) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void CollisionResponse::init() {
  const std::string& r = response.value();
  if (r.empty()) {
    msg_error("response is not set: no contact will be created (use response=\"PenalityContactForceField\")");
    return;
  }
  if (!known_response(r))
    msg_error("response \"" + r + "\" is not available (available: " + contact_response_names() +
              "); pairs using it get no contact");
}

std::string CollisionResponse::response_for(const CollisionModelBase& m1, const CollisionModelBase& m2) const {
  const std::string& r1 = m1.contact_response.value();
  const std::string& r2 = m2.contact_response.value();
  if (r1.empty() && r2.empty()) return response.value();
  if (r1.empty()) return r2;
  if (r2.empty()) return r1;
  return r1 == r2 ? r1 : response.value();
}

std::unique_ptr<Contact> CollisionResponse::create(const std::string& name, CollisionModelBase& m1,
                                                   CollisionModelBase& m2, const Intersection& method) {
  auto fail = [&](const std::string& why) -> std::unique_ptr<Contact> {
    if (creation_errors_++ < 10)
      msg_error("no contact between " + m1.describe() + " and " + m2.describe() + ": " + why);
    return nullptr;
  };
  auto factory = factories().find(name);
  if (factory == factories().end())
    return fail("response \"" + name + "\" is not available (available: " + contact_response_names() + ")");
  std::unique_ptr<Contact> c = factory->second(m1, m2, method);
  // responseParams: name=value pairs separated by '&' (or '?').
  const std::string& params = response_params.value();
  std::size_t start = 0;
  while (start < params.size()) {
    std::size_t end = params.find_first_of("&?", start);
    if (end == std::string::npos) end = params.size();
    const std::string item = params.substr(start, end - start);
    start = end + 1;
    if (item.empty()) continue;
    const std::size_t eq = item.find('=');
    std::string error;
    if (eq == std::string::npos) {
      if (creation_errors_++ < 10) msg_warning("responseParams item \"" + item + "\" is not name=value: ignored");
    } else if (!c->set_param(item.substr(0, eq), item.substr(eq + 1), error)) {
      if (creation_errors_++ < 10) msg_warning("responseParams: " + error + ": ignored");
    }
  }
  return c;
}

void CollisionResponse::create_contacts(std::vector<PairOutputs>& outputs, const Intersection& method) {
  for (Entry& e : entries_) e.seen = false;
  for (PairOutputs& p : outputs) {
    if (p.outputs.empty()) continue;
    auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.models == p.models; });
    if (it == entries_.end()) {
      const std::string name = response_for(*p.models.first, *p.models.second);
      Entry e;
      e.models = p.models;
      const std::size_t id1 = ids_.id(p.models.first);
      e.key = {id1, ids_.id(p.models.second)};
      if (name != "nullptr") e.contact = create(name, *p.models.first, *p.models.second, method);
      auto at = std::upper_bound(entries_.begin(), entries_.end(), e.key,
                                 [](const auto& key, const Entry& x) { return key < x.key; });
      it = entries_.insert(at, std::move(e));
    }
    it->seen = true;
    if (it->contact) it->contact->set_detection_outputs(p.outputs);
  }
  // Pairs that stopped colliding lose their contact, unless it is kept alive:
  // then it is told there are no outputs this step (SOFA passes it none).
  no_outputs_.clear();
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (!it->seen && !(it->contact && it->contact->keep_alive())) {
      if (it->contact) it->contact->cleanup();
      it = entries_.erase(it);
    } else {
      if (!it->seen) it->contact->set_detection_outputs(no_outputs_);
      ++it;
    }
  }
  contacts_.clear();
  for (Entry& e : entries_)
    if (e.contact) contacts_.push_back(e.contact.get());
}

void register_collision_response(Registry& r) {
  ComponentInfo info;
  info.name = "CollisionResponse";
  info.category = "Collision/Response";
  info.description = "creates the contact response (penalty force fields) of each colliding pair of models";
  info.create = creator<CollisionResponse>();
  r.add(std::move(info));
}

}  // namespace sinew
