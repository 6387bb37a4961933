#include "core/field.h"

#include "core/base.h"
#include "core/engine.h"

namespace sinew {

namespace {
constexpr int kMaxUpdateDepth = 1000;
}  // namespace

BaseField::BaseField(Base* owner, std::string name, std::string help, std::string group, const char* unit)
    : owner_(owner), name_(std::move(name)), help_(std::move(help)), group_(std::move(group)), unit_(unit) {
  if (owner_) owner_->register_field(this);
}

void BaseField::set_parent(BaseField* parent) {
  parent_ = parent;
  parent_version_seen_ = 0;  // force a copy at the next read
  set_ = true;
}

void BaseField::update() const {
  if (!parent_ && !producer_) return;
  // Link cycles are refused by the scene builder; this bound only keeps a
  // cycle made later (by code) from overflowing the stack. Chains of links in
  // scenes are a few fields deep.
  thread_local int depth = 0;
  if (depth > kMaxUpdateDepth) return;
  ++depth;
  struct Leave {
    ~Leave() { --depth; }
  } leave;
  if (parent_) {
    parent_->update();
    if (parent_->version_ != parent_version_seen_) {
      parent_version_seen_ = parent_->version_;
      const_cast<BaseField*>(this)->copy_from(*parent_);
      ++version_;
    }
  }
  if (producer_) producer_->update();
}

void BaseField::copy_generic(const BaseField& other) {
  const int w_other = other.row_width();
  if (w_other > 0 && row_width() > 0) {
    std::vector<double> flat;
    other.get_rows(flat);
    set_rows(flat, w_other);
    return;
  }
  if (row_width() > 0) {
    // A single fixed-size vector into a list is one element, as SOFA's element-wise copy between
    // Data of different types: a Rigid3d position linked to a Vec3 (GeomagicDriver's
    // positionBase) is one frame at that centre with the identity rotation. As text, the three
    // numbers would not make one Rigid3d coordinate.
    other.update();
    const FieldLayout l = const_cast<BaseField&>(other).layout();
    if (l.scalar == FieldLayout::Scalar::f64 && l.dims == 1 && !l.list && l.data && l.cols > 0) {
      const double* d = static_cast<const double*>(l.data);
      set_rows(std::vector<double>(d, d + l.cols), l.cols);
      return;
    }
  }
  read(other.text());
}

BaseLink::BaseLink(Base* owner, std::string name, std::string help)
    : name_(std::move(name)), help_(std::move(help)) {
  if (owner) owner->register_link(this);
}

namespace {
BaseDestroyedHook g_destroyed_hook = nullptr;
}

void set_base_destroyed_hook(BaseDestroyedHook hook) { g_destroyed_hook = hook; }

Base::~Base() {
  if (g_destroyed_hook) g_destroyed_hook(this);
}

BaseField* Base::find_field(std::string_view name) const {
  for (BaseField* f : fields_) {
    if (f->name() == name) return f;
    for (const auto& a : f->aliases())
      if (a == name) return f;
  }
  return nullptr;
}

BaseLink* Base::find_link(std::string_view name) const {
  for (BaseLink* l : links_)
    if (l->name() == name) return l;
  return nullptr;
}

}  // namespace sinew
