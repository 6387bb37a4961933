#include "core/value_text.h"
#include "scene/xml_tree.h"

#include <tinyxml2.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sinew::scene {

const std::string* Element::find(std::string_view name) const {
  for (const auto& [key, value] : attributes) {
    if (key == name) return &value;
  }
  return nullptr;
}

std::string_view Element::name() const {
  const std::string* n = find("name");
  return n ? std::string_view(*n) : std::string_view();
}

void Element::set(std::string_view name, std::string value) {
  for (auto& [key, old] : attributes) {
    if (key == name) {
      old = std::move(value);
      return;
    }
  }
  if (name == "name") {
    // Keep the name first: it is what a reader looks for when printing the element.
    attributes.insert(attributes.begin(), {std::string(name), std::move(value)});
  } else {
    attributes.emplace_back(std::string(name), std::move(value));
  }
}

namespace {

namespace tx = tinyxml2;

// The file an XML element was read from.
struct FileCtx {
  std::string file;  // reported in messages and Element::where.file
  std::string dir;   // absolute folder: includes and macros are resolved against it
};

// Element under construction. Kept apart from Element because the base folder of an
// element is only known once includes are spliced: an element resolves against the
// folder of the nearest enclosing *file root* in the final tree (SOFA changes the
// working directory when it initialises a file root), and Group/_Merge_ roots vanish.
struct Item {
  Element el;  // el.children stays empty until finish()
  std::vector<Item> kids;
  std::string root_dir;  // set on the root element of a file: the folder of that file
};

bool is_regular_file_no_throw(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && !ec;
}

// tinyxml2's ErrorStr() is "Error=<NAME> ErrorID=<n> (0x..) Line number=<n>[: <detail>]";
// the line goes into the message location, so keep the name and the detail only.
std::string xml_error_text(const tx::XMLDocument& doc) {
  std::string text = std::string("malformed XML: ") + doc.ErrorName();
  const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
  const std::size_t line_pos = full.find("Line number=");
  const std::size_t detail = full.find(": ", line_pos == std::string::npos ? 0 : line_pos);
  if (detail != std::string::npos) text += " (" + full.substr(detail + 2) + ")";
  return text;
}

class Builder {
 public:
  Builder(const ResourcePaths& paths, const KnownTypePredicate& is_known_type, Diagnostics& diag)
      : paths_(paths), is_known_type_(is_known_type), diag_(diag) {}

  // Builds the tree of the main document. `abs_path` identifies the file for include
  // cycle detection.
  std::optional<Element> build_main(const tx::XMLDocument& doc, const FileCtx& f, const std::string& abs_path) {
    const tx::XMLElement* root = doc.RootElement();
    if (root == nullptr) {
      diag_.error({f.file, 0}, "empty document: no root element");
      return std::nullopt;
    }
    if (std::string_view(root->Name()) != "Node") {
      diag_.error({f.file, root->GetLineNum()},
                  "the root element of a scene must be <Node>, found <" + std::string(root->Name()) + ">");
      return std::nullopt;
    }
    stack_.push_back(abs_path);
    Item item = build_node(root, f);
    stack_.pop_back();
    item.root_dir = f.dir;
    return finish(std::move(item), f.dir);
  }

 private:
  static SourceLocation at(const tx::XMLElement* x, const FileCtx& f) { return {f.file, x->GetLineNum()}; }

  bool type_is_known(std::string_view type) const { return !is_known_type_ || is_known_type_(type); }

  // Copies the attributes of `x` except `type` (consumed: class name of <Object>,
  // meaningless elsewhere once the element kind is decided).
  static void copy_attributes(const tx::XMLElement* x, Element& el) {
    for (const tx::XMLAttribute* a = x->FirstAttribute(); a != nullptr; a = a->Next()) {
      if (std::string_view(a->Name()) == "type") continue;
      el.attributes.emplace_back(a->Name(), a->Value() ? a->Value() : "");
    }
  }

