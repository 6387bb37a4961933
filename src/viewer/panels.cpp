// The Dear ImGui panels of `sinew view`: menu bar (play, step, reset, reload, time, FPS),
// scene graph, properties of the selection (live-editable fields), display flags, mouse
// settings, performance. Immediate mode: everything is rebuilt every frame from the graph.
#include <cstdio>
#include <string>

#include "core/diagnostics.h"
#include "core/node.h"
#include "imgui.h"
#include "viewer/viewer_app.h"
#include "visual/visual_style.h"

namespace sinew::viewer {

namespace {

// The leaves of SOFA's display flags, with the words VisualStyle reads.
struct FlagName {
  DisplayFlags::Leaf leaf;
  const char* label;
  const char* word;  // "show" + word / "hide" + word
};
constexpr FlagName kFlags[] = {
    {DisplayFlags::visual_models, "Visual models", "VisualModels"},
    {DisplayFlags::behavior_models, "Behavior models", "BehaviorModels"},
    {DisplayFlags::force_fields, "Force fields", "ForceFields"},
    {DisplayFlags::interaction_force_fields, "Interaction force fields", "InteractionForceFields"},
    {DisplayFlags::collision_models, "Collision models", "CollisionModels"},
    {DisplayFlags::bounding_collision_models, "Bounding trees", "BoundingCollisionModels"},
    {DisplayFlags::detection_outputs, "Detection outputs", "DetectionOutputs"},
    {DisplayFlags::mappings, "Mappings", "Mappings"},
    {DisplayFlags::mechanical_mappings, "Mechanical mappings", "MechanicalMappings"},
    {DisplayFlags::advanced_rendering, "Advanced rendering", "AdvancedRendering"},
    {DisplayFlags::wireframe, "Wireframe", "Wireframe"},
    {DisplayFlags::normals, "Normals", "Normals"},
};

// The root's VisualStyle, created (first in the root) when the scene has none: the panel
// edits the root's flags, as SOFA's viewers do; VisualStyles below still override them.
VisualStyle& root_style(Node& root) {
  if (auto* s = root.find_local<VisualStyle>()) return *s;
  auto style = std::make_unique<VisualStyle>();
  style->set_type("VisualStyle", "");
  style->name.set("displayFlags");
  auto* s = static_cast<VisualStyle*>(root.add_object(std::move(style), true));
  s->init();
  return *s;
}

void display_flags_panel(Node& root) {
  if (!ImGui::Begin("Display flags")) {
    ImGui::End();
    return;
  }
  const DisplayFlags effective = display_flags_at(root);
  for (const FlagName& f : kFlags) {
    bool on = effective.shown(f.leaf);
    if (ImGui::Checkbox(f.label, &on)) {
      VisualStyle& style = root_style(root);
      // Rewrite the root's flags with this leaf changed; the other words stay as written.
      DisplayFlags flags = style.flags();
      flags.leaf[f.leaf] = on ? DisplayFlags::State::shown : DisplayFlags::State::hidden;
      std::string text;
      for (const FlagName& g : kFlags) {
        if (flags.leaf[g.leaf] == DisplayFlags::State::neutral) continue;
        if (!text.empty()) text += ' ';
        text += (flags.leaf[g.leaf] == DisplayFlags::State::shown ? "show" : "hide");
        text += g.word;
      }
      style.display_flags.set(text);
    }
  }
  ImGui::End();
}

void tree(Node& node, ViewerApp& app) {
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen;
  if (app.selected == &node) flags |= ImGuiTreeNodeFlags_Selected;
  const std::string label = (node.name.get().empty() ? std::string("(node)") : node.name.get()) + "##" +
                            std::to_string(reinterpret_cast<std::uintptr_t>(&node));
  const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
  if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) app.selected = &node;
  if (!open) return;
  for (const auto& o : node.objects()) {
    // The class, and the name when it is not the default one ("MechanicalObject1").
    std::string l = o->class_name();
    const std::string& name = o->name.get();
    if (!name.empty() && name.rfind(o->class_name(), 0) != 0) l += "  " + name;
    if (o->state() != ComponentState::valid) l += "  [invalid]";
    l += "##" + std::to_string(reinterpret_cast<std::uintptr_t>(o.get()));
    if (ImGui::Selectable(l.c_str(), app.selected == o.get())) app.selected = o.get();
  }
  for (Node* child : node.children()) tree(*child, app);
  ImGui::TreePop();
}

// A field's text in a box; Enter writes it back (read() parses and checks it), then the
// component's reinit() runs, as SOFA's Data widgets do. Long values are shown, not edited.
void field_row(BaseField& f, Component* owner, std::string& status) {
  std::string text = f.text();
  ImGui::PushID(&f);
  ImGui::TextUnformatted(f.name().c_str());
  if (ImGui::IsItemHovered() && !f.help().empty()) ImGui::SetTooltip("%s", f.help().c_str());
  ImGui::SameLine(180);
  constexpr std::size_t kEditable = 512;
  if (text.size() > kEditable) {
    ImGui::TextDisabled("%.60s... (%zu characters)", text.c_str(), text.size());
  } else {
    char buffer[kEditable + 256];
    std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##value", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)) {
      if (f.read(buffer)) {
        if (owner) owner->reinit();
        status = f.name() + " = " + buffer;
      } else {
        status = "cannot read '" + std::string(buffer) + "' as " + f.type_name() + " for " + f.name();
      }
    }
  }
  ImGui::PopID();
}

