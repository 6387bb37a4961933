// libFuzzer target: link paths (core/path.h, spec/framework.md §2.3) resolved on a
// small fixed graph with a shared (DAG) node, from several owners: object paths
// ("@../a", "@/body/leaf/l0", "@[-1]"), data links ("@a.position") and the link
// cycle finder over a ring the input closes.
//
// Oracle besides sanitizers: a path that resolves returns an object of the graph
// accepted by the predicate; one that does not says why.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/component.h"
#include "core/engine.h"
#include "core/node.h"
#include "core/path.h"
#include "fuzz_support.h"

using namespace sinew;

namespace {

class Foo final : public Component {
 public:
  Field<std::vector<double>> position{this, "position", {}, "some data"};
  Field<double> mass{this, "totalMass", 1.0, "a scalar"};
};
class Bar final : public Component {};

template <class T>
T* add(Node& n, const std::string& name) {
  auto c = std::make_unique<T>();
  c->name.set(name);
  return static_cast<T*>(n.add_object(std::move(c)));
}

// root{rootFoo, dup} / dup{dupFoo}, body{a, b, c} / leaf{l0}, shared (also a child of dup)
struct Graph {
  Node root{"root"};
  std::vector<Component*> owners;
  std::vector<Node*> nodes;
  Graph() {
    Node* dup = root.add_child(std::make_unique<Node>("dup"));
    Node* body = root.add_child(std::make_unique<Node>("body"));
    Node* leaf = body->add_child(std::make_unique<Node>("leaf"));
    Node* shared = body->add_child(std::make_unique<Node>("shared"));
    dup->add_linked_child(shared);
    owners = {add<Foo>(root, "rootFoo"), add<Bar>(root, "dup"), add<Foo>(*dup, "dupFoo"), add<Foo>(*body, "a"),
              add<Bar>(*body, "b"),      add<Foo>(*body, "c"),  add<Bar>(*leaf, "l0"),   add<Foo>(*shared, "s")};
    nodes = {&root, dup, body, body, body, body, leaf, shared};
  }
  bool contains(const Base* b) const {
    for (const Component* c : owners)
      if (c == b) return true;
    for (const Node* n : nodes)
      if (n == b) return true;
    return false;
  }
};

bool any(Base*) { return true; }
bool is_foo(Base* b) { return dynamic_cast<Foo*>(b) != nullptr; }

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::limit_scene_memory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Graph* g = new Graph;  // built once: resolution never changes the graph
  const std::string path(reinterpret_cast<const char*>(data), size);
  for (std::size_t k = 0; k < g->owners.size(); ++k) {
    Node& node = *g->nodes[k];
    Component* owner = g->owners[k];
    for (bool foo_only : {false, true}) {
      std::string why;
      Base* b = resolve_object_path(node, owner, path, foo_only ? is_foo : any, &why);
      if (b && !(g->contains(b) || b == owner)) __builtin_trap();  // not an object of this graph
      if (b && foo_only && !is_foo(b)) __builtin_trap();
      if (!b && why.empty()) __builtin_trap();  // a failure always says why
    }
    std::string why;
    BaseField* f = resolve_field_link(node, owner, path, &why);
    if (!f && why.empty()) __builtin_trap();
  }

  // A ring of data links closed through the input's target: the finder reports it
  // and pulling a value returns (no stack overflow).
  Foo a, b;
  std::string why;
  BaseField* target = resolve_field_link(*g->nodes[3], g->owners[3], path, &why);
  a.mass.set_parent(&b.mass);
  if (target && target->type_name() == b.mass.type_name()) {
    b.mass.set_parent(target);
    std::vector<const BaseField*> fields = {&a.mass, &b.mass, target};
    (void)find_field_cycles(fields);
    (void)a.mass.get();
    b.mass.set_parent(nullptr);
  }
  return 0;
}