  // Dispatches one child element of `parent` by tag (framework.md §1.1).
  void build_child(const tx::XMLElement* x, const FileCtx& f, Item& parent) {
    const std::string_view tag = x->Name();
    if (tag == "include") {
      expand_include(x, f, parent, std::nullopt);
    } else if (tag == "Node") {
      parent.kids.push_back(build_node(x, f));
    } else if (tag == "Attribute") {
      apply_legacy_attribute(x, f, parent);
    } else if (tag == "Data") {
      diag_.warning(at(x, f), "<Data> outside of an <Attribute> element has no effect; ignored");
    } else {
      const std::optional<std::string> type = component_type(x, f);
      if (!type) return;
      if (!type_is_known(*type)) {
        // XML macro object: an unknown class backed by Objects/<Type>.xml is an include
        // of that file with the element's other attributes (framework.md §1.5).
        std::optional<std::string> macro = paths_.resolve("Objects/" + *type + ".xml", f.dir);
        if (macro && is_regular_file_no_throw(*macro)) {
          expand_include(x, f, parent, std::move(macro));
          return;
        }
      }
      parent.kids.push_back(build_component(x, f, *type));
    }
  }

  // Class name of a component element, or nullopt (after reporting) when the element
  // cannot be a component.
  std::optional<std::string> component_type(const tx::XMLElement* x, const FileCtx& f) {
    const std::string_view tag = x->Name();
    const char* type = x->Attribute("type");
    if (tag == "Object") {
      if (type == nullptr || *type == '\0') {
        diag_.error(at(x, f), "<Object> element without a 'type' attribute; ignored");
        return std::nullopt;
      }
      return std::string(type);
    }
    // SOFA treats a missing type as "default"; any other type on a non-keyword tag
    // makes element creation fail, and the element is dropped with an info message.
    if (type != nullptr && std::string_view(type) != "default") {
      diag_.info(at(x, f), "element <" + std::string(tag) + "> with type=" + quote_value(type) +
                               " cannot be created (only <Object> takes a 'type' attribute); element dropped");
      return std::nullopt;
    }
    return std::string(tag);
  }

  Item build_node(const tx::XMLElement* x, const FileCtx& f) {
    Item item;
    item.el.tag = "Node";
    item.el.is_node = true;
    item.el.where = at(x, f);
    copy_attributes(x, item.el);
    for (const tx::XMLElement* c = x->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      build_child(c, f, item);
    }
    return item;
  }

  Item build_component(const tx::XMLElement* x, const FileCtx& f, std::string type) {
    Item item;
    item.el.tag = std::move(type);
    item.el.where = at(x, f);
    copy_attributes(x, item.el);
    for (const tx::XMLElement* c = x->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      build_child(c, f, item);
    }
    // Only <Attribute> children mean something inside a component (they were folded
    // into its attributes above). SOFA refuses a Node under a component and cannot
    // create a component inside another one, so both are dropped.
    for (const Item& k : item.kids) {
      const std::string what = k.el.is_node ? "Node '" + std::string(k.el.name()) + "'"
                                            : "component <" + k.el.tag + ">";
      const std::string text = what + " cannot be a child of component <" + item.el.tag + ">; dropped";
      if (k.el.is_node) {
        diag_.info(k.el.where, text);
      } else {
        diag_.warning(k.el.where, text);
      }
    }
    item.kids.clear();
    return item;
  }

  // Legacy form <Attribute type="a"><Data value="v"/></Attribute>: sets a="v" on the
  // enclosing component.
  void apply_legacy_attribute(const tx::XMLElement* x, const FileCtx& f, Item& parent) {
    if (parent.el.is_node) {
      // SOFA parses a node's attributes before initialising its children, so the
      // value would never reach the node.
      diag_.warning(at(x, f), "<Attribute> inside a Node has no effect; ignored");
      return;
    }
    const char* name = x->Attribute("type");
    if (name == nullptr || *name == '\0') {
      diag_.warning(at(x, f), "<Attribute> without a 'type' attribute naming the attribute to set; ignored");
      return;
    }
    std::string value;
    for (const tx::XMLElement* c = x->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      if (std::string_view(c->Name()) == "Data") {
        const char* v = c->Attribute("value");
        value = v ? v : "";
      } else {
        diag_.warning(at(c, f), "<" + std::string(c->Name()) + "> inside <Attribute> has no effect; ignored");
      }
    }
    parent.el.set(name, std::move(value));
  }

