// The previewer's interactive widgets: Dear ImGui's, each noted as it is drawn
// with the label it shows, a name unique in the window, its kind and its
// rectangle in window pixels. `prism view --dump-widgets FILE` writes the
// list every frame, so that tests can aim real mouse events at real widgets;
// and two widgets that ImGui identifies alike (the Save button once shared its
// id with the Save section's header, so clicking it did nothing) are caught.
// Every widget of the panel goes through these wrappers.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

namespace prism {

struct WidgetRecord {
  std::string label; // as shown, without ImGui's "##..." part
  std::string name;  // the scopes it sits in and its label: "Lights/light 2/intensity"
  // "button", "checkbox", "slider", "drag", "colour", "input", "header", "radio", "selectable"
  std::string kind;
  std::string value; // what it shows: "true", "5", "0.1 0.2 0.3", the text; "" for buttons
  float x = 0, y = 0, w = 0, h = 0; // window pixels, origin top-left: where the mouse acts
  bool active = false;              // held by the mouse, or a text field being typed in
  bool visible = false;             // wholly inside its window's visible part (not scrolled away)
  ImGuiID id = 0;
};

// What one frame drew. Scopes (ui::Scope) name groups of widgets.
class WidgetLog {
public:
  void beginFrame();
  void pushScope(const std::string& name);
  void popScope();
  // Records ImGui's last item as widget `label` (its "##..." part removed;
  // when nothing is left, the part after "##" names it) of `kind`.
  // `frameWidth`, when positive, is the width of the part that takes the
  // mouse (a slider's or a number field's frame, without its label).
  void noteLastItem(const char* label, const char* kind, std::string value = "",
                    float frameWidth = -1.0f);

  const std::vector<WidgetRecord>& widgets() const { return widgets_; }
  // Names of widgets drawn with an id an earlier widget of the frame had.
  std::vector<std::string> duplicateIds() const;
  // A JSON array of {"label", "name", "kind", "value", "active", "visible",
  // "x", "y", "w", "h"}.
  std::string json() const;

private:
  std::vector<WidgetRecord> widgets_;
  std::vector<std::string> scopes_;
};

// The log the panel's widgets write to (the window has one panel).
WidgetLog& widgetLog();

namespace ui {

// Names the widgets drawn while it lives (and scopes their ImGui ids, so the
// same label in two scopes never collides).
class Scope {
public:
  explicit Scope(const std::string& name);
  ~Scope();
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;
};

bool button(const char* label, const ImVec2& size = ImVec2(0.0f, 0.0f));
bool checkbox(const char* label, bool* value);
bool sliderInt(const char* label, int* value, int min, int max);
bool sliderFloat(const char* label, float* value, float min, float max, const char* format,
                 ImGuiSliderFlags flags = 0);
// `count` doubles edited by dragging (or typing after a double-click).
bool dragDoubles(const char* label, double* values, int count, float speed, const char* format);
// A colour: three numbers dragged or typed, and a swatch that opens a colour
// picker; floats, not limited to 1.
bool colourEdit(const char* label, float* rgb);
bool inputText(const char* label, std::string* text);
bool collapsingHeader(const char* label);
bool selectable(const char* label, bool selected = false);
// One of a group: sets *value to `mine` when clicked.
bool radioButton(const char* label, int* value, int mine);

} // namespace ui

} // namespace prism
