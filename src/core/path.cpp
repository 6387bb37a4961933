#include "core/path.h"

#include <vector>

#include "core/node.h"
#include "core/parse.h"

namespace sinew {

namespace {

std::vector<std::string_view> split_path(std::string_view p) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i <= p.size()) {
    std::size_t j = p.find('/', i);
    if (j == std::string_view::npos) j = p.size();
    if (j > i) out.push_back(p.substr(i, j - i));
    i = j + 1;
  }
  return out;
}

// "[k]" → object at owner's index + k in its node.
Base* relative_index(Node& node, Component* owner, std::string_view elem, std::string* why) {
  std::string_view inner = elem.substr(1, elem.size() - 2);
  if (inner.empty()) return owner ? static_cast<Base*>(owner) : &node;
  long long k = 0;
  if (!parse::read_int(inner, k)) {
    if (why) *why = "bad index '" + std::string(elem) + "'";
    return nullptr;
  }
  const auto& objs = node.objects();
  long long pos = -1;
  for (std::size_t i = 0; i < objs.size(); ++i)
    if (objs[i].get() == owner) pos = static_cast<long long>(i);
  if (pos < 0) pos = static_cast<long long>(objs.size());  // owner not inserted yet: after the last
  const long long target = pos + k;
  if (target < 0 || target >= static_cast<long long>(objs.size())) {
    if (why) *why = "no object at relative index " + std::string(inner);
    return nullptr;
  }
  return objs[static_cast<std::size_t>(target)].get();
}

}  // namespace

Base* resolve_object_path(Node& start, Component* owner, std::string_view path,
                          const std::function<bool(Base*)>& accept, std::string* why) {
  if (!path.empty() && path[0] == '@') path.remove_prefix(1);
  // "@" (the owner) and "@[k]" are checked against `accept` like every other path:
  // a multi-link would otherwise drop a target of the wrong type without a word.
  if (path.empty() || (path.front() == '[' && path.back() == ']')) {
    Base* b = path.empty() ? (owner ? static_cast<Base*>(owner) : &start) : relative_index(start, owner, path, why);
    if (!b || accept(b)) return b;
    if (why) *why = b->describe() + " has the wrong type";
    return nullptr;
  }

  Node* node = &start;
  Base* current = nullptr;  // object reached, if any
  bool anchored = false;
  if (path[0] == '/') {
    node = start.root();
    anchored = true;
  }
  auto elems = split_path(path);
  for (std::size_t i = 0; i < elems.size(); ++i) {
    std::string_view e = elems[i];
    if (current) {  // nothing below an object
      if (why) *why = "'" + std::string(e) + "' follows an object";
      return nullptr;
    }
    if (e == ".") {
      anchored = true;
      continue;
    }
    if (e == "..") {
      anchored = true;
      if (node->parent()) node = node->parent();
      continue;
    }
    if (e.front() == '[' && e.back() == ']') {
      current = relative_index(*node, owner, e, why);
      if (!current) return nullptr;
      continue;
    }
    // Child nodes shadow objects; the first element searches upward unless anchored.
    Node* search = node;
    for (;;) {
      if (Node* c = search->find_child_named(e)) {
        node = c;
        break;
      }
      if (Component* o = search->find_object_named(e)) {
        node = search;
        current = o;
        break;
      }
      if (i == 0 && !anchored && search->parent()) {
        search = search->parent();
        continue;
      }
      if (why) *why = "no node or object named '" + std::string(e) + "'";
      return nullptr;
    }
  }
  if (current) {
    if (accept(current)) return current;
    if (why) *why = current->describe() + " has the wrong type";
    return nullptr;
  }
  if (accept(node)) return node;
  // Ended on a node: the unique object of the requested type there.
  Base* found = nullptr;
  for (auto& o : node->objects()) {
    if (accept(o.get())) {
      if (found) {
        if (why) *why = "several candidates in " + node->describe();
        return nullptr;
      }
      found = o.get();
    }
  }
  if (found) return found;
  // Fall back to the node's state, searching ancestors (e.g. input="@..").
  for (Node* n = node; n; n = n->parent())
    if (n->mechanical_state && accept(n->mechanical_state)) return n->mechanical_state;
  if (why) *why = "no object of the requested type in " + node->describe();
  return nullptr;
}

BaseField* resolve_field_link(Node& node, Component* owner, std::string_view link, std::string* why) {
  if (!link.empty() && link[0] == '@') link.remove_prefix(1);
  const std::size_t slash = link.rfind('/');
  const std::size_t dot = link.rfind('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
    if (why) *why = "link '@" + std::string(link) + "' names no field (expected @path.field)";
    return nullptr;
  }
  // "../.position" or "./.x" style: a trailing '/' or '.' before the field name belongs to the path.
  std::string_view obj_path = link.substr(0, dot);
  std::string_view field = link.substr(dot + 1);
  Base* target = nullptr;
  if (obj_path.empty()) {
    target = owner ? static_cast<Base*>(owner) : &node;
  } else {
    target = resolve_object_path(node, owner, obj_path, [](Base*) { return true; }, why);
  }
  if (!target) return nullptr;
  BaseField* f = target->find_field(field);
  if (!f && why) *why = target->describe() + " has no field '" + std::string(field) + "'";
  return f;
}

}  // namespace sinew