  // Root element of an included file: a Node or a component (SOFA accepts both; the
  // latter simply becomes a child component). Macros are not expanded at a file root.
  std::optional<Item> build_file_root(const tx::XMLElement* x, const FileCtx& f) {
    const std::string_view tag = x->Name();
    std::optional<Item> item;
    if (tag == "Node") {
      item = build_node(x, f);
    } else if (tag == "include" || tag == "Attribute" || tag == "Data") {
      diag_.error(at(x, f), "<" + std::string(tag) + "> cannot be the root element of an included file");
      return std::nullopt;
    } else if (std::optional<std::string> type = component_type(x, f)) {
      item = build_component(x, f, std::move(*type));
    } else {
      return std::nullopt;
    }
    item->root_dir = f.dir;
    return item;
  }

  // Expands an <include> element (or a macro element, then `macro_file` is the
  // resolved Objects/<Type>.xml) into `parent` (framework.md §1.6).
  void expand_include(const tx::XMLElement* x, const FileCtx& f, Item& parent,
                      std::optional<std::string> macro_file) {
    const SourceLocation where = at(x, f);
    std::optional<std::string> file = std::move(macro_file);
    const bool is_macro = file.has_value();
    if (!is_macro) {
      const char* href = x->Attribute("href");
      if (href == nullptr || *href == '\0') {
        diag_.error(where, "<include> requires a non-empty 'href' attribute");
        return;
      }
      file = paths_.resolve(href, f.dir);
      if (!file || !is_regular_file_no_throw(*file)) {
        diag_.error(where, std::string("included file '") + href + "' not found (searched in " + f.dir +
                               " then in the data folders)");
        return;
      }
    }
    if (stack_.size() >= kMaxIncludeDepth) {
      // Cycles are caught below by path; this catches those hidden behind symbolic
      // links, which would otherwise recurse until the stack overflows.
      diag_.error(where, "includes nested more than " + std::to_string(kMaxIncludeDepth) +
                             " levels deep; include skipped");
      return;
    }
    if (std::find(stack_.begin(), stack_.end(), *file) != stack_.end()) {
      std::string chain;
      for (const std::string& s : stack_) chain += s + " -> ";
      diag_.error(where, "include cycle: " + chain + *file + "; include skipped");
      return;
    }

    tx::XMLDocument doc;
    if (doc.LoadFile(file->c_str()) != tx::XML_SUCCESS) {
      diag_.error({*file, doc.ErrorLineNum()}, xml_error_text(doc) + " (included from " + f.file + ":" +
                                                    std::to_string(where.line) + ")");
      return;
    }
    const tx::XMLElement* root = doc.RootElement();
    if (root == nullptr) {
      diag_.error(where, "included file '" + *file + "' has no root element");
      return;
    }
    stack_.push_back(*file);
    std::optional<Item> item = build_file_root(root, FileCtx{*file, parent_dir(*file)});
    stack_.pop_back();
    if (!item) return;

    // Include attributes, in document order as SOFA applies them.
    for (const tx::XMLAttribute* a = x->FirstAttribute(); a != nullptr; a = a->Next()) {
      const std::string_view key = a->Name();
      const std::string value = a->Value() ? a->Value() : "";
      if (key == "href") continue;
      if (is_macro && key == "type") continue;  // the macro's class name, not a replacement
      if (key == "name") {
        item->el.set("name", value);
      } else if (const std::size_t sep = key.find("__"); sep != std::string_view::npos) {
        const std::string only(key.substr(0, sep));
        replace_attribute(*item, key.substr(sep + 2), value, &only);
      } else {
        replace_attribute(*item, key, value, nullptr);
      }
    }

    const std::string_view root_name = item->el.name();
    if (root_name == "Group" || root_name == "_Group_") {
      for (Item& k : item->kids) parent.kids.push_back(std::move(k));
    } else if (root_name == "_Merge_") {
      merge_into(parent, std::move(*item));
    } else {
      parent.kids.push_back(std::move(*item));
    }
  }

