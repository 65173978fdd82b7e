// Every key tap, typed character, click, drag and wheel turn reaches the
// window whole and in order, however short it is and however slow the frames
// are. ImGui 1.86's GLFW backend keeps only whether a key or button is down
// when a frame starts, and where the pointer is then: a tap of 12 ms between
// two frames (or of 100 ms during a slow frame under load) was pressed and
// released before the frame looked, and was lost, Ctrl+Q and the overlay key
// among them; a text field acts on one key a frame, so keys that arrived
// together (Ctrl+A, then Backspace) lost all but one; and a release followed
// by a press within one frame merged two clicks into a drag.
//
// The latch queues the window's input events and replays them to ImGui at the
// start of each frame, in order, up to and including the first press or
// release of a key or a button: every press and every release gets a frame of
// its own (so a key tapped twice is seen down, up, down), with the pointer
// where it happened and the modifiers held with it. Motion, characters and modifier keys never end
// a frame's share. The mouse buttons and the pointer ImGui sees are the replayed ones, not the live
// state the backend would read.
#pragma once

#include <glm/vec2.hpp>

#include <optional>

struct GLFWwindow;

namespace prism {

// Takes over `window`'s key, character, mouse-button, cursor and scroll
// callbacks after ImGui_ImplGlfw_InitForOpenGL has installed its own (which
// receive the events from the latch). One window at a time.
void installInputLatch(GLFWwindow* window);

// Before ImGui_ImplGlfw_NewFrame: replays this frame's share of the events.
void beginInputFrame();

// After ImGui_ImplGlfw_NewFrame, before ImGui::NewFrame: puts the replayed
// buttons and pointer in place of the live ones the backend read.
void applyInputFrame();

// Where mouse button `button` (0 left, 1 right, 2 middle) went down in this
// frame's share, in window coordinates.
std::optional<glm::dvec2> pressedAt(int button);

} // namespace prism
