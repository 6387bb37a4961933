#include <sstream>

#include "core/component.h"
#include "core/node.h"
#include "core/path.h"
#include "core/value_text.h"

namespace sinew {

namespace {

bool link_field(Component& c, BaseField& f, std::string* why) {
  BaseField* parent = resolve_field_link(*c.node(), &c, f.link_path(), why);
  if (!parent) return false;
  if (parent == &f) {
    if (why) *why = "a field cannot be linked to itself";
    return false;
  }
  f.set_parent(parent);
  f.set_link_path({});
  return true;
}

void resolve_object_link(Node& n, Component& o, BaseLink& l, Diagnostics& diag) {
  if (l.is_multi()) {  // several whitespace-separated paths
    l.clear_targets();
    std::istringstream tokens(l.path());
    for (std::string p; tokens >> p;) {
      std::string why;
      Base* t = resolve_object_path(n, &o, p, [&l](Base* b) { return l.accept(b); }, &why);
      if (t) l.add_target(t);
      else
        diag.error(o.where, o.describe() + ": cannot resolve link " + l.name() + "=" + quote_value(p) + ": " +
                                (why.empty() ? "wrong type" : why));
    }
    return;
  }
  std::string why;
  Base* t = resolve_object_path(n, &o, l.path(), [&l](Base* b) { return l.accept(b); }, &why);
  if (!t || !l.accept(t))
    diag.error(o.where, o.describe() + ": cannot resolve link " + l.name() + "=" + quote_value(l.path()) + ": " +
                            (why.empty() ? "wrong type" : why));
}

}  // namespace

void resolve_pending_links(Node& root, Diagnostics& diag) {
  std::vector<Component*> fresh;
  for_each_node(root, [&](Node& n) {
    for (auto& o : n.objects())
      if (!o->initialised()) fresh.push_back(o.get());
  });
  // Data links first: an object link may be checked against a value read through one.
  for (Component* c : fresh)
    for (BaseField* f : c->fields()) {
      if (f->link_path().empty()) continue;
      std::string why;
      if (link_field(*c, *f, &why)) continue;
      diag.warning(c->where, c->describe() + ": cannot resolve link " + f->name() + "=" + quote_value(f->link_path()) +
                                 ": " + why + "; '" + f->name() + "' keeps its default, as if not given (as in SOFA)");
      f->set_link_path({});
      f->unset();
    }
  for (Component* c : fresh)
    for (BaseLink* l : c->links())
      if (l->is_set() && !l->target()) resolve_object_link(*c->node(), *c, *l, diag);
}

}  // namespace sinew
