#include "input_latch.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <array>
#include <cfloat>
#include <deque>

namespace prism {

namespace {

struct Event {
  enum class Kind { Key, Char, Button, Move, Scroll } kind;
  GLFWwindow* window;
  int code = 0; // key or mouse button
  int scancode = 0, action = 0, mods = 0;
  unsigned codepoint = 0;
  glm::dvec2 at{0.0}; // pointer position (Move), wheel offsets (Scroll)
};

constexpr int kButtons = 3; // left, right, middle

// GLFW calls back on the window's thread, which also draws the frames.
std::deque<Event> queue;
glm::dvec2 pointer(0.0);              // as replayed so far
std::array<bool, kButtons> down{};    // as replayed so far
std::array<bool, kButtons> pressed{}; // went down in this frame's share
std::array<std::optional<glm::dvec2>, kButtons> presses;

bool isModifier(int key) {
  return key == GLFW_KEY_LEFT_CONTROL || key == GLFW_KEY_RIGHT_CONTROL ||
         key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT || key == GLFW_KEY_LEFT_ALT ||
         key == GLFW_KEY_RIGHT_ALT || key == GLFW_KEY_LEFT_SUPER || key == GLFW_KEY_RIGHT_SUPER;
}

void queueKey(GLFWwindow* w, int key, int scancode, int action, int mods) {
  queue.push_back({Event::Kind::Key, w, key, scancode, action, mods, 0, {}});
}
void queueChar(GLFWwindow* w, unsigned codepoint) {
  queue.push_back({Event::Kind::Char, w, 0, 0, 0, 0, codepoint, {}});
}
void queueButton(GLFWwindow* w, int button, int action, int mods) {
  queue.push_back({Event::Kind::Button, w, button, 0, action, mods, 0, {}});
}
void queueMove(GLFWwindow* w, double x, double y) {
  queue.push_back({Event::Kind::Move, w, 0, 0, 0, 0, 0, {x, y}});
}
void queueScroll(GLFWwindow* w, double dx, double dy) {
  queue.push_back({Event::Kind::Scroll, w, 0, 0, 0, 0, 0, {dx, dy}});
}

// Hands `e` to ImGui (or to the replayed state); true when it ends the
// frame's share: a key (other than a modifier) or a button going down or up.
bool replay(const Event& e) {
  switch (e.kind) {
  case Event::Kind::Key:
    ImGui_ImplGlfw_KeyCallback(e.window, e.code, e.scancode, e.action, e.mods);
    return !isModifier(e.code);
  case Event::Kind::Char: ImGui_ImplGlfw_CharCallback(e.window, e.codepoint); return false;
  case Event::Kind::Move: pointer = e.at; return false;
  case Event::Kind::Scroll: ImGui_ImplGlfw_ScrollCallback(e.window, e.at.x, e.at.y); return false;
  case Event::Kind::Button: {
    ImGui_ImplGlfw_MouseButtonCallback(e.window, e.code, e.action, e.mods);
    if (e.code < 0 || e.code >= kButtons) return false;
    const auto b = std::size_t(e.code);
    down[b] = e.action == GLFW_PRESS;
    if (down[b]) {
      pressed[b] = true;
      presses[b] = pointer;
    }
    return true;
  }
  }
  return false;
}

} // namespace

void installInputLatch(GLFWwindow* window) {
  queue.clear();
  down = {};
  pressed = {};
  presses = {};
  glfwGetCursorPos(window, &pointer.x, &pointer.y);
  glfwSetKeyCallback(window, queueKey);
  glfwSetCharCallback(window, queueChar);
  glfwSetMouseButtonCallback(window, queueButton);
  glfwSetCursorPosCallback(window, queueMove); // ImGui 1.86's backend sets none
  glfwSetScrollCallback(window, queueScroll);
}

void beginInputFrame() {
  pressed = {};
  presses = {};
  while (!queue.empty()) {
    const Event e = queue.front();
    queue.pop_front();
    if (replay(e)) break;
  }
}

void applyInputFrame() {
  ImGuiIO& io = ImGui::GetIO();
  for (int b = 0; b < kButtons; ++b)
    io.MouseDown[b] = down[std::size_t(b)] || pressed[std::size_t(b)];
  // The backend leaves the pointer unknown (-FLT_MAX) when it is not over the
  // window; otherwise it is where the replayed events put it.
  if (io.MousePos.x != -FLT_MAX) io.MousePos = ImVec2(float(pointer.x), float(pointer.y));
}

std::optional<glm::dvec2> pressedAt(int button) {
  if (button < 0 || button >= kButtons) return std::nullopt;
  return presses[std::size_t(button)];
}

} // namespace prism
