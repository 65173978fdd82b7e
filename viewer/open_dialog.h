// The previewer's Open dialog (Ctrl+O): recent scenes, a folder's folders and
// scene files to browse, and a path to type. Choosing a scene opens it in the
// window (ViewController::open) and puts it first among the recent ones.
#pragma once

#include "scene_files.h"
#include "view_controller.h"

#include <string>

namespace prism {

struct OpenDialog {
  bool visible = false;
  std::string folder; // being browsed
  std::string path;   // the field
};

// Shows the dialog (when visible) over a `width` x `height` window.
void drawOpenDialog(ViewController& controller, OpenDialog& dialog, RecentFiles& recent,
                    float uiScale, float width, float height);

// Opens `path` and remembers it among the recent scenes.
void openScene(ViewController& controller, RecentFiles& recent, const std::string& path);

} // namespace prism
