// A drag-and-drop source for tests: drops files on the window of another
// program in an X server, speaking the XDND protocol as a file manager does
// (enter, position, drop, then handing over the selection as text/uri-list).
// xdotool can move and click but cannot carry a drop.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace prism::test {

// Drops `files` at window pixel (x, y) of the first mapped top-level window
// on `display` that accepts drops (has XdndAware). True once the target has
// taken the data and said it finished (XdndFinished), within `seconds`.
bool dropFiles(const std::string& display, const std::vector<std::filesystem::path>& files, int x,
               int y, double seconds = 20.0);

} // namespace prism::test
