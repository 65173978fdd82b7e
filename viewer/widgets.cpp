#include "widgets.h"

#include <imgui_internal.h> // the window's clip rectangle
#include <imgui_stdlib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <set>

namespace prism {

void WidgetLog::beginFrame() {
  widgets_.clear();
  scopes_.clear();
}

void WidgetLog::pushScope(const std::string& name) { scopes_.push_back(name); }

void WidgetLog::popScope() {
  if (!scopes_.empty()) scopes_.pop_back();
}

void WidgetLog::noteLastItem(const char* label, const char* kind, std::string value,
                             float frameWidth) {
  const std::string full = label;
  const std::size_t hidden = full.find("##");
  std::string shown = full.substr(0, hidden);
  if (shown.empty() && hidden != std::string::npos) shown = full.substr(hidden + 2);
  std::string name;
  for (const std::string& scope : scopes_)
    name += scope + "/";
  const ImVec2 min = ImGui::GetItemRectMin();
  ImVec2 max = ImGui::GetItemRectMax();
  if (frameWidth > 0.0f) max.x = std::min(max.x, min.x + frameWidth);
  // The id ImGui derives from the label in the current scope: what two widgets
  // must not share (for a multi-part widget such as a 3-number drag the last
  // item is its group, which has none).
  const ImRect clip = ImGui::GetCurrentWindow()->InnerClipRect;
  const bool visible = clip.Contains(ImRect(min, max));
  widgets_.push_back({shown, name + shown, kind, std::move(value), min.x, min.y, max.x - min.x,
                      max.y - min.y, ImGui::IsItemActive(), visible, ImGui::GetID(label)});
}

std::vector<std::string> WidgetLog::duplicateIds() const {
  std::vector<std::string> duplicates;
  std::set<ImGuiID> seen;
  for (const WidgetRecord& w : widgets_)
    if (!seen.insert(w.id).second) duplicates.push_back(w.name);
  return duplicates;
}

// A widget as --dump-widgets lists it: every member by its own name but the
// ImGui id, which means nothing outside the process.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(WidgetRecord, label, name, kind, value, active, visible, x, y, w,
                                   h)

std::string WidgetLog::json() const {
  const nlohmann::json list = widgets_;
  return list.dump(1) + "\n";
}

WidgetLog& widgetLog() {
  static WidgetLog log;
  return log;
}

namespace ui {

Scope::Scope(const std::string& name) {
  ImGui::PushID(name.c_str());
  widgetLog().pushScope(name);
}

Scope::~Scope() {
  widgetLog().popScope();
  ImGui::PopID();
}

namespace {

// Notes the widget just drawn, showing `value`, and passes on what it returned.
bool noted(bool result, const char* label, const char* kind, std::string value = "",
           float frameWidth = -1.0f) {
  widgetLog().noteLastItem(label, kind, std::move(value), frameWidth);
  return result;
}

// Numbers as the dump shows them: shortest round-trip text, space separated.
template <class T> std::string numbers(const T* values, int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    char item[32];
    std::snprintf(item, sizeof item, "%.17g", double(values[i]));
    text += (i > 0 ? " " : "") + std::string(item);
  }
  return text;
}

} // namespace

bool button(const char* label, const ImVec2& size) {
  return noted(ImGui::Button(label, size), label, "button");
}

bool checkbox(const char* label, bool* value) {
  const bool changed = ImGui::Checkbox(label, value);
  return noted(changed, label, "checkbox", *value ? "true" : "false");
}

bool sliderInt(const char* label, int* value, int min, int max) {
  const float frame = ImGui::CalcItemWidth();
  const bool changed = ImGui::SliderInt(label, value, min, max, "%d", ImGuiSliderFlags_AlwaysClamp);
  return noted(changed, label, "slider", numbers(value, 1), frame);
}

bool sliderFloat(const char* label, float* value, float min, float max, const char* format,
                 ImGuiSliderFlags flags) {
  const float frame = ImGui::CalcItemWidth();
  const bool changed = ImGui::SliderFloat(label, value, min, max, format, flags);
  return noted(changed, label, "slider", numbers(value, 1), frame);
}

bool dragDoubles(const char* label, double* values, int count, float speed, const char* format) {
  const float frame = ImGui::CalcItemWidth();
  const bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, values, count, speed,
                                          nullptr, nullptr, format);
  return noted(changed, label, "drag", numbers(values, count), frame);
}

bool colourEdit(const char* label, float* rgb) {
  const float frame = ImGui::CalcItemWidth(); // the numbers and the swatch
  const bool changed =
      ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
  return noted(changed, label, "colour", numbers(rgb, 3), frame);
}

bool inputText(const char* label, std::string* text) {
  const float frame = ImGui::CalcItemWidth();
  const bool changed = ImGui::InputText(label, text);
  return noted(changed, label, "input", *text, frame);
}

bool collapsingHeader(const char* label) {
  const bool open = ImGui::CollapsingHeader(label, ImGuiTreeNodeFlags_DefaultOpen);
  return noted(open, label, "header", open ? "open" : "closed");
}

bool radioButton(const char* label, int* value, int mine) {
  const bool clicked = ImGui::RadioButton(label, value, mine);
  return noted(clicked, label, "radio", *value == mine ? "true" : "false");
}

bool selectable(const char* label, bool selected) {
  return noted(ImGui::Selectable(label, selected), label, "selectable");
}

} // namespace ui

} // namespace prism