  // Replacement attribute: overwrites `key` on every component of the subtree that
  // already has it (restricted to components named `*only` when given). Nodes are
  // left alone: SOFA applies replacements only when it creates a component.
  static void replace_attribute(Item& item, std::string_view key, const std::string& value,
                                const std::string* only) {
    if (!item.el.is_node && (only == nullptr || item.el.name() == *only)) {
      for (auto& [k, v] : item.el.attributes) {
        if (k == key) v = value;
      }
    }
    for (Item& k : item.kids) replace_attribute(k, key, value, only);
  }

  // _Merge_ include: attributes (but the name) onto `dest`; a child with the same kind,
  // tag and non-empty name as a child of `dest` is merged into it, others are appended.
  static void merge_into(Item& dest, Item&& src) {
    for (auto& [k, v] : src.el.attributes) {
      if (k != "name") dest.el.set(k, std::move(v));
    }
    for (Item& s : src.kids) {
      Item* match = nullptr;
      const std::string_view name = s.el.name();
      if (!name.empty()) {
        for (Item& d : dest.kids) {
          if (d.el.is_node == s.el.is_node && d.el.tag == s.el.tag && d.el.name() == name) {
            match = &d;
            break;
          }
        }
      }
      if (match != nullptr) {
        merge_into(*match, std::move(s));
      } else {
        dest.kids.push_back(std::move(s));
      }
    }
  }

  // Final tree: children attached, base folders decided (nearest file root wins).
  static Element finish(Item&& item, const std::string& inherited_dir) {
    Element el = std::move(item.el);
    el.base_dir = item.root_dir.empty() ? inherited_dir : item.root_dir;
    el.children.reserve(item.kids.size());
    for (Item& k : item.kids) el.children.push_back(finish(std::move(k), el.base_dir));
    return el;
  }

  static constexpr std::size_t kMaxIncludeDepth = 64;

  const ResourcePaths& paths_;
  const KnownTypePredicate& is_known_type_;
  Diagnostics& diag_;
  std::vector<std::string> stack_;  // absolute paths of the files being expanded, outermost first
};

}  // namespace

std::optional<Element> load_scene_tree(const std::string& path, const ResourcePaths& paths,
                                       const KnownTypePredicate& is_known_type, Diagnostics& diag) {
  const std::string abs = absolute_normal(path);
  if (!is_regular_file_no_throw(abs)) {
    diag.error({abs, 0}, "cannot open scene file: no such file");
    return std::nullopt;
  }
  tx::XMLDocument doc;
  if (doc.LoadFile(abs.c_str()) != tx::XML_SUCCESS) {
    diag.error({abs, doc.ErrorLineNum()}, xml_error_text(doc));
    return std::nullopt;
  }
  Builder builder(paths, is_known_type, diag);
  return builder.build_main(doc, FileCtx{abs, parent_dir(abs)}, abs);
}

std::optional<Element> parse_scene_tree(std::string_view xml, const std::string& virtual_path,
                                        const ResourcePaths& paths, const KnownTypePredicate& is_known_type,
                                        Diagnostics& diag) {
  tx::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tx::XML_SUCCESS) {
    diag.error({virtual_path, doc.ErrorLineNum()}, xml_error_text(doc));
    return std::nullopt;
  }
  Builder builder(paths, is_known_type, diag);
  return builder.build_main(doc, FileCtx{virtual_path, parent_dir(virtual_path)}, absolute_normal(virtual_path));
}

}  // namespace sinew::scene