void properties_panel(ViewerApp& app) {
  ImGui::SetNextWindowPos(ImVec2(10, 420), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 300), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Properties")) {
    ImGui::End();
    return;
  }
  if (!app.selected) {
    ImGui::TextDisabled("select a node or a component in the scene graph");
  } else {
    auto* component = dynamic_cast<Component*>(app.selected);
    if (component) {
      ImGui::Text("%s %s", component->class_name().c_str(), component->template_name().c_str());
      ImGui::Separator();
    }
    std::string group;
    for (BaseField* f : app.selected->fields()) {
      if (f->group() != group) {
        group = f->group();
        ImGui::SeparatorText(group.empty() ? "Data" : group.c_str());
      }
      field_row(*f, component, app.status);
    }
  }
  ImGui::End();
}

void mouse_panel(ViewerApp& app) {
  if (!ImGui::Begin("Mouse")) {
    ImGui::End();
    return;
  }
  ImGui::TextWrapped("Shift + left-drag: attach a spring to the body under the cursor (while playing).");
  float k = static_cast<float>(app.attach_stiffness);
  if (ImGui::SliderFloat("stiffness", &k, 0.f, 10000.f, "%.0f", ImGuiSliderFlags_Logarithmic))
    app.attach_stiffness = k;
  ImGui::End();
}

void performance_panel(ViewerApp& app) {
  if (!ImGui::Begin("Performance")) {
    ImGui::End();
    return;
  }
  const Timings& t = app.timings;
  ImGui::Text("%.1f frames/s (%.2f ms/frame)", t.last_frame_ms > 0 ? 1000.0 / t.last_frame_ms : 0.0,
              t.last_frame_ms);
  ImGui::Text("step %.3f ms (mean %.3f ms over %ld steps)", t.last_step_ms, t.steps ? t.step_total_ms / t.steps : 0.0,
              t.steps);
  ImGui::PlotLines("frame ms", t.frame_ms.data(), Timings::kHistory, t.cursor, nullptr, 0.f, FLT_MAX, ImVec2(0, 50));
  ImGui::PlotLines("step ms", t.step_ms.data(), Timings::kHistory, t.cursor, nullptr, 0.f, FLT_MAX, ImVec2(0, 50));
  ImGui::Text("%zu draw batches", app.list.used);
  ImGui::End();
}

// SOFA's ImGui "Log": every message of the scene with its level, filtered by level.
void log_panel(const Diagnostics& d, bool show[3]) {
  if (!ImGui::Begin("Log")) {
    ImGui::End();
    return;
  }
  ImGui::Checkbox("info", &show[0]);
  ImGui::SameLine();
  ImGui::Checkbox("warnings", &show[1]);
  ImGui::SameLine();
  ImGui::Checkbox("errors", &show[2]);
  ImGui::Separator();
  ImGui::BeginChild("messages", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  static const ImVec4 kColour[3] = {ImVec4(0.7f, 0.7f, 0.7f, 1), ImVec4(1, 0.8f, 0.2f, 1), ImVec4(1, 0.3f, 0.3f, 1)};
  static const char* kTag[3] = {"[INFO]", "[WARNING]", "[ERROR]"};
  for (const Message& m : d.messages()) {
    const int level = static_cast<int>(m.severity);
    if (!show[level]) continue;
    ImGui::TextColored(kColour[level], "%s", kTag[level]);
    ImGui::SameLine();
    ImGui::TextUnformatted(Diagnostics::format(m).c_str());
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);  // follow new messages
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace

void ViewerApp::draw_panels() {
  Node& root = this->root();
  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::Button(animating ? "Pause" : "Play")) animating = !animating;
    ImGui::BeginDisabled(animating);
    if (ImGui::Button("Step")) step_once = true;
    ImGui::EndDisabled();
    if (ImGui::Button("Reset")) reset_scene();
    if (ImGui::Button("Reload")) reload_scene();
    if (ImGui::Button("Screenshot")) {
      char name[32];
      std::snprintf(name, sizeof name, "screenshot_%04d.png", screenshot_counter++);
      save_screenshot(name);
    }
    ImGui::Text("  Time: %.4g", root.time.get());
    ImGui::Text("  %.0f FPS", timings.last_frame_ms > 0 ? 1000.0 / timings.last_frame_ms : 0.0);
    ImGui::EndMainMenuBar();
  }
  ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(320, 380), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Scene graph")) tree(root, *this);
  ImGui::End();
  properties_panel(*this);
  // The other panels start folded, one under the other on the right.
  const float right = ImGui::GetIO().DisplaySize.x - 290;
  ImGui::SetNextWindowPos(ImVec2(right, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  display_flags_panel(root);
  ImGui::SetNextWindowPos(ImVec2(right, 60), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  mouse_panel(*this);
  ImGui::SetNextWindowPos(ImVec2(right, 90), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  performance_panel(*this);
  ImGui::SetNextWindowPos(ImVec2(right, 120), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(600, 250), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  log_panel(root.diagnostics(), log_levels);

  // The mouse spring, drawn while grabbing (SOFA draws the interaction force field then).
  if (attach.active()) {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    double ax, ay, tx, ty;
    if (project(view, attach.attached_point(), int(size.x), int(size.y), ax, ay) &&
        project(view, attach.target(), int(size.x), int(size.y), tx, ty)) {
      ImDrawList* d = ImGui::GetForegroundDrawList();
      d->AddLine(ImVec2(float(ax), float(ay)), ImVec2(float(tx), float(ty)), IM_COL32(255, 220, 40, 255), 2.f);
      d->AddCircleFilled(ImVec2(float(tx), float(ty)), 4.f, IM_COL32(255, 220, 40, 255));
    }
  }
  if (!status.empty()) {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::GetForegroundDrawList()->AddText(ImVec2(10, size.y - 22), IM_COL32(255, 255, 255, 230), status.c_str());
  }
}

}  // namespace sinew::viewer
