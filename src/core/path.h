// Link paths: `@name`, `@../x`, `@/a/b`, `@[-1]`, `@path.field` (spec/framework.md §2.3).
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace sinew {

class Base;
class BaseField;
class Component;
class Node;

// Resolves an object path (text after '@') as seen from `owner` in `node`.
// `accept` says whether a candidate has the requested type; when the path
// ends on a node and the node itself is not accepted, the unique accepted
// object of that node is taken (none or several → nullptr, reason in *why).
Base* resolve_object_path(Node& node, Component* owner, std::string_view path,
                          const std::function<bool(Base*)>& accept, std::string* why = nullptr);

// Resolves a data link "@path.field" to the field; nullptr (reason in *why) when not found.
BaseField* resolve_field_link(Node& node, Component* owner, std::string_view link, std::string* why = nullptr);

}  // namespace sinew

namespace sinew {

class Diagnostics;

// Resolves the links still pending on components whose init has not run:
// data links whose target did not exist when they were declared (a Python
// scene may link to objects it adds later), then object links (SOFA's
// updateLinks). An unresolvable data link is a warning and leaves its field
// unset, as in SOFA; an unresolvable object link is an error. Run by the
// scene builder at the end of a file and by init_root/init_added.
void resolve_pending_links(Node& root, Diagnostics& diag);

}  // namespace sinew
